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
// least 1.8, through the algorithmic tangent of the radial return. The
// last two repeat the neo-Hookean and the plastic case with Volumetric
// smoothing = cell: F-bar for the neo-Hookean model, the rate form's
// B-bar under the radial return. Their linearizations couple the
// particles of a cell; the same orders show that they are consistent
// (without the coupling terms, F-bar converges linearly, by a factor of
// about 0.6 per iteration). nu = 0.3: near nu = 0.5 the residual's
// round-off floor rises to 1e-11 and the order of three residuals no
// longer measures the tangent, with or without smoothing.
#include <algorithm>
#include <vector>

#include "../tests.h"

namespace
{
  /// Cook's membrane in plane strain, quasi-static, under the shear load
  /// @p load ramped linearly over @p ramp, in steps of @p step, of the
  /// material given by the entries @p material of its Material subsection,
  /// with the `Volumetric smoothing` @p smoothing.
  std::string
  cooks_membrane(const std::string &load,
                 const std::string &ramp,
                 const std::string &step,
                 const std::string &material,
                 const std::string &smoothing = "none")
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
           "    subsection Locking remedies\n"
           "      set Volumetric smoothing = " +
           smoothing +
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
  auto                                    &sim = *c.simulator;
  std::vector<double>                      rates;
  unsigned int                             most_iterations = 0;
  while (sim.time() < 1 - 1e-9)
    {
      sim.do_time_step(0.05);
      rates.push_back(mpm_test::integrator_value(sim, "convergence_rate"));
      most_iterations = std::max<unsigned int>(
        most_iterations, mpm_test::integrator_value(sim, "newton_iterations"));
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

  // Cook's membrane: the smallest order of the steps with at least
  // @p min_iterations Newton iterations (all: 0; the yielding ones of the
  // plastic load: 4) and how many there were.
  const auto slowest_order = [&](const std::string &load,
                                 const std::string &ramp,
                                 const double       step,
                                 const unsigned int n_steps,
                                 const std::string &material,
                                 const std::string &smoothing,
                                 const unsigned int min_iterations) {
    mpm_test::Case<2> cook(
      cooks_membrane(load, ramp, std::to_string(step), material, smoothing));
    double       slowest = 1e300;
    unsigned int counted = 0;
    for (unsigned int k = 0; k < n_steps; ++k)
      {
        cook.simulator->do_time_step(step);
        const auto &run = *cook.simulator;
        if (mpm_test::integrator_value(run, "newton_iterations") >=
            min_iterations)
          {
            ++counted;
            slowest =
              std::min(slowest,
                       mpm_test::integrator_value(run, "convergence_rate"));
          }
      }
    return std::make_pair(slowest, counted);
  };
  const std::string neo_hookean = R"(
      set Model = neo-Hookean
      subsection Neo-Hookean
        set Young's modulus = E
        set Poisson's ratio = 0.3
      end)";
  const std::string von_mises   = R"(
      set Model = von Mises plasticity
      subsection Von Mises plasticity
        set Young's modulus = E
        set Poisson's ratio = 0.3
        set Yield stress = 2e-4
        set Hardening modulus = 0.01
      end)";
  for (const std::string smoothing : {"none", "cell"})
    {
      const std::string elastic_name =
        smoothing == "none" ? "neo-Hookean" : "neo-Hookean, F-bar";
      const std::string plastic_name =
        smoothing == "none" ? "von Mises" : "von Mises, theta-bar";
      const auto elastic =
        slowest_order("F=0.1", "1", 0.1, 4, neo_hookean, smoothing, 0);
      mpm_test::report(elastic.first >= 1.8,
                       "Cook's membrane, " + elastic_name +
                         ": smallest order >= 1.8",
                       elastic.first);
      const auto plastic =
        slowest_order("F=1e-3", "2", 0.125, 16, von_mises, smoothing, 4);
      mpm_test::report(plastic.second >= 2,
                       "Cook's membrane, " + plastic_name + ": it yields",
                       plastic.second);
      mpm_test::report(plastic.first >= 1.8,
                       "Cook's membrane, " + plastic_name +
                         ": smallest order of a yielding step >= 1.8",
                       plastic.first);
    }
}
