#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <mpm/fe_reference/reference_mesh.h>
#include <mpm/grid/mesh_reader.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    namespace
    {
      /// The multilinear map of the unit box onto the corners (given in
      /// deal.II's lexicographic vertex order).
      template <int dim>
      Point<dim>
      multilinear(const std::vector<Point<dim>> &corners, const Point<dim> &r)
      {
        Point<dim> x;
        for (unsigned int v = 0; v < corners.size(); ++v)
          {
            double weight = 1;
            for (unsigned int d = 0; d < dim; ++d)
              weight *= (v >> d) & 1 ? r[d] : 1 - r[d];
            x += weight * corners[v];
          }
        return x;
      }
    } // namespace

    template <int dim>
    void
    create_coarse_mesh(Triangulation<dim>  &tria,
                       const Geometry<dim> &geometry,
                       const std::string   &input_folder)
    {
      tria.clear();
      switch (geometry.type)
        {
          case Geometry<dim>::Type::box:
            GridGenerator::subdivided_hyper_rectangle(tria,
                                                      geometry.subdivisions,
                                                      geometry.lower,
                                                      geometry.upper,
                                                      /*colorize=*/true);
            break;
            case Geometry<dim>::Type::quadrilateral: {
              Point<dim> one;
              for (unsigned int d = 0; d < dim; ++d)
                one[d] = 1;
              GridGenerator::subdivided_hyper_rectangle(
                tria, geometry.subdivisions, Point<dim>(), one, true);
              // the map is affine along every edge of the unit box, so the
              // straight cells it gives tile the mapped body exactly
              GridTools::transform(
                [&](const Point<dim> &r) {
                  return multilinear(geometry.corners, r);
                },
                tria);
              for (const auto &cell : tria.active_cell_iterators())
                if (!(cell->measure() > 0))
                  throw InputError(
                    "Geometry/Corners: the mapped cells are inverted or "
                    "degenerate; give the corners counter-clockwise (2D) "
                    "and the body convex");
              break;
            }
          case Geometry<dim>::Type::mesh_file:
            read_mesh(tria,
                      geometry.mesh_file,
                      input_folder,
                      "Geometry/Mesh file");
            break;
        }
    }

    template void
    create_coarse_mesh(Triangulation<2> &,
                       const Geometry<2> &,
                       const std::string &);
    template void
    create_coarse_mesh(Triangulation<3> &,
                       const Geometry<3> &,
                       const std::string &);
  } // namespace fe_reference
} // namespace mpm
