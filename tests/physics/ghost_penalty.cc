// The ghost penalty of the implicit step (Implicit solver/Ghost penalty,
// doc/guide/implicit.md) on Cook's membrane of neo-Hookean material in
// plane strain (prm/cooks_membrane.prm, quasi-static, F = 0.1 ramped over
// t = 1 in steps of 0.1, four steps). uGIMP's particle boxes reach across
// the loaded edge by slivers; without the penalty Newton fails in the
// second step, even after a step cut. With beta = 1e-3 it runs, and
// u_y(48, 52) is within 0.5% of standard MPM's. Standard MPM runs without
// the penalty; beta = 1e-3 changes its u_y(48, 52) by less than 0.2%.
#include <cmath>

#include "../tests.h"

namespace
{
  /// u_y(48, 52) after four steps, or NaN if the run stops (Newton fails
  /// after at most @p cuts step cuts).
  double
  deflection(const std::string &family,
             const std::string &beta,
             const std::string &cuts = "6")
  {
    mpm_test::Case<2> c("include " SOURCE_DIR "/../../prm/cooks_membrane.prm\n"
                        "set Kinematic assumption = plane strain\n"
                        "set Constants = F=0.1, uy_ref=25.19, "
                        "uy_ref_mid=23.967, r_fit=4, tr=1, E=1, rho=1\n" +
                        std::string(R"(
subsection Time stepping
  set Integrator = quasi-static
  set Time step control = fixed
  set Time step = 0.1
  set Damping coefficient = 0
end
subsection Implicit solver
  set Ghost penalty = )") +
                        beta + R"(
  set Maximum step cuts = )" +
                        cuts + R"(
end
subsection Shape functions
  set Family = )" + family +
                        R"(
end
subsection Output
  set Directory = results
end
subsection Bodies
  subsection Body 0
    set Traction = 0; F/16*min(t/tr, 1)
    subsection Material
      set Model = neo-Hookean
      subsection Neo-Hookean
        set Young's modulus = E
        set Poisson's ratio = 0.3
      end
    end
  end
end)");
    try
      {
        for (unsigned int k = 0; k < 4; ++k)
          c.simulator->do_time_step(0.1);
      }
    catch (const std::exception &)
      {
        return std::nan("");
      }
    return c.simulator->benchmark_values()[1];
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double standard = deflection("standard", "0");
  mpm_test::report(std::isfinite(standard),
                   "standard MPM runs without the penalty",
                   standard);
  const double held = deflection("standard", "1e-3");
  mpm_test::check(std::abs(held / standard - 1) < 2e-3,
                  "standard MPM, beta = 1e-3: u_y(48, 52) against beta = 0",
                  std::abs(held / standard - 1),
                  2e-3);
  mpm_test::report(std::isnan(deflection("uGIMP", "0", "1")),
                   "uGIMP without the penalty stops (Newton fails)",
                   0);
  const double ugimp = deflection("uGIMP", "1e-3");
  mpm_test::check(std::abs(ugimp / standard - 1) < 5e-3,
                  "uGIMP, beta = 1e-3: u_y(48, 52) against standard MPM",
                  std::abs(ugimp / standard - 1),
                  5e-3);
}
