#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/active_nodes.h>
#include <mpm/grid/background_grid.h>
#include <mpm/grid/nodal_layout.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/transfer/transfer_context.h>

#include <cmath>
#include <sstream>
#include <string>

namespace mpm
{
  namespace transfer
  {
    /**
     * The end of G2P for one particle, given the grid velocity @p v_grid
     * and its increment @p dv interpolated at it: the new velocity (the
     * FLIP blend, or APIC's grid velocity) and position
     * x <- x + dt v_grid. A non-finite result is reported in @p error
     * (if still empty).
     */
    template <int dim, typename Particle>
    inline __attribute__((always_inline)) void
    move_particle(Particle     &p,
                  const double *v_grid,
                  const double *dv,
                  const double  flip,
                  const bool    apic,
                  const double  dt,
                  std::string  &error)
    {
      using L                 = ParticleLayout<dim>;
      double            *prop = p.get_properties().data();
      dealii::Point<dim> x    = p.get_location();
      bool               ok   = true;
      for (unsigned int d = 0; d < dim; ++d)
        {
          double &vp = prop[L::velocity + d];
          vp = apic ? v_grid[d] : flip * (vp + dv[d]) + (1. - flip) * v_grid[d];
          x[d] += dt * v_grid[d];
          ok = ok && std::isfinite(vp) && std::isfinite(x[d]);
        }
      if (!ok && error.empty())
        {
          std::ostringstream s;
          s << "non-finite velocity or position of particle " << p.get_id()
            << " near (" << p.get_location() << ")";
          error = s.str();
        }
      p.set_location(x);
    }

    /// What a G2P pass works on, besides the particles and the grid.
    template <int dim>
    struct G2PContext : TransferContext<dim>
    {
      /// The nodal velocities and increments (KinematicsLayout).
      const NodalVector &kinematics;
      double             dt;
      double             flip_fraction;
      /// MUSL: the vector (dim components per node) that receives the
      /// particles' new momenta; null: no re-map in this pass.
      NodalVector *remap;
      /// Non-null: zero @p remap only where it may be non-zero (the pass
      /// adds at the nodes of the last P2G pass); null: zero it whole.
      ActiveNodes *active = nullptr;
    };

    /**
     * Grid to particle: with v_i the nodal velocity at the end of the step
     * and dv_i its increment (KinematicsLayout),
     *   v_p <- a (v_p + sum_i N_ip dv_i) + (1 - a) sum_i N_ip v_i,
     *   x_p <- x_p + dt sum_i N_ip v_i,
     * with a the FLIP fraction and N_ip the family's weights. Particles
     * keep their cell and reference location until they are sorted again.
     * Returns an empty string or a description of the first particle with
     * a non-finite value (or a bad domain). Compiled per registered family,
     * chosen once per call.
     *
     * APIC (affine != 0, particle-domain families) sets
     * v_p <- sum_i S_ip v_i and C_p <- sum_i v_i (x) grad S_ip (the flip
     * fraction is not used).
     *
     * With a re-map vector (MUSL), each particle's new momentum m_p v_p
     * goes back to the nodes in the same pass, with the same weights
     * (compressed at the end): one walk through the particle data instead
     * of two, the data being what bounds these loops, and the domain
     * families' stencils are not evaluated again.
     */
    template <int dim>
    std::string
    grid_to_particle(const G2PContext<dim> &context);

    /**
     * CPDI2's domain update, with the position update at the end of the
     * step: every corner moves by dt times the grid velocity interpolated
     * at it (the particle centres move in G2P). Only the particles
     * @p only selects.
     */
    template <int dim>
    std::string
    move_domain_corners(
      const BackgroundGrid<dim>                        &grid,
      dealii::Particles::ParticleHandler<dim>          &particles,
      const NodalVector                                &kinematics,
      const double                                      dt,
      const shape_functions::DomainShapeFunctions<dim> &domains,
      const FieldSelection                             &only = {});
  } // namespace transfer
} // namespace mpm
