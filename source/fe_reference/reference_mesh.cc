#include <deal.II/grid/grid_generator.h>

#include <mpm/fe_reference/reference_mesh.h>
#include <mpm/grid/mesh_reader.h>
#include <mpm/grid/quadrilateral_mesh.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;


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
          case Geometry<dim>::Type::quadrilateral:
            create_quadrilateral_mesh(tria,
                                      geometry.subdivisions,
                                      geometry.corners,
                                      "Geometry/Corners");
            break;
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
