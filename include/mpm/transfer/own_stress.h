#pragma once

#include <deal.II/base/tensor.h>

#include <mpm/particles/particle_layout.h>

namespace mpm
{
  namespace transfer
  {
    /**
     * The stress of a P2G pass without the assumed-stress filter: each
     * particle's own (midpoint rule). The interface of the filtered
     * versions (IntegratedFieldForce, ProjectedStressForce), with nothing
     * to do per cell.
     */
    template <int dim>
    struct OwnStress
    {
      template <typename CellIterator, typename ParticleRange>
      void
      begin_cell(const CellIterator &, const ParticleRange &)
      {}

      /// -V_p sigma_p: what multiplies grad S_ip in the internal force.
      template <typename Particle>
      dealii::Tensor<2, dim>
      weighted_stress(const Particle &, const double *prop, const unsigned int)
      {
        using L                  = ParticleLayout<dim>;
        dealii::Tensor<2, dim> s = in_plane_stress<dim>(prop + L::stress);
        s *= -prop[L::volume];
        return s;
      }

      template <typename CellIterator,
                typename ParticleRange,
                typename Sum,
                typename Weights>
      void
      finish_cell(const CellIterator &,
                  const ParticleRange &,
                  Sum &,
                  const Weights &)
      {}
    };
  } // namespace transfer
} // namespace mpm
