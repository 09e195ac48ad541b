#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>

namespace mpm
{
  /**
   * Keeps particles sorted into cells after their positions changed,
   * without deal.II's global re-sort: each particle's reference coordinates
   * are recomputed in its own cell (directly on boxes, by Newton on general
   * Q1 cells); the few particles that left their cell are found by walking
   * face neighbours, moved to an owned cell, or sent with all their
   * properties to the rank owning the ghost cell they entered. In
   * parallel, a particle that moved beyond the ghost layer is searched
   * for in the owned cells of every rank and sent to the one that has it.
   *
   * Returns false, on every rank, if some particle could not be placed this
   * way (it left the grid; serially, also one the walk did not reach); the
   * caller then runs
   * ParticleHandler::sort_particles_into_subdomains_and_cells(), which also
   * reports lost particles.
   */
  template <int dim>
  bool
  relocate_particles(const BackgroundGrid<dim>               &grid,
                     dealii::Particles::ParticleHandler<dim> &particles,
                     const MPI_Comm                           comm);
} // namespace mpm
