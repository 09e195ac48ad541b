#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/grid/nodal_layout.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/remedies/assumed_stress.h>
#include <mpm/remedies/assumed_stress_force.h>
#include <mpm/shape_functions/q1_cell.h>
#include <mpm/transfer/cell_projection.h>

#include <algorithm>
#include <vector>

namespace mpm
{
  namespace transfer
  {
    /**
     * The internal force of filtered bodies in standard MPM (2D, 3D): the
     * cell's assumed-stress field, projected from the particles of the
     * cell in the same pass (remedies::StressFilter's begin_cell(),
     * add_particle(), finish_cell()), integrated exactly over their
     * domains (remedies::AssumedStressForce) and added to the cell's
     * per-cell sum after its particles. Unfiltered bodies keep their own
     * stresses.
     */
    template <int dim>
    class IntegratedFieldForce : private CellProjection<dim>
    {
    public:
      explicit IntegratedFieldForce(const P2GContext<dim> &c)
        : CellProjection<dim>(c)
        , field_force(c.bodies.size())
        , cell_count(c.bodies.size())
        , cell_volume(c.bodies.size())
        , domain_integration(c.bodies.size())
      {}

      template <typename CellIterator, typename ParticleRange>
      inline __attribute__((always_inline)) void
      begin_cell(const CellIterator &cell, const ParticleRange &pic)
      {
        using L                         = ParticleLayout<dim>;
        const dealii::Tensor<2, dim> J0 = this->centre_jacobian(cell);
        J0_inverse                      = invert(J0);
        // Which filtered bodies fill this cell (AssumedStressForce::
        // fills): count and volume first, while the particles come into
        // cache.
        std::fill(cell_count.begin(), cell_count.end(), 0u);
        std::fill(cell_volume.begin(), cell_volume.end(), 0.);
        for (const auto &p : pic)
          {
            const double      *prop = p.get_properties().data();
            const unsigned int b    = static_cast<unsigned int>(prop[L::body]);
            ++cell_count[b];
            cell_volume[b] += prop[L::volume];
          }
        const double volume_of_cell = std::abs(determinant(J0));
        for (unsigned int b = 0; b < field_force.size(); ++b)
          domain_integration[b] =
            Force::fills(cell_count[b], cell_volume[b], volume_of_cell);
        this->filter.begin_cell(J0);
      }

      /// -V_p sigma_p, or zero for a filtered body: its particle joins
      /// the cell's projection, whose field gives the force at the end.
      template <typename Particle>
      inline __attribute__((always_inline)) dealii::Tensor<2, dim>
      weighted_stress(const Particle &p, const double *prop, const unsigned b)
      {
        using L             = ParticleLayout<dim>;
        const double V      = prop[L::volume];
        auto        &filter = this->filter;
        if (!filter.filtered(b))
          return -V * in_plane_stress<dim>(prop + L::stress);
        if (field_force[b].empty())
          force_bodies.push_back(b);
        const dealii::Point<dim> xi = p.get_reference_location();
        field_force[b].add_particle(xi,
                                    domain_integration[b] ?
                                      dealii::Tensor<2, dim>(
                                        J0_inverse * current_domain(prop)) :
                                      dealii::Tensor<2, dim>(),
                                    V);
        filter.add_particle(b, xi, prop);
        return dealii::Tensor<2, dim>();
      }

      /// Solve the projections of this cell (which writes the projected
      /// stresses back), then add the force of the projected field.
      template <typename CellIterator,
                typename ParticleRange,
                typename Sum,
                typename Weights>
      void
      finish_cell(const CellIterator  &cell,
                  const ParticleRange &pic,
                  Sum                 &sum,
                  const Weights       &weights)
      {
        using P                       = P2GLayout<dim>;
        constexpr unsigned int nv     = shape_functions::n_q1<dim>;
        auto                  &filter = this->filter;
        const auto            &geo    = this->grid.geometry(cell);
        for (const unsigned int b : force_bodies)
          {
            // the largest field's coefficients
            double     beta[remedies::AssumedStressProjection<3>::n_beta];
            double     f[nv * dim] = {};
            const auto result      = filter.finish_cell(pic, b, beta);
            if (result != remedies::StressFilter<dim>::Result::unchanged)
              field_force[b].add_internal_force(geo,
                                                filter.cartesian_field(b),
                                                f);
            else
              own_stress_force(geo, pic, b, f);
            for (unsigned int v = 0; v < nv; ++v)
              {
                double *node = sum.slot(weights, v);
                for (unsigned int d = 0; d < dim; ++d)
                  node[P::force + d] += f[v * dim + d];
              }
            field_force[b].clear();
          }
        force_bodies.clear();
      }

    private:
      using Force = remedies::AssumedStressForce<dim>;

      /// Half-vectors of the current particle domain, F r_i (columns).
      static dealii::Tensor<2, dim>
      current_domain(const double *prop)
      {
        using L = ParticleLayout<dim>;
        return load_matrix<dim>(prop + L::F) *
               load_matrix<dim>(prop + L::domain);
      }

      /// Nothing to project onto: the force of body b's own particle
      /// stresses, into @p f (f[v * dim + d]).
      template <typename ParticleRange>
      static void
      own_stress_force(const shape_functions::Q1Cell<dim> &geo,
                       const ParticleRange                &pic,
                       const unsigned int                  b,
                       double                             *f)
      {
        using L                   = ParticleLayout<dim>;
        constexpr unsigned int nv = shape_functions::n_q1<dim>;
        double                 N[nv];
        dealii::Tensor<1, dim> G[nv];
        for (const auto &p : pic)
          {
            const double *prop = p.get_properties().data();
            if (static_cast<unsigned int>(prop[L::body]) != b)
              continue;
            geo.values_and_gradients(p.get_reference_location(), N, G);
            const dealii::Tensor<2, dim> sigma =
              -prop[L::volume] * in_plane_stress<dim>(prop + L::stress);
            for (unsigned int v = 0; v < nv; ++v)
              {
                const dealii::Tensor<1, dim> fv = sigma * G[v];
                for (unsigned int d = 0; d < dim; ++d)
                  f[v * dim + d] += fv[d];
              }
          }
      }

      std::vector<Force> field_force;
      /// The filtered bodies with particles in the current cell.
      std::vector<unsigned int> force_bodies;
      std::vector<unsigned int> cell_count;
      std::vector<double>       cell_volume;
      std::vector<char>         domain_integration;
      dealii::Tensor<2, dim>    J0_inverse;
    };
  } // namespace transfer
} // namespace mpm
