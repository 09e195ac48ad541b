// A rigid body of prescribed motion in the Newmark step: the platen of
// rigid_platen (platen_block.h) presses the block (nu = 0.3, its base
// fixed, its sides free, so the block's top nodes, which the smooth
// platen holds in y only, move outward in x) down by 5 mm and then by
// 2.5 mm in two steps, the block of little mass (density 1e-3).
//
// - The platen's density (1 or 1e6) does not change the reaction, to
//   1e-9: the nodes' inertia is that of the deformable bodies only, and
//   the platen's mass does not hold its nodes' free directions (with it,
//   the reaction of the first step is 2.6% off).
// - The first step's reaction is the quasi-static one to 1e-6 (the
//   block's inertia changes it by about 1e-8). The second is not: the
//   trapezoidal rule carries the imbalance of the step's start (the
//   particle quadrature on the reset grid), 1.2e-4 of the reaction here,
//   into its end.
#include <cmath>

#include "../tests.h"
#include "platen_block.h"

namespace
{
  std::vector<double>
  reactions(const std::string &integrator, const std::string &platen_density)
  {
    mpm_test::Case<2>   c(platen_block::parameters("0.3",
                                                 "t < 0.25 ? -0.02 : -0.01",
                                                 R"(    subsection Material
      set Density = 1e-3
    end
)") + R"(
subsection Time stepping
  set Integrator = )" + integrator +
                          R"(
end
subsection Boundary conditions
  set Slip boundary ids =
  set Fixed boundary ids = 2
end
subsection Bodies
  subsection Body 1
    subsection Material
      set Density = )" + platen_density +
                          R"(
    end
  end
end)",
                        2);
    std::vector<double> r;
    for (unsigned int k = 0; k < 2; ++k)
      {
        c.simulator->do_time_step(0.25);
        r.push_back(mpm_test::integrator_value(*c.simulator, "reaction_y"));
      }
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               light = reactions("Newmark", "1");
  const auto                               heavy = reactions("Newmark", "1e6");
  const auto quasi_static = reactions("quasi-static", "1e6");
  for (unsigned int k = 0; k < 2; ++k)
    mpm_test::report(std::abs(heavy[k] / light[k] - 1) < 1e-9,
                     "step " + std::to_string(k + 1) +
                       ": the platen's density does not change Newmark's "
                       "reaction_y (1e-9)",
                     heavy[k] / light[k] - 1);
  mpm_test::report(std::abs(heavy[0] / quasi_static[0] - 1) < 1e-6,
                   "step 1: Newmark's reaction_y is the quasi-static one "
                   "(1e-6)",
                   heavy[0] / quasi_static[0] - 1);
}
