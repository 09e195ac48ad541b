#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace mpm
{
  /**
   * A box with the given cells per direction, built as the coarsest
   * subdivided box that global refinement turns into it: 384 x 384 becomes
   * 3 x 3 coarse cells refined 7 times. The result is the same set of
   * cells, but p4est and deal.II store far fewer coarse cells (a coarse
   * cell costs about 800 bytes, a refined one a fraction of that), and
   * set-up is faster. Boundary ids: 0/1 x min/max, 2/3 y, 4/5 z.
   * With @p refine = false only the coarse box is built (a restart loads
   * the refinement from its checkpoint).
   */
  template <int dim>
  void
  create_box_mesh(dealii::Triangulation<dim>      &tria,
                  const std::vector<unsigned int> &cells_per_direction,
                  const dealii::Point<dim>        &lower,
                  const dealii::Point<dim>        &upper,
                  const bool                       refine = true);
} // namespace mpm
