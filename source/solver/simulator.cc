// The Simulator's wiring: set-up from the parameters or a checkpoint, the
// time loop, and the per-step bookkeeping around the integrator's step.

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <mpm/shape_functions/family_registry.h>
#include <mpm/solver/simulator.h>
#include <mpm/solver/stress_update.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/wall_clock.h>

#include <filesystem>
#include <limits>
#include <sstream>

namespace mpm
{
  using namespace dealii;

  template <int dim>
  Simulator<dim>::Simulator(const Parameters::AllParameters<dim> &parameters,
                            ParameterHandler                     &prm,
                            const MPI_Comm                        comm)
    : params(parameters)
    , prm(prm)
    , comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
    , input_folder(
        std::filesystem::path(parameters.file_name).parent_path().string())
    , state(parameters, comm, pcout, timer)
  {}

  template <int dim>
  Simulator<dim>::~Simulator() = default;

  template <int dim>
  void
  Simulator<dim>::setup()
  {
    TimerOutput::Scope t(timer, "setup");
    const std::string  folder = find_checkpoint();
    if (!folder.empty())
      resume_from(folder);
    else
      {
        state.background.create(params.grid, input_folder);
        grid_fingerprint =
          checkpoint::coarse_mesh_fingerprint(state.background.triangulation());
        state.background.setup(params.boundary);
      }
    // 1D grids are not distributed; on one rank a repartition is void.
    const bool shared_grid =
      dim > 1 && Utilities::MPI::n_mpi_processes(comm) > 1;
    if (params.load_balancing.interval > 0 ||
        (params.load_balancing.at_setup && shared_grid))
      state.balancer =
        std::make_unique<LoadBalancer<dim>>(params.load_balancing,
                                            state.background,
                                            state.particle_handler);
    const bool balance_now = state.balancer && params.load_balancing.at_setup;
    if (folder.empty())
      create_initial_state(balance_now);
    else
      {
        setup_balance[0] =
          LoadBalancer<dim>::balance(state.particle_handler, comm);
        if (balance_now && state.balancer->unbalanced())
          state.balancer->repartition(params.boundary);
      }
    setup_balance[1] = LoadBalancer<dim>::balance(state.particle_handler, comm);
    create_inflows();
    state.stress_filter =
      std::make_unique<remedies::StressFilter<dim>>(state.bodies);
    state.force_pass_hooks = remedies::create_force_pass_hooks(state.bodies);
    if (params.contact.enabled())
      state.contact =
        std::make_unique<contact::MultiFieldContact<dim>>(params.contact,
                                                          state.bodies);
    if (shape_functions::family_traits(params.shape_functions.family)
          .has_domains)
      state.domain_functions =
        std::make_unique<shape_functions::DomainShapeFunctions<dim>>(
          state.background,
          params.shape_functions.family,
          params.shape_functions.clamp,
          state.layout.corners(),
          params.shape_functions.cache_stencils);
    state.initialize_nodal_vectors();
    benchmark =
      benchmarks::create_benchmark<dim>(params.benchmark, params.constants);
    integrator = create_time_integrator(state);
    energy_watch =
      std::make_unique<EnergyWatch<dim>>(params.output, state.bodies);
    if (resumed())
      {
        // The state the checkpoint was written in: the fixed step was
        // checked against the initial state when the run started.
        state.min_nodal_mass = resume_state.min_nodal_mass;
        state.stable_dt      = resume_state.stable_dt;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          state.stress_filter->n_fallbacks = resume_state.n_filter_fallbacks;
        return;
      }
    // Nodes lighter than this carry no velocity (a relative threshold:
    // far below any real nodal mass, far above round-off); a run that
    // starts empty takes it from the particles its inlets will create.
    inject_particles();
    const auto s = statistics();
    double     m = s.mass / std::max<double>(1, s.n_particles);
    for (const auto &in : inflows)
      if (s.n_particles == 0)
        m = std::max(m,
                     in.particle_volume() *
                       state.bodies[in.body()].material->reference_density());
    state.min_nodal_mass = 1e-12 * m;
    // The inlets' particles bound the step before they exist; the
    // integrator's checks of the first step see that bound.
    state.stable_dt = std::numeric_limits<double>::max();
    bound_step_by_inflows();
    integrator->initialize();
  }

  template <int dim>
  void
  Simulator<dim>::run()
  {
    print_header();
    open_output();
    wall_start = last_progress = wall_seconds();
    last_checkpoint_wall       = wall_start;
    double output_seconds      = 0;
    // Output and checkpoints do not count in the loop's throughput.
    auto untimed = [&](const auto &write) {
      const double before = wall_seconds();
      write();
      output_seconds += wall_seconds() - before;
    };
    const unsigned int first_step = state.current_step;
    const double       end        = params.time.end_time;
    const double       tiny       = 1e-12 * std::max(end, 1e-300);
    const unsigned int max_steps  = params.time.max_steps;
    while (state.current_time < end - tiny &&
           (max_steps == 0 || state.current_step < max_steps))
      {
        double dt = integrator->next_step_length();
        if (state.current_time + dt > end - tiny)
          dt = end - state.current_time;
        check_time_step(dt);
        do_time_step(dt);
        if (output_due())
          untimed([&]() { write_output(); });
        if (checkpoint_due())
          untimed([&]() { write_checkpoint(); });
        print_progress(false);
      }
    // Throughput of the time loop without output: the slowest rank counts.
    const double loop_seconds =
      Utilities::MPI::max(wall_seconds() - wall_start - output_seconds, comm);
    if (last_output_step != state.current_step)
      write_output(); // stopped by the step limit
    print_progress(true);
    if (!params.output.test_summary.empty())
      write_test_summary();
    print_summary(loop_seconds, state.current_step - first_step);
  }

  template <int dim>
  void
  Simulator<dim>::do_time_step(const double dt)
  {
    state.last_dt = dt;
    // (whatever changed the particles between steps, the step's first
    // loop checks their cells)
    state.background.particles_changed_cells();
    if (state.balancer && state.balancer->due(state.current_step))
      repartition();
    integrator->advance(dt);
    state.current_time += dt;
    ++state.current_step;
    // the state at time t holds every inflow layer that has entered by t
    inject_particles();
    bound_step_by_inflows();
    check_errors();
  }

  template <int dim>
  void
  Simulator<dim>::repartition()
  {
    AssertThrow(state.balancer, ExcMessage("Load balancing is off"));
    TimerOutput::Scope t(timer, "repartition");
    // No nodal value lives from one step to the next, so the vectors are
    // only re-sized; the particles carry the whole state.
    state.balancer->repartition(params.boundary);
    state.initialize_nodal_vectors();
    inlet_locator.reset(); // the owned cells have changed
  }

  template <int dim>
  void
  Simulator<dim>::check_errors()
  {
    // One collective per step: the stable step and the first failing rank.
    const unsigned int rank     = Utilities::MPI::this_mpi_process(comm);
    const unsigned int nranks   = Utilities::MPI::n_mpi_processes(comm);
    double             local[2] = {state.stable_dt,
                                   double(state.local_error.empty() ? nranks : rank)};
    double             global[2];
    Utilities::MPI::min(ArrayView<const double>(local, 2),
                        comm,
                        ArrayView<double>(global, 2));
    state.stable_dt = global[0];
    if (global[1] < nranks)
      {
        const std::string msg =
          Utilities::MPI::broadcast(comm,
                                    state.local_error.text(),
                                    static_cast<unsigned int>(global[1]));
        std::ostringstream s;
        s << "at step " << state.current_step << " (t = " << state.current_time
          << "): " << msg;
        throw RuntimeError(s.str());
      }
  }

  template <int dim>
  void
  Simulator<dim>::check_time_step(const double dt)
  {
    using TimeStepping   = Parameters::TimeStepping;
    const double to_end  = params.time.end_time - state.current_time;
    const bool   advance = dt > 0 && std::isfinite(dt) &&
                         state.current_time + dt > state.current_time;
    if (advance && to_end / dt <= TimeStepping::max_steps_to_end)
      return;
    // The step cannot advance the run: say why, and which particle has the
    // smallest stability limit.
    std::ostringstream s;
    s << "at step " << state.current_step << " (t = " << state.current_time
      << "): the time step " << dt;
    if (!(dt > 0) || !std::isfinite(dt))
      s << " is not a positive number, so the run cannot advance";
    else if (!advance)
      s << " does not change the time in double precision (t + dt = t), so "
           "the run cannot advance";
    else
      s << " would need " << to_end / dt
        << " steps (more than 2^53), so the run cannot reach End time";
    s << limiting_particle_text();
    throw RuntimeError(s.str());
  }

  template <int dim>
  std::string
  Simulator<dim>::limiting_particle_text()
  {
    // all ranks: the smallest h/(c + |v|) wins
    auto [limit, which] =
      limiting_particle(state.background, state.particle_handler, state.bodies);
    struct
    {
      double value;
      int    rank;
    } local{limit, int(Utilities::MPI::this_mpi_process(comm))}, global;
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
    which = Utilities::MPI::broadcast(comm, which, global.rank);
    return which.empty() ? std::string() :
                           ". The smallest stability limit h/(c + |v|) is "
                           "that of " +
                             which;
  }

  template <int dim>
  double
  Simulator<dim>::stable_time_step()
  {
    return Utilities::MPI::min(state.stable_dt, comm);
  }

  template <int dim>
  GlobalStatistics<dim>
  Simulator<dim>::statistics()
  {
    GlobalStatistics<dim> s;
    s.compute(state.particle_handler, state.bodies, comm);
    s.removed_mass = Utilities::MPI::sum(state.removed_mass, comm);
    return s;
  }

  template <int dim>
  std::vector<double>
  Simulator<dim>::benchmark_values()
  {
    if (!benchmark)
      return {};
    return benchmark->measure_with_contact(state.particle_handler,
                                           state.current_time,
                                           comm,
                                           contact_forces());
  }

  template <int dim>
  const contact::NodalContactForces<dim> &
  Simulator<dim>::contact_forces() const
  {
    static const contact::NodalContactForces<dim> none;
    return state.contact ? state.contact->forces() : none;
  }

  template <int dim>
  std::vector<double>
  Simulator<dim>::integrator_values() const
  {
    return integrator->statistics_values();
  }

  template <int dim>
  std::vector<std::string>
  Simulator<dim>::integrator_columns() const
  {
    return integrator->statistics_columns();
  }

  template <int dim>
  void
  Simulator<dim>::filter_stress()
  {
    if (!state.stress_filter->any())
      return;
    TimerOutput::Scope t(timer, "stress filter");
    state.stress_filter->apply(state.background, state.particle_handler);
  }

  template class Simulator<1>;
  template class Simulator<2>;
  template class Simulator<3>;
} // namespace mpm
