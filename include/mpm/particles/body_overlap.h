#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/particles/body.h>

#include <string>
#include <vector>

namespace mpm
{
  /**
   * Refuse bodies that overlap: particles of two bodies in one place
   * carry twice the mass there, which no material means. Each particle
   * is tested against the meshes of the other bodies whose bounding box
   * holds it; bodies that only touch pass (a particle lies inside its own
   * body cell, half a particle spacing from the boundary). Throws an
   * InputError naming the first overlapping pair and the volume of the
   * particles of one body that lie inside the other. Collective.
   */
  template <int dim>
  void
  check_bodies_do_not_overlap(
    const std::vector<Body<dim>>                  &bodies,
    const dealii::Particles::ParticleHandler<dim> &particles,
    const std::string                             &input_folder,
    const MPI_Comm                                 comm);
} // namespace mpm
