// The node passes limited to the active nodes (grid/active_nodes.h) give
// exactly the vectors of the passes over the whole grid, while a block
// that deforms and crosses the grid (and, with mpirun=2, the rank
// boundary) changes the set of nodes it reaches every few steps. After
// each step of the simulation, on its particles:
// - P2G into a vector kept from step to step, zeroed where the tracker
//   says it may be non-zero, equals P2G into a vector zeroed whole;
// - the grid update and the nodal velocity over the active nodes, into
//   kept vectors, equal the passes over every node (owned and ghost
//   entries);
// for standard MPM (marks per cell) and uGIMP (marks per stencil entry).
// A tracker that forgot a node (a stale sum or velocity left behind)
// makes the difference O(1).
#include <mpm/grid/active_nodes.h>
#include <mpm/grid/grid_update.h>
#include <mpm/remedies/stress_filter.h>
#include <mpm/transfer/particle_to_grid.h>

#include "../tests.h"

namespace
{
  double
  max_difference(const mpm::NodalVector &a, const mpm::NodalVector &b)
  {
    double d = 0;
    for (unsigned int i = 0;
         i < a.locally_owned_size() + a.get_partitioner()->n_ghost_indices();
         ++i)
      d = std::max(d, std::abs(a.local_element(i) - b.local_element(i)));
    return dealii::Utilities::MPI::max(d, MPI_COMM_WORLD);
  }

  void
  run(const std::string &family)
  {
    using P = mpm::P2GLayout<2>;
    using K = mpm::KinematicsLayout<2>;
    mpm_test::Case<2> c(R"(
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 20
end
subsection Shape functions
  set Family = )" + family +
                        R"(
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.1, 0.15
    set Upper corner = 0.35, 0.4
    set Subdivisions = 5
    set Particles per direction = 2
    set Initial velocity = 1.0 + 2*(y - 0.3); 0.7 - 3*(x - 0.2)
    subsection Material
      set Model = linear elastic
      set Density = 1000
      subsection Linear elastic
        set Young's modulus = 1e4
      end
    end
  end
end)");
    auto             &sim  = *c.simulator;
    const auto       &grid = sim.grid();
    mpm::ActiveNodes  active;
    mpm::NodalVector  tracked_sums, whole_sums, tracked_kin, whole_kin;
    grid.initialize_vector(tracked_sums, P::n_components);
    grid.initialize_vector(whole_sums, P::n_components);
    grid.initialize_vector(tracked_kin, K::n_components);
    grid.initialize_vector(whole_kin, K::n_components);
    active.reset(*grid.node_partitioner());
    mpm::remedies::StressFilter<2> no_filter(sim.get_bodies());

    double       sums = 0, kinematics = 0, velocity = 0;
    unsigned int smallest = grid.n_owned_nodes(), largest = 0;
    for (unsigned int n = 0; n < 300; ++n) // 0.3 m: about six cells
      {
        sim.do_time_step(2e-3);
        for (mpm::ActiveNodes *a : {&active, (mpm::ActiveNodes *)nullptr})
          {
            mpm::transfer::P2GContext<2> p2g{
              {grid, sim.particles(), sim.domain_shape_functions(), 0},
              sim.get_bodies(),
              no_filter,
              sim.time(),
              mpm::transfer::P2GContent::mass_momentum_force,
              a ? tracked_sums : whole_sums,
              a};
            AssertThrow(mpm::transfer::particle_to_grid(p2g).empty(),
                        dealii::ExcInternalError());
          }
        sums = std::max(sums, max_difference(tracked_sums, whole_sums));
        smallest =
          std::min(smallest, static_cast<unsigned int>(active.nodes().size()));
        largest =
          std::max(largest, static_cast<unsigned int>(active.nodes().size()));
        mpm::update_grid(
          grid, tracked_sums, 2e-3, 0., 0., tracked_kin, &active);
        mpm::update_grid(grid, whole_sums, 2e-3, 0., 0., whole_kin);
        kinematics =
          std::max(kinematics, max_difference(tracked_kin, whole_kin));
        mpm::nodal_velocity(grid,
                            tracked_sums,
                            tracked_sums,
                            P::n_components,
                            P::momentum,
                            0.,
                            tracked_kin,
                            &active);
        mpm::nodal_velocity(grid,
                            whole_sums,
                            whole_sums,
                            P::n_components,
                            P::momentum,
                            0.,
                            whole_kin);
        velocity = std::max(velocity, max_difference(tracked_kin, whole_kin));
      }
    const double nodes =
      dealii::Utilities::MPI::sum(static_cast<double>(grid.n_owned_nodes()),
                                  MPI_COMM_WORLD);
    // the test means something only if the block reaches a small part of
    // the grid and the set changes
    const double most =
      dealii::Utilities::MPI::max(double(largest), MPI_COMM_WORLD);
    const double least =
      dealii::Utilities::MPI::min(double(smallest), MPI_COMM_WORLD);
    mpm_test::report(most < 0.25 * nodes,
                     family +
                       ": the block reaches less than a quarter of the nodes",
                     most / nodes);
    mpm_test::report(most > least,
                     family + ": the set of active nodes changes",
                     most - least);
    mpm_test::check_small(family + ": P2G sums, tracked - whole", sums, 0);
    mpm_test::check_small(family + ": grid update, tracked - whole",
                          kinematics,
                          0);
    mpm_test::check_small(family + ": nodal velocity, tracked - whole",
                          velocity,
                          0);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run("standard");
  run("uGIMP");
}
