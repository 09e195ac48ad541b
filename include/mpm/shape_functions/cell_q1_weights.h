#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/grid/background_grid.h>
#include <mpm/shape_functions/family_traits.h>
#include <mpm/shape_functions/q1_cell.h>

#include <algorithm>
#include <string>

namespace mpm
{
  namespace shape_functions
  {
    template <int dim>
    class DomainShapeFunctions;

    /**
     * Standard MPM's weights of a particle: the 2^dim Q1 values and
     * gradients of its cell at its reference location, computed directly
     * (no FEValues). Entry k of the stencil is the cell's vertex k, so a
     * per-cell buffer over the vertices collects a cell's particles.
     */
    template <int dim>
    class CellQ1Weights
    {
    public:
      static constexpr unsigned int n_entries = n_q1<dim>;
      /// A cell's particles reach the same nodes: sum per cell.
      static constexpr NodalSummation summation = NodalSummation::per_cell;
      /// The projected field is integrated against these Q1 functions over
      /// the particle domains (remedies::AssumedStressForce).
      static constexpr FilteredForce filtered_force =
        FilteredForce::integrated_field;

      CellQ1Weights(const BackgroundGrid<dim> &grid,
                    const DomainShapeFunctions<dim> *)
        : grid(grid)
      {}

      /// Nothing is kept between passes.
      void
      begin_pass(const std::size_t) const
      {}
      void
      end_pass(const bool) const
      {}

      template <typename CellIterator>
      void
      begin_cell(const CellIterator &cell)
      {
        geo   = &grid.geometry(cell);
        nodes = grid.nodes(cell);
      }

      /// Values at the particle, and gradients if @p with_gradients.
      template <typename Particle>
      bool
      evaluate(const Particle &p, const bool with_gradients, std::string &)
      {
        xi = p.get_reference_location();
        if (with_gradients)
          geo->values_and_gradients(xi, value_at, gradient_at);
        else
          geo->values(xi, value_at);
        return true;
      }

      static constexpr unsigned int
      size()
      {
        return n_entries;
      }
      unsigned int
      node(const unsigned int k) const
      {
        return nodes[k];
      }
      double
      value(const unsigned int k) const
      {
        return value_at[k];
      }
      const dealii::Tensor<1, dim> &
      gradient(const unsigned int k) const
      {
        return gradient_at[k];
      }

      /**
       * The weights of the point @p d_face away from the particle (its
       * loaded face). A face that has left the particle's cell acts at
       * the nearest point of the cell, the last one whose nodes the body
       * reaches.
       */
      void
      face_values(const dealii::Tensor<1, dim> &d_face, double *S_face) const
      {
        dealii::Point<dim> xi_face =
          xi + dealii::Point<dim>(invert(geo->jacobian(xi)) * d_face);
        for (unsigned int d = 0; d < dim; ++d)
          xi_face[d] = std::clamp(xi_face[d], 0., 1.);
        geo->values(xi_face, S_face);
      }

    private:
      const BackgroundGrid<dim> &grid;
      const Q1Cell<dim>         *geo   = nullptr;
      const unsigned int        *nodes = nullptr;
      dealii::Point<dim>         xi;
      double                     value_at[n_entries];
      dealii::Tensor<1, dim>     gradient_at[n_entries];
    };
  } // namespace shape_functions
} // namespace mpm
