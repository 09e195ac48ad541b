#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>

namespace mpm
{
  /**
   * The hot loops' skeleton: visit every locally owned cell that holds
   * particles, calling f(cell, particles) with the cell's particles as a
   * range of ParticleRef (particles/particle_index.h). Walking particles
   * cell by cell lets each loop evaluate the cell's geometry once and
   * gather or scatter nodal values with the cell's node indices; reading
   * them through the grid's particle index spares each loop the walk
   * through deal.II's particle containers. @p f may change what particles
   * carry, not which cell holds them.
   */
  template <int dim, typename Function>
  inline void
  for_each_cell_with_particles(
    const BackgroundGrid<dim>               &grid,
    dealii::Particles::ParticleHandler<dim> &particles,
    const Function                          &f)
  {
    auto &index = grid.particle_index();
    if (!index.up_to_date(particles))
      {
        // the cells that held particles are tried first: walking the
        // whole grid would make a step cost what the grid costs
        const auto cells = index.cells();
        if (!index.build(particles, cells))
          index.build(particles, grid.owned_cells());
      }
    const auto &cells = index.cells();
    for (std::size_t c = 0; c < cells.size(); ++c)
      f(cells[c], index.particles_of(c));
  }
} // namespace mpm
