// A block in rigid translation across a distorted (non-Cartesian) grid,
// through many cells and, with mpirun=2, across the rank boundary:
// - every particle moves exactly with x = X + v t and stays stress-free;
// - particles are sorted into cells correctly by the project's own
//   relocation (reference coordinates map back to the position, and
//   deal.II's own sort afterwards changes nothing);
// - no particle is lost or duplicated;
// - a particle loop between two steps (output, the time step) visits
//   every particle, also those that entered cells empty before the step.
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>

#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using L = mpm::ParticleLayout<2>;
  mpm_test::Case<2> c(R"(
subsection Grid
  set Type = mesh file
  set Mesh file = )" SOURCE_DIR R"(/../solver/distorted_grid_2d.ucd
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.1, 0.15
    set Upper corner = 0.35, 0.4
    set Subdivisions = 5
    set Particles per direction = 3
    set Initial velocity = 1.0; 0.7
    subsection Material
      set Model = linear elastic
      set Density = 1000
    end
  end
end)");
  auto             &sim = *c.simulator;
  const auto        n0  = sim.particles().n_global_particles();
  const double      dt  = 1e-3;
  double missed         = 0; // most particles a loop after a step did not visit
  for (unsigned int n = 0; n < 500; ++n) // 0.5 m: about four cells
    {
      sim.do_time_step(dt);
      double visited = 0;
      mpm::for_each_cell_with_particles(
        sim.grid(), sim.particles(), [&](const auto &, const auto &pic) {
          for (auto p = pic.begin(); p != pic.end(); ++p)
            ++visited;
        });
      missed =
        std::max(missed,
                 double(sim.particles().n_locally_owned_particles()) - visited);
    }
  missed         = dealii::Utilities::MPI::max(missed, MPI_COMM_WORLD);
  const double t = sim.time();

  double             max_position = 0, max_stress = 0, max_mapping = 0;
  unsigned long long id_sum = 0;
  for (const auto &cell : sim.grid().triangulation().active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &p : sim.particles().particles_in_cell(cell))
        {
          const double          *prop = p.get_properties().data();
          const dealii::Point<2> exact(prop[L::X] + 1.0 * t,
                                       prop[L::X + 1] + 0.7 * t);
          max_position =
            std::max(max_position, p.get_location().distance(exact));
          for (unsigned int s = 0; s < 6; ++s)
            max_stress = std::max(max_stress, std::abs(prop[L::stress + s]));
          max_mapping = std::max(max_mapping,
                                 sim.grid()
                                   .geometry(cell)
                                   .map(p.get_reference_location())
                                   .distance(p.get_location()));
          id_sum += p.get_id();
        }
  const MPI_Comm comm = MPI_COMM_WORLD;
  max_position        = dealii::Utilities::MPI::max(max_position, comm);
  max_stress          = dealii::Utilities::MPI::max(max_stress, comm);
  max_mapping         = dealii::Utilities::MPI::max(max_mapping, comm);
  id_sum              = dealii::Utilities::MPI::sum(id_sum, comm);

  // deal.II's sort must find every particle where the relocation put it.
  std::map<dealii::types::particle_index, dealii::Point<2>> before;
  for (const auto &p : sim.particles())
    before[p.get_id()] = p.get_reference_location();
  sim.particles().sort_particles_into_subdomains_and_cells();
  double moved = 0;
  for (const auto &p : sim.particles())
    {
      const auto it = before.find(p.get_id());
      moved         = std::max(moved,
                       it == before.end() ?
                                 1. :
                                 p.get_reference_location().distance(it->second));
    }
  moved = dealii::Utilities::MPI::max(moved, comm);
  sim.particles().update_cached_numbers();

  mpm_test::check_small("particles lost or duplicated",
                        double(sim.particles().n_global_particles()) -
                          double(n0),
                        0);
  mpm_test::check_small("id checksum",
                        double(id_sum) - double(n0 * (n0 - 1) / 2),
                        0);
  mpm_test::check_small("max |x - (X + v t)|", max_position, 1e-12);
  mpm_test::check_small("steps that needed deal.II's global sort",
                        sim.n_global_sorts_used(),
                        0);
  mpm_test::check_small("max |stress| [Pa]", max_stress, 1e-9);
  mpm_test::check_small("max |x(xi) - x|", max_mapping, 1e-12);
  // deal.II's inverse mapping stops at about 1e-11; a particle in the
  // wrong cell would differ by O(1).
  mpm_test::check_small("change by deal.II's sort", moved, 1e-8);
  mpm_test::check_small("particles a loop after a step missed", missed, 0);
}
