// The smooth rigid strip footing on undrained clay (prm/strip_footing.prm:
// von Mises, nu = 0.49, E = 100 c_u, B = 1, half model) on the coarse grid
// h = 0.25, pressed down to a settlement of 0.1 B in ten load steps of the
// quasi-static integrator. The bearing pressure q = -2 reaction_y / B
// against Prandtl's limit (2 + pi) c_u: standard MPM locks (q at least
// 1.4 times the limit, and still rising), theta-bar (Volumetric smoothing
// = cell, linearized) does not (within 15% of the limit on this grid;
// doc/benchmarks/strip_footing.md has the finer grids).
//
// The same with Implicit solver/Geometry = fixed (equilibrium in the
// undeformed shape) to 0.3 B: standard MPM's q still grows by more than
// 10% from 0.2 B to 0.3 B, theta-bar's has reached its limit load (less
// than 0.5% change), 16% above Prandtl's on this grid.
#include <algorithm>
#include <cmath>
#include <vector>

#include "../tests.h"

namespace
{
  /// q / c_u after each step of 0.01 B up to @p steps, with the
  /// `Volumetric smoothing` @p smoothing and the implicit step's
  /// `Geometry` @p geometry.
  std::vector<double>
  bearing_pressure(const std::string &smoothing,
                   const std::string &geometry,
                   const unsigned int steps)
  {
    mpm_test::Case<2>   c("set Number of bodies = 2\n"
                          "include " SOURCE_DIR "/../../prm/strip_footing.prm\n"
                          R"(
subsection Grid
  set Subdivisions = 20, 25
end
subsection Output
  set Directory = results
  set Write vtu = false
end
subsection Implicit solver
  set Geometry = )" + geometry +
                          R"(
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
    auto               &sim = *c.simulator;
    std::vector<double> q;
    for (unsigned int step = 0; step < steps; ++step)
      {
        sim.do_time_step(0.01);
        q.push_back(-2 * mpm_test::integrator_value(sim, "reaction_y") / 1e4);
      }
    return q;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             prandtl = 2 + M_PI;
  const double standard = bearing_pressure("none", "updated", 10)[9] / prandtl;
  mpm_test::check(standard >= 1.4,
                  "standard MPM: q / Prandtl's limit at 0.1 B (locked)",
                  standard,
                  1.4);
  const double theta_bar = bearing_pressure("cell", "updated", 10)[9] / prandtl;
  mpm_test::check_small("theta-bar: q / Prandtl's limit - 1 at 0.1 B",
                        theta_bar - 1,
                        0.15);

  const auto fixed_standard = bearing_pressure("none", "fixed", 30);
  mpm_test::check(fixed_standard[29] / fixed_standard[19] - 1 >= 0.1,
                  "fixed geometry, standard MPM: q(0.3 B) / q(0.2 B) - 1 "
                  "(still rising)",
                  fixed_standard[29] / fixed_standard[19] - 1,
                  0.1);
  const auto fixed_theta_bar = bearing_pressure("cell", "fixed", 30);
  mpm_test::check_small("fixed geometry, theta-bar: q(0.3 B) / q(0.2 B) - 1 "
                        "(a limit load)",
                        fixed_theta_bar[29] / fixed_theta_bar[19] - 1,
                        0.005);
  mpm_test::check_small("fixed geometry, theta-bar: q(0.3 B) / Prandtl's "
                        "limit - 1",
                        fixed_theta_bar[29] / prandtl - 1,
                        0.17);
}
