// The spinning disk of BENCHMARKS.md section 3 on a coarse grid
// (h = 0.125) over a quarter turn. Angular momentum changed by 1.37% here
// when this test was written (the cell-crossing noise of standard MPM feeds
// it); the bound of 2% is a regression bound, not a physics target.
// The stress itself does NOT stay at the steady state with standard MPM on
// this grid: cell-crossing noise dominates (see the issue note); the
// stress errors are therefore printed, not asserted, here.
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpm_test::Case<2>                        c(R"(
set Kinematic assumption = plane stress
set Constants = a=1, omega=1, nu=0.3, rho=1000
set Benchmark = spinning disk
subsection Grid
  set Lower corner = -1.25, -1.25
  set Upper corner = 1.25, 1.25
  set Subdivisions = 20
end
subsection Bodies
  subsection Body 0
    set Geometry = ball
    set Center = 0, 0
    set Radius = 1
    set Refinements = 2
    set Initial velocity = -omega*y; omega*x
    set Initial stress = rho*omega^2/8*((3+nu)*a^2-(1+3*nu)*(x^2+y^2)) - rho*omega^2*(1-nu)/4*x^2; rho*omega^2/8*((3+nu)*a^2-(1+3*nu)*(x^2+y^2)) - rho*omega^2*(1-nu)/4*y^2; -rho*omega^2*(1-nu)/4*x*y
    subsection Material
      set Model = linear elastic
      set Density = 1000
      subsection Linear elastic
        set Young's modulus = 1e6
        set Poisson's ratio = 0.3
      end
    end
  end
end)");
  auto                                    &sim = *c.simulator;
  const auto                               s0  = sim.statistics();
  while (sim.time() < M_PI / 2)
    sim.do_time_step(
      std::min(0.5 * sim.stable_time_step(), M_PI / 2 - sim.time()));
  const auto b  = sim.benchmark_values();
  const auto s1 = sim.statistics();
  mpm_test::log() << "RMS (sigma_rr - exact)/sigma0 " << b[0]
                  << "\nRMS sigma_rt/sigma0 " << b[1] << "\nRMS v_r/(omega a) "
                  << b[2] << std::endl;
  mpm_test::check_small("angular momentum change",
                        (s1.angular_momentum[2] - s0.angular_momentum[2]) /
                          s0.angular_momentum[2],
                        0.02);
}
