// A free-falling block (no boundary conditions, uniform gravity) must have
// v = g t exactly and stay stress-free: every node sees the same
// acceleration, so the velocity gradient vanishes to round-off.
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpm_test::Case<2>                        c(R"(
subsection Grid
  set Lower corner = 0, -2
  set Upper corner = 1, 1
  set Subdivisions = 8, 24
end
subsection Time stepping
  set Time step control = fixed
  set Time step = 1e-3
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.3, 0.4
    set Upper corner = 0.7, 0.8
    set Subdivisions = 6
    set Body force = 0; -9.81
    subsection Material
      set Model = neo-Hookean
      set Density = 1000
    end
  end
end)");
  auto                                    &sim = *c.simulator;
  for (unsigned int n = 0; n < 200; ++n)
    sim.do_time_step(1e-3);
  const auto   s    = sim.statistics();
  const double t    = sim.time();
  const double v_cm = s.momentum[1] / s.mass;
  mpm_test::check_small("v_cm + g t", (v_cm + 9.81 * t) / (9.81 * t), 1e-12);
  mpm_test::check_small("v_cm_x", s.momentum[0] / s.mass, 1e-12);
  mpm_test::check_small("steps that needed deal.II's global sort",
                        sim.n_global_sorts_used(),
                        0);
  mpm_test::check_small("strain energy / kinetic energy",
                        s.strain_energy / s.kinetic_energy,
                        1e-20);
  double max_dev = 0;
  for (const auto &p : sim.particles())
    max_dev =
      std::max(max_dev,
               std::abs(
                 p.get_properties()[mpm::ParticleLayout<2>::velocity + 1] +
                 9.81 * t));
  max_dev = dealii::Utilities::MPI::max(max_dev, MPI_COMM_WORLD);
  mpm_test::check_small("max |v_p + g t| / (g t)", max_dev / (9.81 * t), 1e-12);
}
