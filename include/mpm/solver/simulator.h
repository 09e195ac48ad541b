#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm/benchmarks/benchmark.h>
#include <mpm/integrators/time_integrator.h>
#include <mpm/io/checkpoint.h>
#include <mpm/io/output_writer.h>
#include <mpm/io/statistics.h>
#include <mpm/particles/inflow.h>
#include <mpm/solver/energy_watch.h>
#include <mpm/solver/simulation_state.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * A run: setup() builds the state from the parameters (or a checkpoint)
   * and checks it (every problem is an InputError, raised before anything
   * is written); run() is the time loop, in which a TimeIntegrator
   * advances the state and the Simulator writes output and checkpoints.
   * Its parts live in their own files:
   *   simulator.cc          wiring, set-up, the loop;
   *   initial_state.cc      bodies and their particles;
   *   simulator_output.cc   statistics, particle and grid files, screen;
   *   checkpoint_restart.cc checkpoints and resuming from them;
   * and the step itself in integrators/.
   */
  template <int dim>
  class Simulator
  {
  public:
    Simulator(const Parameters::AllParameters<dim> &parameters,
              dealii::ParameterHandler             &prm,
              const MPI_Comm                        comm);
    ~Simulator();

    /// Build grid, bodies and particles; check stability. Collective.
    void
    setup();

    /// The time loop with output. Collective.
    void
    run();

    /// Advance by one step of length dt: repartition if due, the
    /// integrator's step, the clock, the collective error check.
    void
    do_time_step(const double dt);

    double
    time() const
    {
      return state.current_time;
    }
    unsigned int
    step() const
    {
      return state.current_step;
    }
    /// A step that is not a positive number, or does not change the
    /// time, stops the run (RuntimeError naming the particle with the
    /// smallest stability limit). Collective.
    void
    check_time_step(const double dt);

    /// ". The smallest stability limit h/(c + |v|) is that of particle
    /// ..." (the particle over all ranks), or empty. Collective.
    std::string
    limiting_particle_text();

    /// Stable step of the current state (collective min).
    double
    stable_time_step();

    /// Global sums of the current state. Collective.
    GlobalStatistics<dim>
    statistics();

    /// Apply the assumed-stress filter of the filtered bodies to the
    /// current state: the stress the next force will be computed from
    /// (output does this before writing). Collective-free.
    void
    filter_stress();

    /// The mass that the bodies' inflows have let in so far (the same on
    /// every rank).
    double
    injected_mass() const;

    /// Benchmark error columns of the current state (empty if none).
    std::vector<double>
    benchmark_values();

    /// The contact forces of the last step at this rank's nodes (empty
    /// without contact; MultiFieldContact::forces()).
    const contact::NodalContactForces<dim> &
    contact_forces() const;

    /// The integrator's statistics columns of the last step (an implicit
    /// step's iteration counts; empty for the explicit one), named by
    /// integrator_columns().
    std::vector<double>
    integrator_values() const;
    std::vector<std::string>
    integrator_columns() const;

    /// Steps in which the project's particle relocation could not place
    /// every particle and deal.II's global sort ran instead.
    unsigned int
    n_global_sorts_used() const
    {
      return state.n_global_sorts;
    }

    /// Repartition the grid by particle count now (Load balancing; a step
    /// does it by itself every `Repartition interval` steps) and rebuild
    /// what depends on the partition. Collective; needs the interval > 0.
    void
    repartition();

    /// The load balancer (null if `Repartition interval` is 0).
    const LoadBalancer<dim> *
    load_balancer() const
    {
      return state.balancer.get();
    }

    /// Particles per rank at set-up, before and after the first
    /// repartition (equal without load balancing).
    const std::array<ParticleBalance, 2> &
    balance_at_setup() const
    {
      return setup_balance;
    }

    dealii::Particles::ParticleHandler<dim> &
    particles()
    {
      return state.particle_handler;
    }
    const BackgroundGrid<dim> &
    grid() const
    {
      return state.background;
    }
    const std::vector<Body<dim>> &
    get_bodies() const
    {
      return state.bodies;
    }
    /// The particle-domain family's weights (null for standard MPM).
    const shape_functions::DomainShapeFunctions<dim> *
    domain_shape_functions() const
    {
      return state.domain_functions.get();
    }

    /// Whether setup() continued from a checkpoint.
    bool
    resumed() const
    {
      return !resume_folder.empty();
    }

    /// Write a checkpoint of the current state (doc/checkpointing.md).
    /// Collective.
    void
    write_checkpoint();

  private:
    // Initial state (initial_state.cc).
    void
    create_bodies();
    /// Per cell (active cell index), the particles the bodies will place
    /// in it if it is owned: the set-up balance's weights. Every rank
    /// walks every body; no communication.
    std::vector<unsigned int>
    count_planned_particles() const;
    /// The bodies' particles; @p planned from count_planned_particles()
    /// on the current partition sizes the storage.
    void
    create_particles(const std::vector<unsigned int> &planned);
    /// Attach the handler to the grid; count the particles that leave it.
    void
    initialize_particle_handler();
    /// The family's layout needs and its checks against grid and remedies.
    void
    check_shape_functions();
    void
    initial_properties(const Body<dim>         &body,
                       const ParticleSeed<dim> &seed,
                       const double             rho,
                       std::vector<double>     &properties) const;
    /// Repartition by the planned particle counts (before any particle
    /// exists) and create the particles.
    void
    create_initial_state(const bool balance_now);

    // Inflow (particle_injection.cc).
    /// The bodies' inlets, checked against the grid; the layers the
    /// current state already holds. Collective.
    void
    create_inflows();
    /// Add the layers that have crossed the inlets by the current time,
    /// each particle on the rank that owns its cell. Collective.
    void
    inject_particles();
    /// Bound the stable step by the entering particles' while an inlet
    /// is still to create some (they are not in the last stress update).
    void
    bound_step_by_inflows();

    // Checkpoint and restart (checkpoint_restart.cc).
    /// The checkpoint folder to resume from, or "" to start anew.
    std::string
    find_checkpoint();
    /// Grid, particles and solver state from the checkpoint in @p folder,
    /// after checking that the parameters have not changed.
    void
    resume_from(const std::string &folder);
    /// Whether a checkpoint is due after the step just taken. Collective.
    bool
    checkpoint_due();

    // Output (simulator_output.cc).
    /// The output folder, the statistics file and the parameters beside
    /// it; on a restart the series as the checkpoint left them.
    void
    open_output();
    /// Whether the step just taken ends at an output time; schedules the
    /// next one.
    bool
    output_due();
    void
    write_output();
    void
    write_test_summary();
    void
    print_header();
    void
    print_progress(const bool force);
    /// Throughput of the loop, filter fall-backs, balance, memory, timers.
    void
    print_summary(const double loop_seconds, const unsigned int n_steps);
    void
    print_memory();

    /// Throw the same RuntimeError on every rank if any rank found one.
    void
    check_errors();

    const Parameters::AllParameters<dim> &params;
    dealii::ParameterHandler             &prm;
    MPI_Comm                              comm;
    dealii::ConditionalOStream            pcout;
    dealii::TimerOutput                   timer;
    std::string                           input_folder;

    SimulationState<dim>                        state;
    std::unique_ptr<TimeIntegrator<dim>>        integrator;
    std::vector<std::string>                    history_names;
    std::unique_ptr<benchmarks::Benchmark<dim>> benchmark;
    std::unique_ptr<EnergyWatch<dim>>           energy_watch;
    std::array<ParticleBalance, 2>              setup_balance;

    std::vector<Inflow<dim>>        inflows;
    std::vector<unsigned long long> inflow_layers_done;
    /// Stable step of the particles entering at each inlet.
    std::vector<double> inflow_stable_dt;
    /// Owned cells of the current partition, for the entering particles.
    std::unique_ptr<typename BackgroundGrid<dim>::OwnedCellLocator>
      inlet_locator;

    std::unique_ptr<OutputWriter<dim>>   writer;
    std::unique_ptr<StatisticsFile<dim>> statistics_file;
    std::vector<std::string>             summary_rows;
    double                               next_output_time = 0;
    unsigned int last_output_step = dealii::numbers::invalid_unsigned_int;
    double       wall_start = 0, last_progress = 0;

    /// Hash of the coarse mesh, stored in checkpoints.
    std::string grid_fingerprint;
    /// The checkpoint this run continues from ("" for a fresh start), and
    /// its solver state.
    std::string             resume_folder;
    checkpoint::SolverState resume_state;
    double                  last_checkpoint_wall  = 0;
    unsigned int            n_checkpoints_written = 0;
  };
} // namespace mpm
