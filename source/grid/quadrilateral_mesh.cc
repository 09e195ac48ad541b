#include <deal.II/base/geometry_info.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <mpm/grid/quadrilateral_mesh.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  using namespace dealii;

  template <int dim>
  std::vector<Point<dim>>
  lexicographic_corners(const std::vector<Point<dim>> &ccw,
                        const std::string             &entry)
  {
    if (ccw.size() != GeometryInfo<dim>::vertices_per_cell)
      throw InputError(entry + ": expected " +
                       std::to_string(GeometryInfo<dim>::vertices_per_cell) +
                       " points separated by ';', got " +
                       std::to_string(ccw.size()));
    if (dim == 1)
      return ccw;
    std::vector<Point<dim>> lex(ccw.size());
    for (unsigned int layer = 0; layer < ccw.size() / 4; ++layer)
      {
        const unsigned int o = 4 * layer;
        lex[o + 0]           = ccw[o + 0];
        lex[o + 1]           = ccw[o + 1];
        lex[o + 2]           = ccw[o + 3];
        lex[o + 3]           = ccw[o + 2];
      }
    return lex;
  }

  template <int dim>
  void
  create_quadrilateral_mesh(Triangulation<dim>              &tria,
                            const std::vector<unsigned int> &subdivisions,
                            const std::vector<Point<dim>>   &corners,
                            const std::string               &entry)
  {
    AssertDimension(corners.size(), GeometryInfo<dim>::vertices_per_cell);
    Point<dim> one;
    for (unsigned int d = 0; d < dim; ++d)
      one[d] = 1;
    GridGenerator::subdivided_hyper_rectangle(
      tria, subdivisions, Point<dim>(), one, /*colorize=*/true);
    GridTools::transform(
      [&](const Point<dim> &r) {
        Point<dim> x;
        for (unsigned int v = 0; v < corners.size(); ++v)
          {
            double weight = 1;
            for (unsigned int d = 0; d < dim; ++d)
              weight *= (v >> d) & 1 ? r[d] : 1 - r[d];
            x += weight * corners[v];
          }
        return x;
      },
      tria);
    for (const auto &cell : tria.active_cell_iterators())
      if (!(cell->measure() > 0))
        throw InputError(entry +
                         ": the mapped cells are inverted or degenerate; "
                         "give the corners counter-clockwise (2D) and the "
                         "body convex");
  }

  template std::vector<Point<1>>
  lexicographic_corners(const std::vector<Point<1>> &, const std::string &);
  template std::vector<Point<2>>
  lexicographic_corners(const std::vector<Point<2>> &, const std::string &);
  template std::vector<Point<3>>
  lexicographic_corners(const std::vector<Point<3>> &, const std::string &);
  template void
  create_quadrilateral_mesh(Triangulation<1> &,
                            const std::vector<unsigned int> &,
                            const std::vector<Point<1>> &,
                            const std::string &);
  template void
  create_quadrilateral_mesh(Triangulation<2> &,
                            const std::vector<unsigned int> &,
                            const std::vector<Point<2>> &,
                            const std::string &);
  template void
  create_quadrilateral_mesh(Triangulation<3> &,
                            const std::vector<unsigned int> &,
                            const std::vector<Point<3>> &,
                            const std::string &);
} // namespace mpm
