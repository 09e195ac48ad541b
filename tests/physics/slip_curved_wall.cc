// Slip on a curved wall: the boundary of a (faceted) circle is one smooth
// wall, so its nodes must keep the tangential velocity and lose only the
// radial one; a wall treated as two walls per node (the faces meet at a
// small angle) would fix the nodes instead. Grid: deal.II's hyper_ball,
// refined twice, written as UCD and read as a mesh-file grid.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>

#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      dealii::Triangulation<2> ball;
      dealii::GridGenerator::hyper_ball(ball, dealii::Point<2>(), 1.);
      ball.refine_global(2);
      std::ofstream out("circle.ucd");
      dealii::GridOut().write_ucd(ball, out);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  mpm_test::Case<2> c(R"(
subsection Grid
  set Type = mesh file
  set Mesh file = circle.ucd
end
subsection Boundary conditions
  set Slip boundary ids = 0
end
subsection Bodies
  subsection Body 0
    set Lower corner = -0.2, -0.2
    set Upper corner = 0.2, 0.2
    subsection Material
      set Model = linear elastic
    end
  end
end)");
  const auto       &grid          = c.simulator->grid();
  double            worst_tangent = 0, worst_normal = 0;
  unsigned int      n_wall = 0;
  for (unsigned int i = 0; i < grid.n_owned_nodes(); ++i)
    {
      const auto x = grid.node_position(i);
      if (std::abs(x.norm() - 1.) > 1e-4) // UCD keeps few digits
        continue;
      ++n_wall;
      double t[2] = {-x[1], x[0]}, n[2] = {x[0], x[1]};
      grid.constrain(i, t);
      grid.constrain(i, n);
      worst_tangent =
        std::max(worst_tangent, std::hypot(t[0] + x[1], t[1] - x[0]));
      worst_normal = std::max(worst_normal, std::hypot(n[0], n[1]));
    }
  n_wall        = dealii::Utilities::MPI::sum(n_wall, MPI_COMM_WORLD);
  worst_tangent = dealii::Utilities::MPI::max(worst_tangent, MPI_COMM_WORLD);
  worst_normal  = dealii::Utilities::MPI::max(worst_normal, MPI_COMM_WORLD);
  mpm_test::log() << "wall nodes: " << n_wall << std::endl;
  // The node normal is the mean of two face normals; on this mesh it
  // differs from the radius by a few degrees at most (faces of unequal
  // length), so a few percent of the velocity.
  mpm_test::check_small("tangential velocity changed by slip",
                        worst_tangent,
                        0.05);
  mpm_test::check_small("radial velocity kept by slip", worst_normal, 0.05);
}
