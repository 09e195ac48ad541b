#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/filters/cell_stress_field.h>
#include <mpm/grid/background_grid.h>
#include <mpm/particles/body.h>

#include <vector>

namespace mpm
{
  namespace filters
  {
    /**
     * The filter phase of the step: for every owned cell and every body
     * with `Stress filter = assumed stress`, the in-plane stresses of that
     * body's particles in the cell (the particles the cell holds) are
     * replaced by their projection onto the assumed-stress field of the
     * cell (AssumedStressProjection). The out-of-plane stress of 2D models
     * is left as the material computed it. The coefficients of each
     * cell's field go to @p field, for the internal force of the next
     * P2G. Returns the number of cells that fell back to constant stress
     * on this rank.
     */
    template <int dim>
    unsigned int
    apply_stress_filter(const BackgroundGrid<dim>               &grid,
                        dealii::Particles::ParticleHandler<dim> &particles,
                        const std::vector<Body<dim>>            &bodies,
                        CellStressField<dim>                    &field);
  } // namespace filters
} // namespace mpm
