#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace mpm
{
  /**
   * The 2^dim corners of a quadrilateral (hexahedron) given in the order a
   * user writes them, counter-clockwise in 2D (in 3D the bottom face
   * counter-clockwise, then the top face), put into deal.II's lexicographic
   * vertex order (0 1 2 3 -> 0 1 3 2 per layer). An InputError naming
   * @p entry if their number is wrong.
   */
  template <int dim>
  std::vector<dealii::Point<dim>>
  lexicographic_corners(const std::vector<dealii::Point<dim>> &ccw,
                        const std::string                     &entry);

  /**
   * The unit box subdivided into @p subdivisions cells per direction and
   * mapped multilinearly onto the @p corners (lexicographic order). The map
   * is affine along every edge of the unit box, so its straight cells tile
   * the mapped body exactly (Cook's membrane). Boundary ids as for a
   * colorized box in the corners' own directions (2D: 0 the edge from the
   * first corner written to the fourth, 1 from the second to the third, 2
   * from the first to the second, 3 from the third to the fourth). An
   * InputError naming @p entry if a mapped cell is inverted or degenerate.
   */
  template <int dim>
  void
  create_quadrilateral_mesh(dealii::Triangulation<dim>            &tria,
                            const std::vector<unsigned int>       &subdivisions,
                            const std::vector<dealii::Point<dim>> &corners,
                            const std::string                     &entry);
} // namespace mpm
