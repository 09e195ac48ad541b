// With `Particles leaving the grid = remove`, a block moving out through
// the free right side of the grid loses its particles one by one; the
// statistics count them and the removed mass, so that mass + removed mass
// stays the initial mass exactly, on 1 and 2 ranks.
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpm_test::Case<2>                        c(R"(
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 0.5
  set Subdivisions = 16, 8
end
subsection Boundary conditions
  set Particles leaving the grid = remove
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.55, 0.1
    set Upper corner = 0.95, 0.4
    set Subdivisions = 4, 3
    set Initial velocity = 2; 0
    subsection Material
      set Model = linear elastic
      set Density = 1000
    end
  end
end)");
  auto                                    &sim = *c.simulator;
  const auto                               s0  = sim.statistics();
  while (sim.time() < 0.1 - 1e-12)
    sim.do_time_step(std::min(0.5 * sim.stable_time_step(), 0.1 - sim.time()));
  sim.particles().update_cached_numbers();
  const auto s1 = sim.statistics();
  mpm_test::log() << "particles: " << s0.n_particles << " -> " << s1.n_particles
                  << std::endl;
  mpm_test::check(s1.n_particles < s0.n_particles && s1.n_particles > 0,
                  "some but not all particles removed",
                  double(s1.n_particles),
                  double(s0.n_particles));
  mpm_test::check_small("(mass + removed mass - initial mass) / initial mass",
                        (s1.mass + s1.removed_mass - s0.mass) / s0.mass,
                        1e-14);
}
