#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>

namespace mpm
{
  /**
   * The hot loops' skeleton: visit every locally owned cell that holds
   * particles, calling f(cell, particles_in_cell). Walking particles cell
   * by cell lets each loop evaluate the cell's geometry once and gather or
   * scatter nodal values with the cell's node indices.
   */
  template <int dim, typename Function>
  inline void
  for_each_cell_with_particles(
    const BackgroundGrid<dim>               &grid,
    dealii::Particles::ParticleHandler<dim> &particles,
    const Function                          &f)
  {
    for (const auto &cell : grid.owned_cells())
      {
        const auto pic = particles.particles_in_cell(cell);
        if (pic.begin() != pic.end())
          f(cell, pic);
      }
  }
} // namespace mpm
