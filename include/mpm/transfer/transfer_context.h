#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>
#include <mpm/particles/field_selection.h>

namespace mpm::shape_functions
{
  template <int dim>
  class DomainShapeFunctions;
}

namespace mpm
{
  namespace transfer
  {
    /// What every transfer between particles and grid works on: the
    /// particles on the grid, and the shape functions that connect them.
    template <int dim>
    struct TransferContext
    {
      const BackgroundGrid<dim>               &grid;
      dealii::Particles::ParticleHandler<dim> &particles;
      /// The particle-domain family's weights; null for standard MPM
      /// (as Simulator::domain_shape_functions()).
      const shape_functions::DomainShapeFunctions<dim> *domains;
      /// APIC's slot of C_p in the particle properties (0: no APIC).
      unsigned int affine;
      /// The particles of the pass (contact: one velocity field's).
      FieldSelection only = {};
    };
  } // namespace transfer
} // namespace mpm
