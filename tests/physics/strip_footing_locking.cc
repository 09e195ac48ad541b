// The smooth rigid strip footing on undrained clay (prm/strip_footing.prm:
// von Mises, nu = 0.49, E = 100 c_u, B = 1, half model) on the coarse grid
// h = 0.25, pressed down to a settlement of 0.1 B in ten load steps of the
// quasi-static integrator. The bearing pressure q = -2 reaction_y / B
// against Prandtl's limit (2 + pi) c_u: standard MPM locks (q at least
// 1.4 times the limit, and still rising), theta-bar (Volumetric smoothing
// = cell, linearized) does not (within 15% of the limit on this grid;
// doc/benchmarks/strip_footing.md has the finer grids).
#include <algorithm>
#include <cmath>

#include "../tests.h"

namespace
{
  /// q / c_u after ten steps of 0.01 B, with the `Volumetric smoothing`
  /// @p smoothing.
  double
  bearing_pressure(const std::string &smoothing)
  {
    mpm_test::Case<2> c("set Number of bodies = 2\n"
                        "include " SOURCE_DIR "/../../prm/strip_footing.prm\n"
                        R"(
subsection Grid
  set Subdivisions = 20, 25
end
subsection Output
  set Directory = results
  set Write vtu = false
end
subsection Bodies
  subsection Body 0
    set Subdivisions = 20, 20
    subsection Locking remedies
      set Volumetric smoothing = )" +
                          smoothing + R"(
    end
  end
  subsection Body 1
    set Upper corner = 0.5, 5.25
    set Subdivisions = 2, 1
  end
end)",
                        2);
    auto             &sim = *c.simulator;
    for (unsigned int step = 0; step < 10; ++step)
      sim.do_time_step(0.01);
    return -2 * mpm_test::integrator_value(sim, "reaction_y") / 1e4;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             prandtl = 2 + M_PI;
  const double standard = bearing_pressure("none") / prandtl;
  mpm_test::check(standard >= 1.4,
                  "standard MPM: q / Prandtl's limit at 0.1 B (locked)",
                  standard,
                  1.4);
  const double theta_bar = bearing_pressure("cell") / prandtl;
  mpm_test::check_small("theta-bar: q / Prandtl's limit - 1 at 0.1 B",
                        theta_bar - 1,
                        0.15);
}
