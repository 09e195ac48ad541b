// Checkpoint and restart of the Simulator (doc/checkpointing.md): what a
// checkpoint holds, how it is written so that an interrupted write never
// destroys the previous one, and what a restart checks before it trusts it.

#include <deal.II/base/utilities.h>
#include <deal.II/distributed/tria.h>

#include <mpm/io/checkpoint.h>
#include <mpm/io/disk_space.h>
#include <mpm/io/failed_write_abort.h>
#include <mpm/solver/simulator.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/wall_clock.h>

#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>

namespace mpm
{
  using namespace dealii;

  namespace
  {
    /**
     * A test hook (tests/checkpoint): with MPM_TEST_KILL_IN_CHECKPOINT=n in
     * the environment, every rank kills itself (SIGKILL, no clean-up)
     * during the n-th checkpoint this run writes, after the grid and the
     * particles are written and before the checkpoint is complete.
     */
    bool
    kill_requested(const unsigned int n_written_before)
    {
      const char *v = std::getenv("MPM_TEST_KILL_IN_CHECKPOINT");
      return v != nullptr && std::atoi(v) > 0 &&
             static_cast<unsigned int>(std::atoi(v)) == n_written_before + 1;
    }

    /// 1D (serial grid): the particles as a binary table, cell by cell in
    /// the handler's order, so that a restart inserts them in the same
    /// order (and sums over them in the same order).
    template <int dim>
    void
    write_particles_1d(const std::string                     &file_name,
                       const Particles::ParticleHandler<dim> &particles)
    {
      std::ofstream       out(file_name, std::ios::binary);
      const std::uint64_t n       = particles.n_locally_owned_particles();
      const std::uint32_t n_props = particles.n_properties_per_particle();
      out.write(reinterpret_cast<const char *>(&n), sizeof(n));
      out.write(reinterpret_cast<const char *>(&n_props), sizeof(n_props));
      for (const auto &p : particles)
        {
          const auto          cell     = p.get_surrounding_cell();
          const std::int32_t  where[2] = {cell->level(), cell->index()};
          const std::uint64_t id       = p.get_id();
          out.write(reinterpret_cast<const char *>(where), sizeof(where));
          out.write(reinterpret_cast<const char *>(&id), sizeof(id));
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double x[2] = {p.get_location()[d],
                                   p.get_reference_location()[d]};
              out.write(reinterpret_cast<const char *>(x), sizeof(x));
            }
          const auto props = p.get_properties();
          out.write(reinterpret_cast<const char *>(props.data()),
                    sizeof(double) * props.size());
        }
      if (!out)
        throw std::runtime_error("cannot write '" + file_name + "'");
    }

    template <int dim>
    void
    read_particles_1d(const std::string               &file_name,
                      const Triangulation<dim>        &tria,
                      Particles::ParticleHandler<dim> &particles)
    {
      std::ifstream in(file_name, std::ios::binary);
      std::uint64_t n       = 0;
      std::uint32_t n_props = 0;
      in.read(reinterpret_cast<char *>(&n), sizeof(n));
      in.read(reinterpret_cast<char *>(&n_props), sizeof(n_props));
      if (!in || n_props != particles.n_properties_per_particle())
        throw std::runtime_error("the checkpoint file '" + file_name +
                                 "' is damaged or of another layout");
      particles.reserve(n);
      std::vector<double> props(n_props);
      for (std::uint64_t i = 0; i < n; ++i)
        {
          std::int32_t  where[2];
          std::uint64_t id;
          Point<dim>    x, xi;
          in.read(reinterpret_cast<char *>(where), sizeof(where));
          in.read(reinterpret_cast<char *>(&id), sizeof(id));
          for (unsigned int d = 0; d < dim; ++d)
            {
              double v[2];
              in.read(reinterpret_cast<char *>(v), sizeof(v));
              x[d]  = v[0];
              xi[d] = v[1];
            }
          in.read(reinterpret_cast<char *>(props.data()),
                  sizeof(double) * n_props);
          if (!in || where[0] < 0 ||
              where[0] >= static_cast<int>(tria.n_levels()))
            throw std::runtime_error("the checkpoint file '" + file_name +
                                     "' is damaged");
          const typename Triangulation<dim>::active_cell_iterator cell(
            &tria, where[0], where[1]);
          particles.insert_particle(
            x, xi, id, cell, ArrayView<const double>(props));
        }
    }
  } // namespace

  template <int dim>
  std::string
  Simulator<dim>::find_checkpoint()
  {
    using Resume  = Parameters::Checkpointing::Resume;
    const auto &c = params.checkpointing;
    if (c.resume == Resume::no)
      return "";
    // Every file of the checkpoint is checked (size, CRC-32) before
    // anything is loaded: a damaged file would otherwise abort p4est or
    // resume silently from a wrong state.
    std::string folder, problem, notice;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          const auto &dir = params.output.directory;
          folder          = checkpoint::latest(dir);
          if (!folder.empty())
            problem = checkpoint::verify(folder);
          if (!problem.empty())
            {
              std::string usable;
              for (const auto &earlier : checkpoint::earlier_checkpoints(dir))
                if (checkpoint::verify(earlier).empty())
                  {
                    usable = earlier;
                    break;
                  }
              if (c.fall_back_to_previous && !usable.empty())
                {
                  notice = "  the latest checkpoint is damaged (" + problem +
                           "); resuming from the previous one, " + usable +
                           "\n";
                  folder = usable;
                  problem.clear();
                  // the damaged folder goes at the next commit, as any
                  // other but the previous latest
                  checkpoint::set_latest(dir, usable);
                }
              else
                problem +=
                  usable.empty() ?
                    " (and there is no earlier complete checkpoint)" :
                    " (set Checkpointing/Damaged checkpoint = use previous "
                    "to resume from the previous complete checkpoint, " +
                      usable + ")";
            }
        }
      catch (const std::exception &e)
        {
          problem = e.what();
        }
    throw_if_any<InputError>(
      comm, "Checkpointing/Resume computation: ", problem);
    pcout << notice;
    folder = Utilities::MPI::broadcast(comm, folder, 0);
    if (folder.empty() && c.resume == Resume::yes)
      throw InputError(
        "Checkpointing/Resume computation = true, but there is no "
        "checkpoint to resume from: '" +
        checkpoint::root(params.output.directory) +
        "/latest.txt' does not exist (set Resume computation = auto to "
        "start from the initial state when there is none)");
    return folder;
  }

  template <int dim>
  void
  Simulator<dim>::resume_from(const std::string &folder)
  {
    // 1. The parameters and the solver state, read on rank 0: a changed
    // parameter stops the run here, before anything is read or written.
    std::string problem, state_text;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          std::ostringstream now;
          prm.print_parameters(now, ParameterHandler::ShortPRM);
          problem =
            checkpoint::compare_parameters(checkpoint::read_file(
                                             folder + "/parameters.prm"),
                                           now.str(),
                                           folder + "/parameters.prm");
          if (problem.empty())
            state_text = checkpoint::read_file(folder + "/state.txt");
        }
      catch (const std::exception &e)
        {
          problem = std::string("Checkpointing/Resume computation: ") +
                    e.what() + " (the checkpoint is incomplete or damaged)";
        }
    throw_if_any<InputError>(comm, "", problem);
    state_text = Utilities::MPI::broadcast(comm, state_text, 0);
    try
      {
        std::istringstream in(state_text);
        resume_state.read(in, folder + "/state.txt");
      }
    catch (const std::exception &e)
      {
        throw InputError(std::string("Checkpointing/Resume computation: ") +
                         e.what());
      }
    const auto &s = resume_state;
    if (s.dimension != dim)
      throw InputError("the checkpoint '" + folder + "' is of dimension " +
                       std::to_string(s.dimension));

    // 2. The grid: the coarse mesh from the parameters (the same as the
    // checkpoint's, or a mesh file has changed), then the refinement and
    // the partition from the checkpoint.
    state.background.create(params.grid, input_folder, dim > 1);
    grid_fingerprint =
      checkpoint::coarse_mesh_fingerprint(state.background.triangulation());
    if (grid_fingerprint != s.grid_fingerprint)
      throw InputError(
        "the grid built from the parameter file (Grid/" +
        std::string(params.grid.type == Parameters::Grid<dim>::Type::mesh_file ?
                      "Mesh file = '" + params.grid.mesh_file + "'" :
                      "Subdivisions, Lower and Upper corner") +
        ") is not the grid of the checkpoint '" + folder +
        "': has the mesh file changed?");
    if constexpr (dim > 1)
      dynamic_cast<parallel::distributed::Triangulation<dim> &>(
        state.background.triangulation())
        .load(folder + "/triangulation");
    else
      {
        std::ifstream in(folder + "/triangulation.1d", std::ios::binary);
        if (!in)
          throw InputError("the checkpoint file '" + folder +
                           "/triangulation.1d' cannot be read");
        boost::archive::binary_iarchive archive(in);
        state.background.triangulation().load(archive, 0);
      }
    state.background.setup(params.boundary);
    create_bodies();
    check_shape_functions();
    if (state.layout.n_properties() != s.n_properties)
      throw InputError("the checkpoint '" + folder + "' has " +
                       std::to_string(s.n_properties) +
                       " properties per particle, this run needs " +
                       std::to_string(state.layout.n_properties()));

    // 3. The particles: attached to the cells of the p4est checkpoint (they
    // follow their cells to whichever rank owns them now), or the 1D
    // table.
    initialize_particle_handler();
    if constexpr (dim > 1)
      {
        std::ifstream in(folder + "/particle_handler.txt");
        if (!in)
          throw InputError("the checkpoint file '" + folder +
                           "/particle_handler.txt' cannot be read");
        boost::archive::text_iarchive archive(in);
        archive >> state.particle_handler;
        state.particle_handler.deserialize();
      }
    else
      try
        {
          read_particles_1d(folder + "/particles.1d",
                            state.background.triangulation(),
                            state.particle_handler);
        }
      catch (const std::exception &e)
        {
          throw InputError(e.what());
        }
    state.particle_handler.update_cached_numbers();
    state.background.particles_changed_cells();
    if (state.particle_handler.n_global_particles() != s.n_particles)
      throw InputError(
        "the checkpoint '" + folder + "' holds " +
        std::to_string(state.particle_handler.n_global_particles()) +
        " particles, its state.txt says " + std::to_string(s.n_particles));

    // 4. The solver state. The removed mass stays on the rank that counted
    // it when the number of ranks is the same (the same sum, bit for bit).
    state.current_time        = s.time;
    state.current_step        = s.step;
    state.last_dt             = s.last_dt;
    state.n_global_sorts      = s.n_global_sorts;
    const unsigned int rank   = Utilities::MPI::this_mpi_process(comm);
    const unsigned int nranks = Utilities::MPI::n_mpi_processes(comm);
    state.removed_mass        = 0;
    if (s.removed_mass.size() == nranks)
      state.removed_mass = s.removed_mass[rank];
    else if (rank == 0)
      for (const double m : s.removed_mass)
        state.removed_mass += m;
    resume_folder = folder;
  }

  template <int dim>
  bool
  Simulator<dim>::checkpoint_due()
  {
    const auto &c = params.checkpointing;
    if (c.steps_between > 0 && state.current_step % c.steps_between == 0)
      return true;
    if (c.wall_seconds > 0)
      {
        // rank 0's clock decides, so that every rank agrees
        int due = wall_seconds() - last_checkpoint_wall >= c.wall_seconds;
        due     = Utilities::MPI::broadcast(comm, due, 0);
        return due != 0;
      }
    return false;
  }

  template <int dim>
  void
  Simulator<dim>::write_checkpoint()
  {
    TimerOutput::Scope t(timer, "checkpoint");
    const double       start  = wall_seconds();
    const auto        &out    = params.output;
    const bool         root   = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string  prefix = "while writing the checkpoint of step " +
                               std::to_string(state.current_step) + ": ";

    // p4est aborts the process when a write fails: the checkpoint must
    // fit before it is begun. It takes about what the latest one took,
    // or what its particles and cells need.
    state.particle_handler.update_cached_numbers();
    const double particle_bytes = 8. *
                                  state.particle_handler.n_global_particles() *
                                  (state.layout.n_properties() + 2 * dim + 2);
    const double cell_bytes =
      64. * state.background.triangulation().n_global_active_cells();
    // What stays usable if this checkpoint fails (rank 0 knows).
    std::string keep;
    on_root<RuntimeError>(comm, prefix, [&]() {
      const std::string latest = checkpoint::latest(out.directory);
      if (latest.empty())
        keep = "No checkpoint was written; the output so far is kept.";
      else
        keep = "The latest checkpoint, " + latest +
               ", is intact: make room and continue with mpm --resume.";
      std::error_code no_file;
      const auto      statistics_size =
        std::filesystem::file_size(out.directory + "/statistics.txt", no_file);
      double needed = particle_bytes + cell_bytes + 16384. +
                      (no_file ? 0. : double(statistics_size));
      if (!latest.empty())
        needed = std::max<double>(needed, checkpoint::folder_size(latest));
      require_space(out.directory, 1.1 * needed, keep);
    });
    keep = Utilities::MPI::broadcast(comm, keep, 0);

    // A new folder; the latest complete checkpoint stays as it is.
    std::string folder, problem;
    on_root<RuntimeError>(comm, prefix, [&]() {
      folder = checkpoint::begin(out.directory, state.current_step);
    });
    folder = Utilities::MPI::broadcast(comm, folder, 0);

    // Grid and particles (collective in 2D/3D: p4est writes one file for
    // all ranks, the particles travel as data attached to the cells). A
    // disk can still fill during the write (another process, or no free
    // file entries): the failure names the folder and the free space.
    if constexpr (dim > 1)
      {
        try
          {
            state.particle_handler.prepare_for_serialization();
            // p4est aborts on a failed write of its own file.
            const FailedWriteAbort guard(
              "mpm: the simulation stopped " + prefix +
              cannot_write("the grid", folder, out.directory) +
              "p4est stopped on a failed write, from a full disk or a "
              "file system without free file entries. " +
              keep + "\nOutput written before this point is kept.\n");
            dynamic_cast<parallel::distributed::Triangulation<dim> &>(
              state.background.triangulation())
              .save(folder + "/triangulation");
          }
        catch (const std::exception &e)
          {
            problem =
              cannot_write("the grid and particles", folder, out.directory) +
              clean_dealii_message(e.what());
          }
      }
    else
      {
        try
          {
            std::ofstream out(folder + "/triangulation.1d", std::ios::binary);
            {
              boost::archive::binary_oarchive archive(out);
              state.background.triangulation().save(archive, 0);
            }
            if (!out)
              throw std::runtime_error("cannot write '" + folder +
                                       "/triangulation.1d'");
            write_particles_1d(folder + "/particles.1d",
                               state.particle_handler);
          }
        catch (const std::exception &e)
          {
            problem =
              cannot_write("the grid and particles", folder, out.directory) +
              e.what();
          }
      }

    if (kill_requested(n_checkpoints_written))
      {
        MPI_Barrier(comm);
        std::raise(SIGKILL);
      }

    // The solver state, the parameters and the statistics so far (rank 0).
    checkpoint::SolverState s;
    s.dimension          = dim;
    s.n_ranks            = Utilities::MPI::n_mpi_processes(comm);
    s.n_properties       = state.layout.n_properties();
    s.n_particles        = state.particle_handler.n_global_particles();
    s.time               = state.current_time;
    s.step               = state.current_step;
    s.last_dt            = state.last_dt;
    s.stable_dt          = state.stable_dt;
    s.min_nodal_mass     = state.min_nodal_mass;
    s.next_output_time   = next_output_time;
    s.last_output_step   = last_output_step;
    s.n_outputs          = writer->counter();
    s.n_global_sorts     = state.n_global_sorts;
    s.n_filter_fallbacks = Utilities::MPI::sum(
      static_cast<unsigned long long>(state.stress_filter->n_fallbacks), comm);
    s.grid_fingerprint = grid_fingerprint;
    s.removed_mass     = Utilities::MPI::gather(comm, state.removed_mass, 0);
    s.particle_records = writer->particle_series();
    s.grid_records     = writer->grid_series();
    s.summary_rows     = summary_rows;
    if (root && problem.empty())
      try
        {
          if constexpr (dim > 1)
            {
              const std::string file = folder + "/particle_handler.txt";
              std::ofstream     f(file);
              try
                {
                  boost::archive::text_oarchive archive(f);
                  archive << state.particle_handler;
                }
              catch (const std::exception &e)
                {
                  throw std::runtime_error("'" + file + "': " + e.what());
                }
              if (!f)
                throw std::runtime_error("cannot write '" + file + "'");
            }
          std::ostringstream state_text;
          s.write(state_text);
          write_file_atomically(folder + "/state.txt", state_text.str());
          std::ostringstream parameters;
          prm.print_parameters(parameters, ParameterHandler::ShortPRM);
          write_file_atomically(folder + "/parameters.prm", parameters.str());
          write_file_atomically(folder + "/statistics.txt",
                                checkpoint::read_file(out.directory +
                                                      "/statistics.txt"));
        }
      catch (const std::exception &e)
        {
          problem =
            cannot_write("the checkpoint files", folder, out.directory) +
            clean_dealii_message(e.what());
        }
    // Every rank has written its part when every rank gets here.
    if (!problem.empty())
      problem += (problem.back() == '.' ? " " : ". ") + keep;
    throw_if_any<RuntimeError>(comm, prefix, problem);

    // The commit: latest.txt now names the new folder; then the older
    // folders go.
    unsigned long long bytes = 0;
    on_root<RuntimeError>(comm,
                          prefix +
                            cannot_write("the manifest", folder, out.directory),
                          [&]() {
                            checkpoint::commit(out.directory, folder);
                            bytes = checkpoint::folder_size(folder);
                          });
    ++n_checkpoints_written;
    last_checkpoint_wall = wall_seconds();
    pcout << "  checkpoint: step " << state.current_step
          << ", t = " << state.current_time << " -> " << folder << " ("
          << bytes / 1048576. << " MB, "
          << Utilities::MPI::max(last_checkpoint_wall - start, comm) << " s)"
          << std::endl;
  }

#define MPM_INSTANTIATE(dim)                                             \
  template std::string Simulator<dim>::find_checkpoint();                \
  template void        Simulator<dim>::resume_from(const std::string &); \
  template bool        Simulator<dim>::checkpoint_due();                 \
  template void        Simulator<dim>::write_checkpoint();

  MPM_INSTANTIATE(1)
  MPM_INSTANTIATE(2)
  MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
} // namespace mpm
