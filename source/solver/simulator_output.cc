// What a run writes: the output folder with the statistics file, the
// particle and grid files at the output times, the test summary, and the
// lines on the screen (header, progress, the closing summary).

#include <deal.II/base/utilities.h>

#include <mpm/io/atomic_files.h>
#include <mpm/io/disk_space.h>
#include <mpm/solver/simulator.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/wall_clock.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace mpm
{
  using namespace dealii;

  namespace
  {
    std::string
    scheme_name(const Parameters::TimeStepping::Scheme s)
    {
      using S = Parameters::TimeStepping::Scheme;
      return s == S::usf ? "USF" : s == S::usl ? "USL" : "MUSL";
    }

    /// RssAnon and RssFile of this process in kB from /proc/self/status
    /// (zeros where that file does not exist).
    std::pair<double, double>
    resident_anonymous_and_file_kb()
    {
      std::ifstream in("/proc/self/status");
      std::string   line;
      double        anon = 0, file = 0;
      while (std::getline(in, line))
        {
          std::istringstream words(line);
          std::string        key;
          double             kb = 0;
          words >> key >> kb;
          if (key == "RssAnon:")
            anon = kb;
          else if (key == "RssFile:")
            file = kb;
        }
      return {anon, file};
    }
  } // namespace

  template <int dim>
  void
  Simulator<dim>::open_output()
  {
    const auto &out = params.output;
    // Only now, with the input checked, touch the output folder (rank 0;
    // every rank learns whether that worked).
    on_root<InputError>(comm,
                        "Output/Directory = '" + out.directory +
                          "' cannot be created: ",
                        [&]() {
                          std::filesystem::create_directories(out.directory);
                        });
    writer          = std::make_unique<OutputWriter<dim>>(comm,
                                                 out.directory,
                                                 state.layout,
                                                 history_names);
    statistics_file = std::make_unique<StatisticsFile<dim>>();
    // A folder that exists but cannot take the files (a full disk) is a
    // failed write like any later one: status 2, the free space named.
    on_root<RuntimeError>(
      comm,
      "while opening the output: " +
        cannot_write("the statistics and parameter files", out.directory),
      [&]() {
        // A restart continues the statistics file of the checkpoint: the
        // rows written after it (by the interrupted run) are dropped.
        if (resumed())
          statistics_file->resume(out.directory + "/statistics.txt",
                                  checkpoint::read_file(resume_folder +
                                                        "/statistics.txt"));
        else
          {
            // the integrator's columns (its solver's iterations), then the
            // benchmark's measures
            auto columns = integrator->statistics_columns();
            if (!inflows.empty())
              columns.push_back("injected_mass");
            if (benchmark)
              for (const auto &c : benchmark->columns())
                columns.push_back(c);
            statistics_file->open(out.directory + "/statistics.txt", columns);
          }
        // Every entry of this run (defaults included, no comments), so
        // that scripts/recompute_measures.py finds the benchmark, its
        // constants and the grid beside the output.
        const std::string parameters = out.directory + "/parameters.prm";
        try
          {
            prm.print_parameters(parameters, ParameterHandler::ShortPRM);
          }
        catch (const std::exception &)
          {
            // deal.II's text here is a generic list of I/O causes
            throw std::runtime_error("'" + parameters +
                                     "' could not be written");
          }
      });

    if (resumed())
      {
        // The outputs up to the checkpoint are on disk already; the
        // ParaView series are rewritten without those of the interrupted
        // run after it.
        const auto &s    = resume_state;
        next_output_time = s.next_output_time;
        last_output_step = s.last_output_step;
        summary_rows     = s.summary_rows;
        writer->restore(s.n_outputs, s.particle_records, s.grid_records);
        on_root<RuntimeError>(comm, "", [&]() { writer->write_series(); });
      }
    else
      {
        // The first output has no grid fields yet: fill them from the
        // state.
        integrator->compute_nodal_fields();
        write_output();
        next_output_time = out.interval;
      }
  }

  template <int dim>
  bool
  Simulator<dim>::output_due()
  {
    const double end   = params.time.end_time;
    const double tiny  = 1e-12 * std::max(end, 1e-300);
    const double t     = state.current_time;
    const double dt    = state.last_dt;
    const auto  &every = params.output.interval;
    if (!(t >= next_output_time - 1e-9 * dt || t >= end - tiny))
      return false;
    // next multiple of the interval (Interval = 0: every step)
    next_output_time =
      every > 0 ? every * (std::floor(t / every + 1e-9) + 1) : t;
    return true;
  }

  template <int dim>
  void
  Simulator<dim>::write_output()
  {
    // The stress the next force will be computed from (the filter is a
    // projection: applying it here changes nothing else).
    filter_stress();
    TimerOutput::Scope t(timer, "output");
    state.particle_handler.update_cached_numbers();
    const auto &out   = params.output;
    const auto  stats = statistics();
    const auto  extra = benchmark_values();
    last_output_step  = state.current_step;

    // Each writer has collective parts; a failure on one rank (a full
    // disk, say) is collected and reported on all ranks afterwards, so no
    // rank waits for another that has given up.
    FirstProblem problem;
    auto         attempt = [&](const std::string &what, const auto &write) {
      const std::string p = problem_of(write);
      if (!p.empty())
        problem.record(cannot_write(what, out.directory) +
                       clean_dealii_message(p));
    };
    attempt("statistics.txt", [&]() {
      auto values = integrator->statistics_values();
      if (!inflows.empty())
        values.push_back(injected_mass());
      values.insert(values.end(), extra.begin(), extra.end());
      statistics_file->write_row(
        state.current_time, state.current_step, state.last_dt, stats, values);
    });
    if (out.write_vtu)
      {
        attempt("the particle vtu files", [&]() {
          writer->write_particles_vtu(state.particle_handler,
                                      state.current_time);
        });
        if (out.write_grid)
          attempt("the grid vtu files", [&]() {
            writer->write_grid_vtu(state.background,
                                   state.p2g,
                                   state.kinematics,
                                   state.contact ? &state.contact->forces() :
                                                   nullptr,
                                   state.current_time);
          });
      }
    if (out.write_csv)
      attempt("the particle csv file", [&]() {
        writer->write_particles_csv(state.particle_handler, state.current_time);
      });
    if (out.write_csv && state.contact)
      attempt("the contact csv file",
              [&]() { writer->write_contact_csv(state.contact->forces()); });
    writer->advance();
    throw_if_any<RuntimeError>(comm,
                               "while writing output at step " +
                                 std::to_string(state.current_step) + ": ",
                               problem.text());

    if (!out.test_summary.empty())
      {
        // Few digits, scaled quantities: stable across ranks and compilers.
        std::ostringstream s;
        s << std::scientific << std::setprecision(6) << "t "
          << state.current_time << " step " << state.current_step << " n "
          << stats.n_particles << " mass " << stats.mass << " removed "
          << stats.removed_mass;
        if (!inflows.empty())
          s << " injected " << injected_mass();
        s << " Ekin " << stats.kinetic_energy << " Estrain "
          << stats.strain_energy;
        for (unsigned int d = 0; d < dim; ++d)
          s << " p" << d << ' ' << stats.momentum[d];
        if (dim >= 2)
          s << " Lz " << stats.angular_momentum[2];
        for (const double e : extra)
          s << " b " << e;
        summary_rows.push_back(s.str());
      }

    // The row just written shows it; the run stops here rather than going
    // on with an overflowed state.
    const bool kinetic_finite = std::isfinite(stats.kinetic_energy);
    if (!kinetic_finite || !std::isfinite(stats.strain_energy))
      {
        std::ostringstream s;
        s << "at step " << state.current_step << " (t = " << state.current_time
          << "): the total " << (kinetic_finite ? "strain" : "kinetic")
          << " energy is "
          << (kinetic_finite ? stats.strain_energy : stats.kinetic_energy)
          << ", so a velocity or a stress has overflowed"
          << limiting_particle_text();
        throw RuntimeError(s.str());
      }
    energy_watch->check(stats,
                        state.current_step,
                        state.current_time,
                        Utilities::MPI::this_mpi_process(comm) == 0 ?
                          &std::cerr :
                          nullptr);
  }

  template <int dim>
  void
  Simulator<dim>::write_test_summary()
  {
    // Written by rank 0; a failure stops every rank (collective check).
    on_root<RuntimeError>(
      comm, "while writing Output/Test summary file: ", [&]() {
        std::ostringstream s;
        for (const auto &r : summary_rows)
          s << r << '\n';
        write_file_atomically(params.output.test_summary, s.str());
      });
  }

  template <int dim>
  void
  Simulator<dim>::print_header()
  {
    const auto &p = params;
    pcout << "mpm: " << p.file_name << '\n'
          << "  dimension " << dim << " (" << to_string(p.kinematics) << "), "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)\n"
          << "  grid: " << state.background.n_global_cells() << " cells, "
          << state.background.n_global_nodes() << " nodes"
          << (state.background.is_cartesian() ? " (Cartesian)" :
                                                " (general Q1)")
          << '\n';
    for (const auto &b : state.bodies)
      {
        pcout << "  body " << b.index << ": " << b.material->name()
              << ", rho0 = " << b.material->reference_density();
        if (b.prm.geometry != Parameters::Body<dim>::Geometry::none)
          pcout << ", " << b.prm.particles_per_direction << "^" << dim
                << " particles per body cell";
        pcout << '\n';
      }
    for (const auto &in : inflows)
      pcout << "  inflow of body " << in.body() << ": " << in.n_per_layer()
            << " particles per layer, " << in.n_layers() << " layers ("
            << in.n_particles() << " particles, "
            << in.n_particles() * in.particle_volume()
            << " of volume) by the end time\n";
    pcout << "  particles: " << state.particle_handler.n_global_particles()
          << '\n'
          << "  integrator " << integrator->name();
    if (p.time.integrator ==
        Parameters::TimeStepping::Integrator::explicit_dynamics)
      pcout << ", scheme " << scheme_name(p.time.scheme) << ", FLIP fraction "
            << p.time.flip_fraction << ", end time " << p.time.end_time << '\n'
            << "  time step: "
            << (p.time.step_control ==
                    Parameters::TimeStepping::StepControl::fixed ?
                  "fixed " + Utilities::to_string(p.time.time_step) :
                  "CFL " + Utilities::to_string(p.time.cfl_number))
            << " (stability limit now " << stable_time_step() << ")\n";
    else if (p.time.integrator == Parameters::TimeStepping::Integrator::newmark)
      pcout << " (beta " << p.time.newmark_beta << ", gamma "
            << p.time.newmark_gamma << "), end time " << p.time.end_time << '\n'
            << "  time step: fixed " << p.time.time_step << '\n';
    else
      pcout << ", end time " << p.time.end_time << '\n'
            << "  load step: " << p.time.time_step << '\n';
    pcout << "  output: " << p.output.directory << "/ every "
          << p.output.interval << " s; energy balance ";
    if (energy_watch->not_watched().empty())
      pcout << "watched (tolerance " << p.output.energy_tolerance << ")"
            << std::endl;
    else
      pcout << "not watched: " << energy_watch->not_watched() << std::endl;
    if (resumed())
      pcout << "  resumed from the checkpoint " << resume_folder << " at step "
            << state.current_step << ", t = " << state.current_time
            << std::endl;
    if (state.balancer)
      pcout << "  load balancing: "
            << (p.load_balancing.at_setup ? "at set-up" : "not at set-up")
            << (p.load_balancing.interval > 0 ?
                  ", every " + std::to_string(p.load_balancing.interval) +
                    " steps" :
                  std::string())
            << "; cell weight " << p.load_balancing.cell_weight
            << ", particle weight " << p.load_balancing.particle_weight
            << "; particles per rank at set-up " << setup_balance[0].min << "-"
            << setup_balance[0].max << " -> " << setup_balance[1].min << "-"
            << setup_balance[1].max << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::print_progress(const bool force)
  {
    const double now = wall_seconds();
    if (!force && now - last_progress < params.output.progress_interval)
      return;
    last_progress = now;
    const double done =
      params.time.end_time > 0 ? state.current_time / params.time.end_time : 1.;
    const double       elapsed = now - wall_start;
    std::ostringstream s;
    s << "  step " << std::setw(8) << state.current_step
      << "  t = " << std::setw(11) << std::setprecision(5) << state.current_time
      << "  dt = " << std::setw(11) << state.last_dt << "  " << std::fixed
      << std::setprecision(1) << std::setw(5) << 100 * done << "%  elapsed "
      << elapsed << " s";
    if (done > 0 && done < 1)
      s << "  left ~" << elapsed * (1 - done) / done << " s";
    pcout << s.str() << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::print_summary(const double       loop_seconds,
                                const unsigned int n_steps)
  {
    const double updates =
      double(state.particle_handler.n_global_particles()) * n_steps;
    pcout << "  time loop: " << loop_seconds << " s wall (without output) for "
          << n_steps
          << " steps = " << updates / std::max(loop_seconds, 1e-300) / 1e6
          << " M particle-updates/s" << std::endl;
    if (state.stress_filter->any())
      pcout << "  stress filter: "
            << Utilities::MPI::sum(state.stress_filter->n_fallbacks, comm)
            << " cell projections fell back to constant stress" << std::endl;
    if (state.balancer)
      {
        const auto b = LoadBalancer<dim>::balance(state.particle_handler, comm);
        pcout << "  load balancing: " << state.balancer->n_repartitions
              << " repartitions; particles per rank now " << b.min << "-"
              << b.max << " (largest / mean " << b.imbalance() << ")"
              << std::endl;
      }
    print_memory();
    timer.print_summary();
  }

  template <int dim>
  void
  Simulator<dim>::print_memory()
  {
    Utilities::System::MemoryStats m;
    Utilities::System::get_memory_stats(m);
    const double peak = Utilities::MPI::sum(double(m.VmHWM) * 1024., comm);
    const double n =
      std::max<double>(1, state.particle_handler.n_global_particles());
    const double grid = Utilities::MPI::sum(
      double(state.background.triangulation().memory_consumption() +
             state.background.dof_handler().memory_consumption()),
      comm);
    pcout << "  memory: peak " << peak / 1048576.
          << " MB over all ranks = " << peak / n / 1024.
          << " KB per particle (triangulation and nodes " << grid / 1048576.
          << " MB)" << std::endl;
    // The peak counts the shared libraries in every process, though
    // their pages are files shared by the ranks: what the run allocates
    // is the anonymous part (Linux only).
    const auto [anon, file] = resident_anonymous_and_file_kb();
    if (Utilities::MPI::min(anon > 0 ? 1 : 0, comm) == 1)
      {
        const double all = Utilities::MPI::sum(anon * 1024., comm);
        pcout << "  memory: at the end " << all / 1048576.
              << " MB allocated over all ranks = " << all / n / 1024.
              << " KB per particle, plus " << file / 1024.
              << " MB of mapped files (shared libraries) on rank 0"
              << std::endl;
      }
  }

#define MPM_INSTANTIATE(d)                                         \
  template void Simulator<d>::open_output();                       \
  template bool Simulator<d>::output_due();                        \
  template void Simulator<d>::write_output();                      \
  template void Simulator<d>::write_test_summary();                \
  template void Simulator<d>::print_header();                      \
  template void Simulator<d>::print_progress(bool);                \
  template void Simulator<d>::print_summary(double, unsigned int); \
  template void Simulator<d>::print_memory();
  MPM_INSTANTIATE(1)
  MPM_INSTANTIATE(2)
  MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
} // namespace mpm
