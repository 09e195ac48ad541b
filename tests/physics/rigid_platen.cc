// A rigid body of prescribed motion in the quasi-static step: a smooth
// rigid platen (Material/Model = rigid, Prescribed velocity, Prescribed
// directions = y) presses a linear elastic block (plane strain, E = 1e6,
// nu = 0, 1 m x 1 m, on a grid of h = 0.25) between slip walls down by
// 0.5 m, then by 0.25 m: uniaxial strain. The platen's reaction
// (statistics column reaction_y) is the block's stress times its width,
// -E times the steps' strains summed (the hypoelastic update: h =
// -0.5/1, then -0.25/0.5 of the compressed block). The block's top stays
// on a node row, the platen moves into the cell rows the block left, and
// each cell holds whole rows of particles, so the particles integrate the
// uniform stress exactly: the reaction agrees to 1e-9 relative. (A top
// inside a cell is reached through the nodes above it, and rows that
// split unevenly between cells weigh the cells' volume wrongly: standard
// MPM's quadrature error, 3.6% after a compression to 0.75 and 0.5.)
#include <algorithm>

#include "../tests.h"
#include "platen_block.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpm_test::Case<2> c(platen_block::parameters("0", "t < 0.25 ? -2 : -1"), 2);
  auto             &sim = *c.simulator;
  const double      E = 1e6, nu = 0;
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)); // lambda + 2 mu
  double       strain = 0, height = 1;
  for (const double settlement : {0.5, 0.25})
    {
      sim.do_time_step(0.25);
      strain += settlement / height;
      height -= settlement;
      const double reaction = mpm_test::integrator_value(sim, "reaction_y");
      const double exact    = -M * strain * 1.;
      mpm_test::check_small("platen at " + std::to_string(height) +
                              ": reaction / exact - 1",
                            reaction / exact - 1,
                            1e-9);
    }
}
