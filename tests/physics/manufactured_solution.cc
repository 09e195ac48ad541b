// The manufactured solution u_i = G sin(pi X_i) sin(c pi t + phi_i)
// (doc/benchmarks/manufactured_solution.md, prm/manufactured_solution.prm,
// doc/benchmarks/manufactured_solution.md), standard MPM, MUSL,
// FLIP, G = 1e-4 (no particle crosses a cell face).
//
// 1. The benchmark files carry the right loads: the muparser body force of
//    prm/manufactured_solution.prm and of its 3D version equals the
//    benchmark's closed form (checked against the neo-Hookean law in
//    tests/unit/test_manufactured_solution.cc) to round-off, and every
//    particle starts with the exact velocity.
// 2. Convergence over one period from h = 1/16 to h = 1/32: the L2 and the
//    maximum displacement errors fell by 4.02 and 4.02 when this test was
//    written (0.0241 -> 0.0060 and 0.0340 -> 0.0085 of G), and the study
//    over h = 1/8 ... 1/64 gives rates 2.03, 2.01, 1.98 (doc/
//    benchmarks/manufactured_solution.md). The bound 3.5 on both ratios (a rate
//    of 1.8) leaves room for round-off and platform differences but fails for
//    an error of first order: the body force evaluated one step late (t + dt)
//    gives 0.0058 and 0.0033 (ratio 1.78), smaller at h = 1/16 yet of first
//    order, so the ratio and not the error size is the test. The errors
//    themselves are bounded 25% above the measured ones.
#include <mpm/benchmarks/manufactured_solution.h>

#include <random>

#include "../tests.h"

namespace
{
  const std::string benchmark_2d =
    "include " SOURCE_DIR "/../../prm/manufactured_solution.prm\n";
  const std::string benchmark_3d =
    "include " SOURCE_DIR "/../../prm/manufactured_solution_3d.prm\n";

  template <int dim>
  mpm::benchmarks::ManufacturedSolution<dim>
  exact_of(const mpm_test::Case<dim> &c)
  {
    const auto &k = c.parameters.constants;
    return {k.at("G"), k.at("E"), k.at("nu"), k.at("rho")};
  }

  /// Largest |b_file - b_exact| / |b| scale over random points and times,
  /// and the largest initial particle velocity error / (G c pi).
  template <int dim>
  void
  check_loads(const std::string &text, const std::string &name)
  {
    mpm_test::Case<dim> c(text);
    const auto          exact = exact_of(c);
    const auto         &body  = c.simulator->get_bodies()[0];
    const double G = c.parameters.constants.at("G"), cc = exact.wave_speed();
    const double scale = G * cc * cc * M_PI * M_PI;

    std::mt19937                           gen(3);
    std::uniform_real_distribution<double> unit(0., 1.);
    double                                 worst_force = 0;
    for (unsigned int q = 0; q < 50; ++q)
      {
        dealii::Point<dim> X;
        for (unsigned int d = 0; d < dim; ++d)
          X[d] = unit(gen);
        const double t = 2 / cc * unit(gen);
        double       b[dim];
        body.body_force_at(X, &X[0], t, b);
        const auto b_exact = exact.body_force(X, t);
        for (unsigned int d = 0; d < dim; ++d)
          worst_force = std::max(worst_force, std::abs(b[d] - b_exact[d]));
      }
    mpm_test::check_small(name +
                            ": body force of the file - exact, / G (c pi)^2",
                          worst_force / scale,
                          1e-12);

    using L               = mpm::ParticleLayout<dim>;
    double worst_velocity = 0;
    for (const auto &p : c.simulator->particles())
      {
        const double      *prop = p.get_properties().data();
        dealii::Point<dim> X;
        for (unsigned int d = 0; d < dim; ++d)
          X[d] = prop[L::X + d];
        const auto v = exact.velocity(X, 0);
        for (unsigned int d = 0; d < dim; ++d)
          worst_velocity =
            std::max(worst_velocity, std::abs(prop[L::velocity + d] - v[d]));
      }
    worst_velocity =
      dealii::Utilities::MPI::max(worst_velocity, MPI_COMM_WORLD);
    mpm_test::check_small(name + ": initial velocity - exact, / G c pi",
                          worst_velocity / (G * cc * M_PI),
                          1e-12);
  }

  /// L2 and max error / G after one period with n cells per direction.
  std::array<double, 2>
  errors_after_one_period(const unsigned int n)
  {
    const std::string  cells = std::to_string(n);
    mpm_test::Case<2>  c(benchmark_2d +
                        "subsection Grid\n set Subdivisions = " + cells +
                        "\nend\nsubsection Bodies\n subsection Body 0\n"
                         "  set Subdivisions = " +
                        cells + "\n end\nend\n");
    auto              &sim   = *c.simulator;
    const double       speed = exact_of(c).wave_speed();
    const double       T = 2 / speed, dt = 0.2 / (n * speed);
    const unsigned int steps = std::lround(T / dt);
    for (unsigned int s = 0; s < steps; ++s)
      sim.do_time_step(dt);
    mpm_test::check_small("h = 1/" + cells + ": time - T",
                          (sim.time() - T) / T,
                          1e-12);
    const auto b = sim.benchmark_values();
    return {{b[0], b[1]}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_loads<2>(benchmark_2d, "2D");
  check_loads<3>(benchmark_3d + "subsection Grid\n set Subdivisions = 4\nend\n"
                                "subsection Bodies\n subsection Body 0\n"
                                "  set Subdivisions = 4\n end\nend\n",
                 "3D");

  const auto coarse = errors_after_one_period(16);
  const auto fine   = errors_after_one_period(32);
  mpm_test::check_small("h = 1/16: L2 error / G", coarse[0], 0.030);
  mpm_test::check_small("h = 1/32: L2 error / G", fine[0], 0.0075);
  mpm_test::check_small("h = 1/32: max error / G", fine[1], 0.0106);
  mpm_test::check(coarse[0] / fine[0] > 3.5,
                  "L2 error ratio 1/16 : 1/32 above",
                  coarse[0] / fine[0],
                  3.5);
  mpm_test::check(coarse[1] / fine[1] > 3.5,
                  "max error ratio 1/16 : 1/32 above",
                  coarse[1] / fine[1],
                  3.5);
}
