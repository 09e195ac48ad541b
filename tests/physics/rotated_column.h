// The laterally confined column under its own weight between slip walls
// (neo-Hookean, 1 x 10 in a grid of 1 x 11), with grid, body and gravity
// rotated by an angle: for slip_rotated_column and
// cell_pressure_preconditioner.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace rotated_column
{
  /// The grid text that reads the rotated grid of write_grid().
  inline const std::string rotated_grid = R"(
subsection Grid
  set Type = mesh file
  set Mesh file = rotated_column.ucd
end)";

  /// Rank 0 writes the grid (2 x 22 cells, boundary ids by face) rotated
  /// by @p angle to rotated_column.ucd; every rank waits for it.
  inline void
  write_grid(const double angle)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        dealii::Triangulation<2> grid;
        dealii::GridGenerator::subdivided_hyper_rectangle(
          grid, {2, 22}, dealii::Point<2>(0, 0), dealii::Point<2>(1, 11), true);
        dealii::GridTools::rotate(angle, grid);
        std::ofstream out("rotated_column.ucd");
        dealii::GridOut().write_ucd(grid, out);
      }
    MPI_Barrier(MPI_COMM_WORLD);
  }

  /// The column's parameter text on the grid @p grid, rotated by
  /// @p angle (the body's corners and the gravity with it), Poisson's
  /// ratio @p nu, and @p body_text added to the body's subsection.
  inline std::string
  parameters(const std::string &grid,
             const double       angle,
             const double       nu,
             const std::string &body_text = "")
  {
    const double c = std::cos(angle), s = std::sin(angle);
    auto         point = [&](const double x, const double y) {
      std::ostringstream p;
      p.precision(17);
      p << c * x - s * y << ", " << s * x + c * y;
      return p.str();
    };
    std::ostringstream prm;
    prm.precision(17);
    prm << grid << R"(
subsection Time stepping
  set Integrator = quasi-static
  set Time step control = fixed
  set Time step = 1
  set End time = 1
end
subsection Boundary conditions
  set Slip boundary ids = 0, 1, 2
end
subsection Output
  set Directory = results
end
subsection Bodies
  subsection Body 0
    set Geometry = quadrilateral
    set Corners = )"
        << point(0, 0) << "; " << point(1, 0) << "; " << point(1, 10) << "; "
        << point(0, 10) << R"(
    set Subdivisions = 2, 20
    set Body force = )"
        << 10 * s << "; " << -10 * c << R"(
    subsection Material
      set Model = neo-Hookean
      set Density = 80
      subsection Neo-Hookean
        set Young's modulus = 1e6
        set Poisson's ratio = )"
        << nu << R"(
      end
    end
)" << body_text
        << R"(  end
end
)";
    return prm.str();
  }
} // namespace rotated_column
