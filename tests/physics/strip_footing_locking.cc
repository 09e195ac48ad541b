// The smooth rigid strip footing on undrained clay (prm/strip_footing.prm:
// von Mises, nu = 0.49, E = 100 c_u, B = 1, half model) on the coarse grid
// h = 0.25, pressed down to a settlement of 0.1 B in ten load steps of the
// quasi-static integrator. The bearing pressure q = -2 reaction_y / B
// against Prandtl's limit (2 + pi) c_u: standard MPM locks (q at least
// 1.4 times the limit, and still rising), theta-bar (Volumetric smoothing
// = cell, linearized) does not (within 15% of the limit on this grid;
// doc/benchmarks/strip_footing.md has the finer grids).
//
// The limit load of the discretization: Implicit solver/Geometry = fixed
// (equilibrium in the undeformed shape) with a stiff soil, E = 1e5 c_u,
// which reaches it within a few steps of 1e-4 B, before the fixed grid is
// sheared: theta-bar's q changes by less than 0.1% from step 10 to 20, and
// is within 15% of Prandtl's limit on this grid (the doc's graded grids
// converge to it); standard MPM's grows by more than 20%, it has no limit
// load.
//
// Geometry = small strain is linear in the kinematics: the benchmark's
// soil, E = 100 c_u, in steps of 0.1 B gives theta-bar the loads of the
// stiff soil in steps of 1e-4 B at every step (1e-6 relative; a
// finite-strain update would be sheared by many cells here).
#include <algorithm>
#include <cmath>
#include <vector>

#include "../tests.h"

namespace
{
  /// q / c_u after each of @p steps load steps of @p step B, with the
  /// `Volumetric smoothing` @p smoothing, the implicit step's `Geometry`
  /// @p geometry and the soil's E / c_u @p stiffness.
  std::vector<double>
  bearing_pressure(const std::string &smoothing,
                   const std::string &geometry,
                   const std::string &stiffness,
                   const double       step,
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
    subsection Material
      subsection Von Mises plasticity
        set Young's modulus = )" +
                          stiffness + R"(*cu
      end
    end
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
    for (unsigned int k = 0; k < steps; ++k)
      {
        sim.do_time_step(step);
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
  const double                             standard =
    bearing_pressure("none", "updated", "100", 0.01, 10)[9] / prandtl;
  mpm_test::check(standard >= 1.4,
                  "standard MPM: q / Prandtl's limit at 0.1 B (locked)",
                  standard,
                  1.4);
  const double theta_bar =
    bearing_pressure("cell", "updated", "100", 0.01, 10)[9] / prandtl;
  mpm_test::check_small("theta-bar: q / Prandtl's limit - 1 at 0.1 B",
                        theta_bar - 1,
                        0.15);

  const auto fixed_standard =
    bearing_pressure("none", "fixed", "1e5", 1e-4, 20);
  mpm_test::check(fixed_standard[19] / fixed_standard[9] - 1 >= 0.2,
                  "limit load, standard MPM: q(step 20) / q(step 10) - 1 "
                  "(still rising)",
                  fixed_standard[19] / fixed_standard[9] - 1,
                  0.2);
  const auto fixed_theta_bar =
    bearing_pressure("cell", "fixed", "1e5", 1e-4, 20);
  mpm_test::check_small("limit load, theta-bar: q(step 20) / q(step 10) - 1",
                        fixed_theta_bar[19] / fixed_theta_bar[9] - 1,
                        1e-3);
  mpm_test::check_small("limit load, theta-bar: q / Prandtl's limit - 1",
                        fixed_theta_bar[19] / prandtl - 1,
                        0.15);

  const auto soft   = bearing_pressure("cell", "small strain", "100", 0.1, 20);
  const auto stiff  = bearing_pressure("cell", "small strain", "1e5", 1e-4, 20);
  double     scaled = 0;
  for (unsigned int k = 0; k < 20; ++k)
    scaled = std::max(scaled, std::abs(soft[k] / stiff[k] - 1));
  // (round-off: no value printed)
  mpm_test::report(scaled < 1e-6,
                   "small strain, theta-bar: q(E = 100 c_u, steps of 0.1 B) "
                   "equals q(E = 1e5 c_u, steps of 1e-4 B) at every step "
                   "(1e-6 relative)",
                   scaled);
}
