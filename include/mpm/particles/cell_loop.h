#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>

namespace mpm
{
  /**
   * The hot loops' skeleton: visit every locally owned cell that holds
   * particles, calling f(cell, particles_in_cell). Walking particles cell
   * by cell lets each loop evaluate the cell's geometry once and gather or
   * scatter nodal values with the cell's node indices. @p f may change
   * what particles carry, not which cell holds them.
   */
  template <int dim, typename Function>
  inline void
  for_each_cell_with_particles(
    const BackgroundGrid<dim>               &grid,
    dealii::Particles::ParticleHandler<dim> &particles,
    const Function                          &f)
  {
    // The cells that held particles in the previous loop, as long as
    // they still hold every particle: particles change cell now and then,
    // and a grid may be much larger than its bodies, whose empty cells
    // then cost nothing. The list stays in active cell index order, so
    // sums over cells keep their order (bit-identical runs and restarts).
    // It is checked once after the particles changed cells (the loops of
    // one step between two relocations share the check: counting the
    // particles of each cell costs deal.II a cell lookup).
    auto &cells = grid.cells_with_particles();
    if (!grid.check_cells_with_particles(particles))
      {
        dealii::types::particle_index held = 0;
        for (const auto &cell : cells)
          held += particles.n_particles_in_cell(cell);
        if (held != particles.n_locally_owned_particles())
          {
            cells.clear();
            for (const auto &cell : grid.owned_cells())
              if (particles.n_particles_in_cell(cell) > 0)
                cells.push_back(cell);
          }
      }
    for (const auto &cell : cells)
      {
        const auto pic = particles.particles_in_cell(cell);
        if (pic.begin() != pic.end())
          f(cell, pic);
      }
  }
} // namespace mpm
