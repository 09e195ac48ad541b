// The glass meshes (prm/glass/glass_2d.geo, glass_3d.geo), made by Gmsh
// and read as a grid: every cell an axis-parallel box in axis order (the
// grid is Cartesian), the air's volume, and the boundary ids with the area
// of each: 1 the sides of the box, 3 the table outside the glass, 4 the
// top, 5 every face of the glass (outer and inner walls, rim, the top of
// its base), each against the geometry of the .geo file's defaults.
#include <deal.II/grid/tria.h>

#include <mpm/grid/mesh_reader.h>

#include <cstdlib>
#include <map>

#include "../tests.h"

namespace
{
  template <int dim>
  void
  check(const double h)
  {
    const std::string name = "glass_" + std::to_string(dim) + "d";
    const std::string command =
      "gmsh -" + std::to_string(dim) + " -format msh41 -setnumber h " +
      std::to_string(h) + " " SOURCE_DIR "/../../prm/glass/" + name +
      ".geo -o " + name + ".msh > gmsh_" + name + ".txt 2>&1";
    mpm_test::report(std::system(command.c_str()) == 0,
                     name + ": Gmsh makes the mesh",
                     0);
    dealii::Triangulation<dim> tria;
    mpm::read_mesh(tria, name + ".msh", "", "Grid/Mesh file");

    // the .geo's defaults
    const double W = 0.16, H = 0.16, Ri = 0.0325, tb = 0.005, Hg = 0.1;
    const double t     = dim == 2 ? 0.0025 : 0.005;
    const double outer = 2 * (Ri + t), inner = 2 * Ri;
    // in axis order: vertex v | 2^d lies beyond vertex v in direction d
    double       volume   = 0;
    unsigned int reversed = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        volume += cell->measure();
        bool ordered = true;
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          for (unsigned int d = 0; d < dim; ++d)
            if (!((v >> d) & 1))
              ordered = ordered && cell->vertex(v | (1u << d))[d] >
                                     cell->vertex(v)[d] + 0.1 * h;
        reversed += ordered ? 0 : 1;
      }
    mpm_test::report(reversed == 0,
                     name + ": every cell in axis order",
                     reversed);
    std::map<unsigned int, double> area;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f))
          area[cell->face(f)->boundary_id()] += cell->face(f)->measure();
    const double section = dim == 2 ? 1. : W; // depth of the box
    const double glass_section =
      dim == 2 ? outer * Hg - inner * (Hg - tb) :
                 outer * outer * Hg - inner * inner * (Hg - tb);
    const double box = dim == 2 ? W * H : W * W * H;
    mpm_test::check_small(name + ": air volume / (box - glass) - 1",
                          volume / (box - glass_section) - 1,
                          1e-12);
    mpm_test::report(area.size() == 4 && area.count(1) && area.count(3) &&
                       area.count(4) && area.count(5),
                     name + ": boundary ids 1, 3, 4, 5",
                     area.size());
    const double sides = dim == 2 ? 2 * H : 4 * W * H;
    const double table = dim == 2 ? W - outer : W * W - outer * outer;
    const double top   = W * section;
    // outer walls, inner walls, rim, the base's top
    const double glass = dim == 2 ?
                           2 * Hg + 2 * (Hg - tb) + 2 * t + inner :
                           4 * outer * Hg + 4 * inner * (Hg - tb) +
                             (outer * outer - inner * inner) + inner * inner;
    mpm_test::check_small(name + ": sides' area - 1",
                          area[1] / sides - 1,
                          1e-12);
    mpm_test::check_small(name + ": table's area - 1",
                          area[3] / table - 1,
                          1e-12);
    mpm_test::check_small(name + ": top's area - 1", area[4] / top - 1, 1e-12);
    mpm_test::check_small(name + ": glass's area - 1",
                          area[5] / glass - 1,
                          1e-12);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>(0.0025);
  check<3>(0.01);
}
