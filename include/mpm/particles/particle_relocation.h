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
   * properties to the rank owning the ghost cell they entered.
   *
   * Returns false, on every rank, if some particle could not be placed this
   * way (it left the grid, or moved further than the ghost layer); the
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
