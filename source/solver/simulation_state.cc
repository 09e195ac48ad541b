#include <deal.II/base/mpi.h>

#include <mpm/grid/grid_update.h>
#include <mpm/particles/particle_relocation.h>
#include <mpm/remedies/volumetric_smoothing.h>
#include <mpm/solver/simulation_state.h>
#include <mpm/solver/stress_update.h>
#include <mpm/transfer/particle_to_grid.h>

namespace mpm
{
  template <int dim>
  void
  SimulationState<dim>::initialize_nodal_vectors()
  {
    background.initialize_vector(p2g, transfer::P2GLayout<dim>::n_components);
    background.initialize_vector(kinematics,
                                 KinematicsLayout<dim>::n_components);
    background.initialize_vector(remap, dim);
    active_nodes.reset(*background.node_partitioner());
    if (contact)
      contact->initialize_vectors(background);
    if (remedies::VolumetricSmoothing<dim>::through_nodes(bodies))
      background.initialize_vector(
        volume_sums, remedies::VolumetricSmoothing<dim>::n_node_sums);
  }

  template <int dim>
  void
  SimulationState<dim>::relocate_moved_particles()
  {
    lost_messages.clear();
    if (!relocate_particles(background, particle_handler, comm))
      {
        // deal.II's sort drops a particle whose new cell lies beyond the
        // ghost layer of its rank without telling: count them.
        const auto count = [&]() {
          return dealii::Utilities::MPI::sum(
            static_cast<double>(particle_handler.n_locally_owned_particles()),
            comm);
        };
        const double before = count();
        particle_handler.sort_particles_into_subdomains_and_cells();
        ++n_global_sorts;
        const double reported =
          dealii::Utilities::MPI::sum(static_cast<double>(lost_messages.size()),
                                      comm);
        const double dropped = before - count() - reported;
        if (dropped > 0.5)
          local_error.record(
            std::to_string(static_cast<long>(dropped)) +
            " particle(s) moved in one step into cells beyond the ghost "
            "layer of their rank and were lost: on several ranks a step "
            "may move a particle by about one cell at most (take a "
            "smaller Time step, or run on one rank)");
      }
    // The particles are in their new cells: the next loop checks the list
    // of cells with particles.
    background.particles_changed_cells();
    if (!lost_messages.empty() && !params.boundary.remove_lost_particles)
      local_error.record(lost_messages.front() +
                         " (set Boundary conditions/Particles leaving the "
                         "grid = remove to delete such particles instead)");
  }

  template <int dim>
  double
  SimulationState<dim>::update_particle_stress(const double          dt,
                                               const NodalVector    &velocities,
                                               const FieldSelection &only)
  {
    dealii::TimerOutput::Scope t(timer, "stress update");
    const auto                 r = ::mpm::update_stress(
      background,
      particle_handler,
      bodies,
      velocities,
      dt,
      &volume_sums,
      domain_functions.get(),
      only,
      params.time.integrator ==
        Parameters::TimeStepping::Integrator::explicit_dynamics,
      params.implicit.small_strain);
    local_error.record(r.error);
    return r.stable_time_step;
  }

  template struct SimulationState<1>;
  template struct SimulationState<2>;
  template struct SimulationState<3>;
} // namespace mpm
