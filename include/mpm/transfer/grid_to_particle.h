#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>

#include <string>

namespace mpm
{
  namespace transfer
  {
    /**
     * Grid to particle: with v_i the nodal velocity at the end of the step
     * and dv_i its increment (KinematicsLayout),
     *   v_p <- a (v_p + sum_i N_ip dv_i) + (1 - a) sum_i N_ip v_i,
     *   x_p <- x_p + dt sum_i N_ip v_i,
     * with a the FLIP fraction. Particles keep their cell and reference
     * location until they are sorted again. Returns an empty string or a
     * description of the first particle with a non-finite value.
     */
    template <int dim>
    std::string
    grid_to_particle(const BackgroundGrid<dim>               &grid,
                     dealii::Particles::ParticleHandler<dim> &particles,
                     const NodalVector                       &kinematics,
                     const double                             dt,
                     const double                             flip_fraction);
  } // namespace transfer
} // namespace mpm
