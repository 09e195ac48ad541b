#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/active_nodes.h>
#include <mpm/grid/background_grid.h>
#include <mpm/grid/nodal_layout.h>
#include <mpm/particles/body.h>
#include <mpm/transfer/transfer_context.h>

#include <vector>

namespace mpm::remedies
{
  template <int dim>
  class StressFilter;
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

    /// The P2G vector's layout (grid/nodal_layout.h).
    template <int dim>
    using P2GLayout = mpm::P2GLayout<dim>;

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

    /// What a P2G pass works on, besides the particles and the grid.
    template <int dim>
    struct P2GContext : TransferContext<dim>
    {
      const std::vector<Body<dim>> &bodies;
      /// Projects the filtered bodies' stresses (none if !filter.any()).
      remedies::StressFilter<dim> &filter;
      double                       time;
      P2GContent                   content;
      /// The ghosted P2G vector (P2GLayout), compressed at the end.
      NodalVector &nodal;
      /// Non-null: zero @p nodal only where it may be non-zero, and mark
      /// the nodes added to; null: zero it whole.
      ActiveNodes *active = nullptr;
    };

    /**
     * Particle to grid: m_i = sum_p N_ip m_p, (mv)_i = sum_p N_ip m_p v_p,
     * f_i = sum_p [ -V_p sigma_p grad N_ip + N_ip (m_p b_p + A_p t_p) ].
     * Walks the particles cell by cell, adds into the ghosted vector
     * context.nodal and compresses it. (MUSL's re-map of the new momenta
     * is part of G2P.) The weights are the family's (standard: Q1 at the
     * particle; GIMP, CPDI, CPDI2: domain averages, which reach the nodes
     * of every cell a particle's domain overlaps); the pass is compiled
     * for each registered family and chosen once per call.
     *
     * Filtered bodies get their stresses projected per cell here
     * (remedies::StressFilter). In standard MPM the internal force of the
     * projected field is integrated exactly over the particle domains
     * (IntegratedFieldForce); the particle-domain families use the
     * projected stress at each particle (ProjectedStressForce).
     *
     * With APIC the momentum sent to node i is S_ip m_p (v_p + C_p (x_i -
     * x_c)), x_c the domain's centroid (particle-domain families only).
     * Returns an empty string, or what went wrong with the first bad
     * particle domain.
     */
    template <int dim>
    std::string
    particle_to_grid(const P2GContext<dim> &context);

    /// The same for callers that hold the pieces (tests): @p filter null
    /// filters nothing, @p domains null is standard MPM.
    template <int dim>
    std::string
    particle_to_grid(
      const BackgroundGrid<dim>                        &grid,
      dealii::Particles::ParticleHandler<dim>          &particles,
      const std::vector<Body<dim>>                     &bodies,
      const double                                      time,
      const P2GContent                                  content,
      NodalVector                                      &nodal,
      remedies::StressFilter<dim>                      *filter  = nullptr,
      const shape_functions::DomainShapeFunctions<dim> *domains = nullptr,
      const unsigned int                                affine  = 0);
  } // namespace transfer
} // namespace mpm
