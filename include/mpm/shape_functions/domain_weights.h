#pragma once

#include <deal.II/base/tensor.h>

#include <mpm/grid/background_grid.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/shape_functions/family_traits.h>
#include <mpm/shape_functions/stencil.h>

#include <string>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * The weights of a particle-domain family (uGIMP, cpGIMP, CPDI,
     * CPDI2): the stencil of the particle's domain (DomainShapeFunctions,
     * which may reuse the step's cached stencil). Entries name nodes of
     * every cell the domain overlaps.
     */
    template <int dim>
    class DomainWeights
    {
    public:
      static constexpr unsigned int n_entries = Stencil<dim>::capacity;
      /// Stencils differ per particle: every entry goes straight to its
      /// node.
      static constexpr NodalSummation summation = NodalSummation::per_entry;
      /// The projected field's value at the particle stands for its
      /// stress.
      static constexpr FilteredForce filtered_force =
        FilteredForce::projected_stress;

      DomainWeights(const BackgroundGrid<dim> &,
                    const DomainShapeFunctions<dim> *domains)
        : domains(*domains)
      {}

      void
      begin_pass(const std::size_t n_particles) const
      {
        domains.begin_pass(n_particles);
      }
      void
      end_pass(const bool ok) const
      {
        domains.end_pass(ok);
      }

      template <typename CellIterator>
      void
      begin_cell(const CellIterator &cell)
      {
        cell_index = cell->active_cell_index();
        ordinal    = 0;
      }

      /// The stencil of the next particle of the cell (gradients always);
      /// false, with @p error set if still empty, if its domain is bad.
      template <typename Particle>
      bool
      evaluate(const Particle &p, const bool, std::string &error)
      {
        return domains.evaluate(cell_index, ordinal++, p, entries, error);
      }

      unsigned int
      size() const
      {
        return entries.n;
      }
      unsigned int
      node(const unsigned int k) const
      {
        return entries.node[k];
      }
      double
      value(const unsigned int k) const
      {
        return entries.value[k];
      }
      const dealii::Tensor<1, dim> &
      gradient(const unsigned int k) const
      {
        return entries.gradient[k];
      }
      const Stencil<dim> &
      stencil() const
      {
        return entries;
      }

      /// The weights of the point @p d_face away from the particle (its
      /// loaded face): sum_k (S_k + grad S_k . d) x_k = x_p + d.
      void
      face_values(const dealii::Tensor<1, dim> &d_face, double *S_face) const
      {
        for (unsigned int k = 0; k < entries.n; ++k)
          S_face[k] = entries.value[k] + entries.gradient[k] * d_face;
      }

    private:
      const DomainShapeFunctions<dim> &domains;
      unsigned int                     cell_index = 0;
      unsigned int                     ordinal    = 0;
      Stencil<dim>                     entries;
    };
  } // namespace shape_functions
} // namespace mpm
