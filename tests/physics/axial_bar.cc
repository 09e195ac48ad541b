// Axial vibration of a fixed-free bar (doc/benchmarks/axial_bar.md), E = 100,
// L = 25, rho = 1, v0 = 0.1, 16 cells, 2 particles per cell,
// dt = 0.2 h/c, over one period T = 10. Exact: v = v0 cos(wt) sin(beta X).
//
// Tolerances: lumped-mass linear elements shift the frequency by about
// (beta h)^2/24 = 4e-4 (relative), a phase error of 2.5e-3 rad per period;
// particle quadrature adds a similar amount. So after one period the
// centre-of-mass velocity must match v0 cos(wt)/(beta L) to 1% of its
// amplitude, and the RMS particle velocity error stays below 2% of v0.
// Energy: MUSL with FLIP is not exactly conservative; 2% over one period.
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpm_test::Case<1>                        c(R"(
set Constants = L=25, E=100, rho=1, v0=0.1
set Benchmark = axial bar
subsection Grid
  set Lower corner = 0
  set Upper corner = 28.125
  set Subdivisions = 18
end
subsection Boundary conditions
  set Fixed boundary ids = 0
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0
    set Upper corner = 25
    set Subdivisions = 16
    set Initial velocity = v0*sin(pi/(2*L)*x)
    subsection Material
      set Model = linear elastic
      set Density = 1
      subsection Linear elastic
        set Young's modulus = 100
        set Poisson's ratio = 0
      end
    end
  end
end)");
  auto                                    &sim   = *c.simulator;
  const auto                               s0    = sim.statistics();
  const double                             dt    = 0.2 * (25. / 16) / 10.;
  double                                   worst = 0, worst_cm = 0;
  for (unsigned int n = 0; n < 320; ++n)
    {
      sim.do_time_step(dt);
      const auto b = sim.benchmark_values();
      worst        = std::max(worst, b[2]);
      worst_cm     = std::max(worst_cm, std::abs(b[0] - b[1]));
    }
  const auto   b         = sim.benchmark_values();
  const auto   s1        = sim.statistics();
  const double amplitude = 0.1 / (M_PI / 50 * 25);
  mpm_test::check_small("time - T", sim.time() - 10., 1e-10);
  mpm_test::check_small("v_cm error at T / amplitude",
                        (b[0] - b[1]) / amplitude,
                        0.01);
  mpm_test::check_small("max v_cm error over the period / amplitude",
                        worst_cm / amplitude,
                        0.02);
  mpm_test::check_small("max RMS velocity error / v0", worst, 0.02);
  mpm_test::check_small("energy change / E0",
                        (s1.kinetic_energy + s1.strain_energy -
                         s0.kinetic_energy) /
                          s0.kinetic_energy,
                        0.02);
}
