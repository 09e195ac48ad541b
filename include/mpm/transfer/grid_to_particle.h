#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>
#include <sstream>
#include <string>

namespace mpm::shape_functions
{
  template <int dim>
  class DomainShapeFunctions;
}

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

    /**
     * Grid to particle: with v_i the nodal velocity at the end of the step
     * and dv_i its increment (KinematicsLayout),
     *   v_p <- a (v_p + sum_i N_ip dv_i) + (1 - a) sum_i N_ip v_i,
     *   x_p <- x_p + dt sum_i N_ip v_i,
     * with a the FLIP fraction. Particles keep their cell and reference
     * location until they are sorted again. Returns an empty string or a
     * description of the first particle with a non-finite value.
     *
     * With @p remap (MUSL), each particle's new momentum m_p v_p goes back
     * to the nodes in the same pass, with the same N_ip (dim components
     * per node, compressed at the end): one walk through the particle data
     * instead of two, the data being what bounds these loops.
     *
     * Standard MPM; the particle-domain families use
     * grid_to_particle_domains().
     */
    template <int dim>
    std::string
    grid_to_particle(const BackgroundGrid<dim>               &grid,
                     dealii::Particles::ParticleHandler<dim> &particles,
                     const NodalVector                       &kinematics,
                     const double                             dt,
                     const double                             flip_fraction,
                     NodalVector                             *remap = nullptr);

    /**
     * G2P of the particle-domain families. @p affine: APIC's slot of C_p
     * (0: no APIC); APIC sets v_p <- sum_i S_ip v_i and
     * C_p <- sum_i v_i (x) grad S_ip (the flip fraction is not used).
     * With @p remap (MUSL), each particle's new momentum goes back to the
     * nodes in the same pass (dim components per node, compressed at the
     * end): the re-map reuses the stencil instead of evaluating the domain
     * again.
     */
    template <int dim>
    std::string
    grid_to_particle_domains(
      const BackgroundGrid<dim>                        &grid,
      dealii::Particles::ParticleHandler<dim>          &particles,
      const NodalVector                                &kinematics,
      const double                                      dt,
      const double                                      flip_fraction,
      const shape_functions::DomainShapeFunctions<dim> &domains,
      NodalVector                                      *remap  = nullptr,
      const unsigned int                                affine = 0);

    /**
     * CPDI2's domain update, with the position update at the end of the
     * step: every corner moves by dt times the grid velocity interpolated
     * at it (the particle centres move in G2P).
     */
    template <int dim>
    std::string
    move_domain_corners(
      const BackgroundGrid<dim>                        &grid,
      dealii::Particles::ParticleHandler<dim>          &particles,
      const NodalVector                                &kinematics,
      const double                                      dt,
      const shape_functions::DomainShapeFunctions<dim> &domains);
  } // namespace transfer
} // namespace mpm
