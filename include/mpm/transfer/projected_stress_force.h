#pragma once

#include <deal.II/base/tensor.h>

#include <mpm/particles/particle_layout.h>
#include <mpm/transfer/cell_projection.h>
#include <mpm/transfer/own_stress.h>

#include <algorithm>
#include <vector>

namespace mpm
{
  namespace transfer
  {
    /**
     * The internal force of filtered bodies with a particle-domain family
     * (2D, 3D): each cell's filtered bodies are projected first (the
     * particles of a cell's projection are those whose centre it holds,
     * remedies::StressFilter::filter_cell()); the force then takes the
     * projected stress of every particle times the family's gradients.
     * With Filtered stress = written back the projection has replaced the
     * particles' stresses; with force only its field is evaluated at each
     * particle and the particles keep theirs. Nothing is added at the end
     * of the cell (OwnStress::finish_cell()).
     */
    template <int dim>
    class ProjectedStressForce : public OwnStress<dim>,
                                 private CellProjection<dim>
    {
    public:
      explicit ProjectedStressForce(const P2GContext<dim> &c)
        : CellProjection<dim>(c)
        , only(c.only)
        , present(c.bodies.size())
        , by_field(c.bodies.size(), 0)
      {}

      template <typename CellIterator, typename ParticleRange>
      void
      begin_cell(const CellIterator &cell, const ParticleRange &pic)
      {
        using L      = ParticleLayout<dim>;
        using Result = typename remedies::StressFilter<dim>::Result;
        auto &filter = this->filter;
        std::fill(present.begin(), present.end(), 0);
        for (const auto &p : pic)
          {
            const double *prop = p.get_properties().data();
            if (!only.template skips<dim>(prop))
              present[static_cast<unsigned int>(prop[L::body])] = 1;
          }
        const dealii::Tensor<2, dim> J0 = this->centre_jacobian(cell);
        double                       beta[remedies::StressFilter<dim>::n_beta];
        for (unsigned int b = 0; b < present.size(); ++b)
          by_field[b] =
            present[b] && filter.filtered(b) &&
            filter.filter_cell(J0, pic, b, beta) != Result::unchanged &&
            !filter.writes_back(b);
      }

      /// -V_p sigma_p with the stress the projection gives the particle.
      template <typename Particle>
      dealii::Tensor<2, dim>
      weighted_stress(const Particle &p, const double *prop, const unsigned b)
      {
        if (!by_field[b])
          return OwnStress<dim>::weighted_stress(p, prop, b);
        dealii::Tensor<2, dim> s =
          this->filter.cartesian_field(b).value(p.get_reference_location());
        s *= -prop[ParticleLayout<dim>::volume];
        return s;
      }

    private:
      /// the pass's particles (the other fields' bodies are not projected)
      const FieldSelection only;
      std::vector<char>    present;
      /// Per body, whether this cell's projected field gives its stresses.
      std::vector<char> by_field;
    };
  } // namespace transfer
} // namespace mpm
