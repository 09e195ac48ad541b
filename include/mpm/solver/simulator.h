#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm/benchmarks/benchmark.h>
#include <mpm/filters/convection_correction.h>
#include <mpm/filters/stress_filter.h>
#include <mpm/grid/background_grid.h>
#include <mpm/grid/load_balancer.h>
#include <mpm/io/checkpoint.h>
#include <mpm/io/output_writer.h>
#include <mpm/io/statistics.h>
#include <mpm/parameters/parameters.h>
#include <mpm/particles/body.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/transfer/particle_to_grid.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * The explicit MPM solver. setup() builds everything from the parameters
   * and checks it (every problem is an InputError, raised before anything
   * is written); run() advances in time and writes results.
   *
   * One step (do_time_step) reads as the algorithm:
   *   P2G -> grid update -> G2P -> [MUSL re-map] -> stress update ->
   *   position update (sorting particles into cells),
   * with the stress update before the force computation for USF.
   */
  template <int dim>
  class Simulator
  {
  public:
    Simulator(const Parameters::AllParameters<dim> &parameters,
              dealii::ParameterHandler             &prm,
              const MPI_Comm                        comm);

    /// Build grid, bodies and particles; check stability. Collective.
    void
    setup();

    /// The time loop with output. Collective.
    void
    run();

    /// Advance by one step of length dt (the phases below).
    void
    do_time_step(const double dt);

    double
    time() const
    {
      return current_time;
    }
    unsigned int
    step() const
    {
      return current_step;
    }
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

    /// Benchmark error columns of the current state (empty if none).
    std::vector<double>
    benchmark_values();

    /// Steps in which the project's particle relocation could not place
    /// every particle and deal.II's global sort ran instead.
    unsigned int
    n_global_sorts_used() const
    {
      return n_global_sorts;
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
      return balancer.get();
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
      return particle_handler;
    }
    const BackgroundGrid<dim> &
    grid() const
    {
      return background;
    }
    const std::vector<Body<dim>> &
    get_bodies() const
    {
      return bodies;
    }
    /// The particle-domain family's weights (null for standard MPM).
    const shape_functions::DomainShapeFunctions<dim> *
    domain_shape_functions() const
    {
      return domain_functions.get();
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
    // The phases of one step.
    void
    particle_to_grid(const transfer::P2GContent content);
    void
    update_grid(const double dt);
    void
    grid_to_particle(const double dt);
    /// Particles, grid and shape functions, for the transfers.
    transfer::TransferContext<dim>
    transfer_context();
    void
    remap_momentum();
    void
    update_stress(const double dt);
    void
    update_positions();

    // Set-up pieces.
    void
    create_bodies();
    /// The nodal vectors of the current partition (set-up, repartition).
    void
    initialize_nodal_vectors();
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
    /// The family's layout needs and its checks against grid and remedies.
    void
    check_shape_functions();
    void
    initial_properties(const Body<dim>         &body,
                       const ParticleSeed<dim> &seed,
                       const double             rho,
                       std::vector<double>     &properties) const;

    // Output pieces.
    void
    write_output();
    void
    print_header();
    void
    print_progress(const bool force);
    void
    print_memory();

    /// Throw the same RuntimeError on every rank if any rank found one.
    void
    check_errors();

    /// Collective: if any rank has a problem, throw Error(prefix + the
    /// first rank's message) on every rank.
    template <typename Error>
    void
    throw_if_any(const std::string &prefix, const std::string &local_problem);

    const Parameters::AllParameters<dim> &params;
    dealii::ParameterHandler             &prm;
    MPI_Comm                              comm;
    dealii::ConditionalOStream            pcout;
    dealii::TimerOutput                   timer;
    std::string                           input_folder;

    BackgroundGrid<dim>                         background;
    dealii::Particles::ParticleHandler<dim>     particle_handler;
    ParticleLayout<dim>                         layout;
    std::vector<Body<dim>>                      bodies;
    std::vector<std::string>                    history_names;
    std::unique_ptr<benchmarks::Benchmark<dim>> benchmark;

    NodalVector p2g, kinematics, remap;
    NodalVector volume_sums; ///< node-based volumetric smoothing only
    std::unique_ptr<LoadBalancer<dim>> balancer;
    std::array<ParticleBalance, 2>     setup_balance;
    double                             min_nodal_mass = 0;

    double       current_time = 0;
    unsigned int current_step = 0;
    double       last_dt      = 0;
    double       stable_dt    = 0; ///< from the last stress update (local)
    double       removed_mass = 0; ///< local
    std::string  local_error;      ///< first problem found on this rank
    std::vector<std::string> lost_messages;

    std::unique_ptr<OutputWriter<dim>>   writer;
    std::unique_ptr<StatisticsFile<dim>> statistics_file;
    std::vector<std::string>             summary_rows;
    double                               next_output_time = 0;
    unsigned int last_output_step = dealii::numbers::invalid_unsigned_int;
    unsigned int n_global_sorts   = 0;
    std::unique_ptr<filters::StressFilter<dim>> stress_filter;
    /// The particle-domain family's weights (null for standard MPM).
    std::unique_ptr<shape_functions::DomainShapeFunctions<dim>>
      domain_functions;
    /// The 1D convection correction, around the P2G passes with forces.
    filters::ConvectionCorrection<dim> convection_correction;
    bool                               any_convection_correction = false;
    double                             wall_start = 0, last_progress = 0;

    /// Hash of the coarse mesh, stored in checkpoints.
    std::string grid_fingerprint;
    /// The checkpoint this run continues from ("" for a fresh start), and
    /// its solver state.
    std::string             resume_folder;
    checkpoint::SolverState resume_state;
    double                  last_checkpoint_wall  = 0;
    unsigned int            n_checkpoints_written = 0;
  };

  template <int dim>
  template <typename Error>
  void
  Simulator<dim>::throw_if_any(const std::string &prefix,
                               const std::string &local_problem)
  {
    const unsigned int rank   = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int nranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int first =
      dealii::Utilities::MPI::min(local_problem.empty() ? nranks : rank, comm);
    if (first < nranks)
      throw Error(
        prefix + dealii::Utilities::MPI::broadcast(comm, local_problem, first));
  }
} // namespace mpm
