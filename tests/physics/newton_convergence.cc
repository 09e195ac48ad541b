// Newton's method of the quasi-static integrator on the elastic column
// compaction (prm/column_compaction.prm: neo-Hookean, 4% compaction at the
// base, 20 load steps): every step converges in at most 4 iterations, and
// the order of convergence of its last iterations (convergence_rate:
// log(r_k/r_k-1)/log(r_k-1/r_k-2) over the residuals above round-off) is
// at least 1.8 in most steps and 1.5 in all. The first iteration of a step
// starts from r ~ 1, before the asymptotic range, which is why the
// minimum is lower. In the uniaxial column the geometric terms of the
// tangent cancel; the second case, Cook's membrane of neo-Hookean
// material under a shear load that bends it by 5% of its length in four
// load steps, needs them: every step converges with an order of at least
// 1.8 (about 1 with the geometric terms left out). The third case is
// plastic: Cook's membrane of von Mises material (plane strain, linear
// hardening) loaded until the clamp yields; every step that yields
// (Newton needs 4 or more iterations there) converges with an order of at
// least 1.8, through the algorithmic tangent of the radial return.
#include <algorithm>
#include <vector>

#include "../tests.h"

namespace
{
  /// Cook's membrane in plane strain, quasi-static, under the shear load
  /// @p load ramped linearly over @p ramp, in steps of @p step, of the
  /// material given by the entries @p material of its Material subsection.
  std::string
  cooks_membrane(const std::string &load,
                 const std::string &ramp,
                 const std::string &step,
                 const std::string &material)
  {
    return "include " SOURCE_DIR "/../../prm/cooks_membrane.prm\n"
           "set Kinematic assumption = plane strain\n"
           "set Constants = " +
           load +
           ", uy_ref=25.19, uy_ref_mid=23.967, "
           "r_fit=4, tr=" +
           ramp +
           ", E=1, rho=1\n"
           "subsection Time stepping\n"
           "  set Integrator = quasi-static\n"
           "  set Time step control = fixed\n"
           "  set Time step = " +
           step +
           "\n"
           "  set Damping coefficient = 0\n"
           "end\n"
           "subsection Output\n"
           "  set Directory = results\n"
           "end\n"
           "subsection Bodies\n"
           "  subsection Body 0\n"
           "    set Traction = 0; F/16*min(t/tr, 1)\n"
           "    subsection Material" +
           material +
           "\n"
           "    end\n"
           "  end\n"
           "end\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpm_test::Case<2>                        c("include " SOURCE_DIR
                      R"(/../../prm/column_compaction.prm
subsection Output
  set Directory = results
end)");
  auto                                    &sim     = *c.simulator;
  const auto                               columns = sim.integrator_columns();
  const auto column = [&](const std::string &name) {
    return std::find(columns.begin(), columns.end(), name) - columns.begin();
  };
  std::vector<double> rates;
  unsigned int        most_iterations = 0;
  while (sim.time() < 1 - 1e-9)
    {
      sim.do_time_step(0.05);
      const auto v = sim.integrator_values();
      rates.push_back(v[column("convergence_rate")]);
      most_iterations =
        std::max<unsigned int>(most_iterations, v[column("newton_iterations")]);
    }
  std::sort(rates.begin(), rates.end());
  mpm_test::check(most_iterations <= 4,
                  "most Newton iterations of a step",
                  most_iterations,
                  4);
  mpm_test::report(rates.front() >= 1.5,
                   "smallest order of convergence >= 1.5",
                   rates.front());
  mpm_test::report(rates[rates.size() / 2] >= 1.8,
                   "median order of convergence >= 1.8",
                   rates[rates.size() / 2]);
  const double stress_error = sim.benchmark_values()[0];
  mpm_test::check_small("sigma_yy error (RMS, relative) at the end",
                        stress_error,
                        0.05);

  mpm_test::Case<2> cook(cooks_membrane("F=0.1", "1", "0.1", R"(
      set Model = neo-Hookean
      subsection Neo-Hookean
        set Young's modulus = E
        set Poisson's ratio = 0.3
      end)"));
  double            slowest = 1e300;
  for (unsigned int step = 0; step < 4; ++step)
    {
      cook.simulator->do_time_step(0.1);
      slowest = std::min(
        slowest,
        cook.simulator->integrator_values()[column("convergence_rate")]);
    }
  mpm_test::report(slowest >= 1.8,
                   "Cook's membrane, neo-Hookean: smallest order >= 1.8",
                   slowest);

  mpm_test::Case<2> plastic(cooks_membrane("F=1e-3", "2", "0.125", R"(
      set Model = von Mises plasticity
      subsection Von Mises plasticity
        set Young's modulus = E
        set Poisson's ratio = 0.3
        set Yield stress = 2e-4
        set Hardening modulus = 0.01
      end)"));
  unsigned int      yielding_steps  = 0;
  double            slowest_plastic = 1e300;
  for (unsigned int step = 0; step < 16; ++step)
    {
      plastic.simulator->do_time_step(0.125);
      const auto v = plastic.simulator->integrator_values();
      if (v[column("newton_iterations")] >= 4)
        {
          ++yielding_steps;
          slowest_plastic =
            std::min(slowest_plastic, v[column("convergence_rate")]);
        }
    }
  mpm_test::report(yielding_steps >= 2,
                   "Cook's membrane, von Mises: it yields",
                   yielding_steps);
  mpm_test::report(slowest_plastic >= 1.8,
                   "Cook's membrane, von Mises: smallest order of a "
                   "yielding step >= 1.8",
                   slowest_plastic);
}
