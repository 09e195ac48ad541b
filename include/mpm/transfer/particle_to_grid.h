#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>
#include <mpm/particles/body.h>

#include <vector>

namespace mpm::remedies
{
  template <int dim>
  class StressFilter;
}
namespace mpm::shape_functions
{
  template <int dim>
  class DomainShapeFunctions;
}

namespace mpm
{
  namespace transfer
  {
    /// What a particle-to-grid pass accumulates.
    enum class P2GContent
    {
      mass_momentum_force, ///< USL and MUSL: everything in one pass
      mass_momentum,       ///< USF, first pass
      force                ///< USF, second pass (after the stress update)
    };

    /// Components per node of the P2G vector: mass, momentum (dim),
    /// force (dim). Offsets of each part.
    template <int dim>
    struct P2GLayout
    {
      static constexpr unsigned int mass         = 0;
      static constexpr unsigned int momentum     = 1;
      static constexpr unsigned int force        = 1 + dim;
      static constexpr unsigned int n_components = 1 + 2 * dim;
    };

    /// What a pass of the given content adds, and where in the node's
    /// values (P2GLayout).
    template <int dim>
    struct P2GPass
    {
      explicit P2GPass(const P2GContent content)
        : mass(content != P2GContent::force)
        , momentum(content != P2GContent::force)
        , force(content != P2GContent::mass_momentum)
      {}
      const bool                    mass, momentum, force;
      static constexpr unsigned int n_components = P2GLayout<dim>::n_components;
      static constexpr unsigned int momentum_offset = P2GLayout<dim>::momentum;
      static constexpr unsigned int force_offset    = P2GLayout<dim>::force;
    };

    /**
     * Particle to grid: m_i = sum_p N_ip m_p, (mv)_i = sum_p N_ip m_p v_p,
     * f_i = sum_p [ -V_p sigma_p grad N_ip + N_ip (m_p b_p + A_p t_p) ].
     * Walks the particles cell by cell with Q1 values computed directly,
     * adds into the ghosted vector @p nodal (packed with P2GLayout) and
     * compresses it. (MUSL's re-map of the new momenta is part of G2P.)
     *
     * With @p filter, the bodies it filters get their stresses projected
     * per cell here (remedies::StressFilter, written back to the
     * particles), and the internal force of the projected field is
     * integrated exactly over the particle domains
     * (remedies::AssumedStressForce) instead of summing the particles'
     * stresses.
     *
     * With @p domains (GIMP, CPDI, CPDI2) the weights are the family's
     * domain averages and reach the nodes of every cell a particle's
     * domain overlaps (particle_to_grid_domains()). Returns an empty
     * string, or what went wrong with the first bad particle domain.
     *
     * @p affine: APIC's slot of C_p in the particle properties (0: no
     * APIC; APIC needs @p domains); the momentum sent to node i is then
     * S_ip m_p (v_p + C_p (x_i - x_c)), x_c the domain's centroid.
     */
    template <int dim>
    std::string
    particle_to_grid(
      const BackgroundGrid<dim>                        &grid,
      dealii::Particles::ParticleHandler<dim>          &particles,
      const std::vector<Body<dim>>                     &bodies,
      const double                                      time,
      const P2GContent                                  content,
      NodalVector                                      &nodal,
      remedies::StressFilter<dim>                       *filter  = nullptr,
      const shape_functions::DomainShapeFunctions<dim> *domains = nullptr,
      const unsigned int                                affine  = 0);

    /**
     * The P2G of the particle-domain families: per particle, the stencil
     * of its domain (DomainShapeFunctions) scattered straight into
     * @p nodal. Filtered bodies are projected per cell first (the
     * particles of a cell's projection are those whose centre it holds);
     * their force is then the projected particle stress times the
     * family's gradients.
     */
    template <int dim>
    std::string
    particle_to_grid_domains(
      const BackgroundGrid<dim>                        &grid,
      dealii::Particles::ParticleHandler<dim>          &particles,
      const std::vector<Body<dim>>                     &bodies,
      const double                                      time,
      const P2GContent                                  content,
      NodalVector                                      &nodal,
      remedies::StressFilter<dim>                       *filter,
      const shape_functions::DomainShapeFunctions<dim> &domains,
      const unsigned int                                affine);
  } // namespace transfer
} // namespace mpm
