#include <deal.II/base/utilities.h>

#include <mpm/filters/stress_filter.h>
#include <mpm/grid/grid_update.h>
#include <mpm/particles/particle_relocation.h>
#include <mpm/shape_functions/family_registry.h>
#include <mpm/solver/simulator.h>
#include <mpm/solver/stress_update.h>
#include <mpm/transfer/grid_to_particle.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <chrono>
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
    double
    wall_seconds()
    {
      using namespace std::chrono;
      return duration<double>(steady_clock::now().time_since_epoch()).count();
    }

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

    /// The particles of @p counts (per active cell index) in the owned cells.
    template <int dim>
    unsigned long long
    owned_total(const BackgroundGrid<dim>       &grid,
                const std::vector<unsigned int> &counts)
    {
      unsigned long long n = 0;
      for (const auto &cell : grid.owned_cells())
        n += counts[cell->active_cell_index()];
      return n;
    }

    /// Body cells whose particles are seeded and located together: bounds
    /// the seeds held at once (a few MB), whatever the body's size.
    constexpr unsigned int seed_chunk_cells = 16384;
  } // namespace

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
    , background(comm)
  {}

  // ----------------------------------------------------------------- set-up
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
        background.create(params.grid, input_folder);
        grid_fingerprint =
          checkpoint::coarse_mesh_fingerprint(background.triangulation());
        background.setup(params.boundary);
      }
    // 1D grids are not distributed; on one rank a repartition is void.
    const bool shared_grid =
      dim > 1 && Utilities::MPI::n_mpi_processes(comm) > 1;
    if (params.load_balancing.interval > 0 ||
        (params.load_balancing.at_setup && shared_grid))
      balancer = std::make_unique<LoadBalancer<dim>>(params.load_balancing,
                                                     background,
                                                     particle_handler);
    const bool balance_now = balancer && params.load_balancing.at_setup;
    if (folder.empty())
      {
        create_bodies();
        check_shape_functions();
        // Balance by the particles the bodies will place, before they
        // exist: no particle data travels.
        auto planned = count_planned_particles();
        setup_balance[0] =
          LoadBalancer<dim>::balance(owned_total(background, planned), comm);
        if (balance_now)
          {
            balancer->weigh_by(&planned);
            const bool repartition = balancer->unbalanced();
            if (repartition)
              balancer->repartition(params.boundary);
            balancer->weigh_by(nullptr);
            if (repartition)
              planned = count_planned_particles();
          }
        create_particles(planned);
      }
    else
      {
        setup_balance[0] = LoadBalancer<dim>::balance(particle_handler, comm);
        if (balance_now && balancer->unbalanced())
          balancer->repartition(params.boundary);
      }
    setup_balance[1] = LoadBalancer<dim>::balance(particle_handler, comm);
    stress_filter    = std::make_unique<filters::StressFilter<dim>>(bodies);
    if (shape_functions::family_traits(params.shape_functions.family)
          .has_domains)
      domain_functions =
        std::make_unique<shape_functions::DomainShapeFunctions<dim>>(
          background,
          params.shape_functions.family,
          params.shape_functions.clamp,
          layout.corners(),
          params.shape_functions.cache_stencils);
    initialize_nodal_vectors();
    benchmark =
      benchmarks::create_benchmark<dim>(params.benchmark, params.constants);
    if (resumed())
      {
        // The state the checkpoint was written in: the fixed step was
        // checked against the initial state when the run started.
        min_nodal_mass = resume_state.min_nodal_mass;
        stable_dt      = resume_state.stable_dt;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          stress_filter->n_fallbacks = resume_state.n_filter_fallbacks;
        return;
      }

    // Nodes lighter than this carry no velocity (a relative threshold:
    // far below any real nodal mass, far above round-off).
    const auto s   = statistics();
    min_nodal_mass = 1e-12 * s.mass / std::max<double>(1, s.n_particles);

    stable_dt = ::mpm::stable_time_step(background, particle_handler, bodies);
    stable_dt = stable_time_step(); // the first step needs the global value
    const double limit = stable_dt;
    if (params.time.step_control ==
          Parameters::TimeStepping::StepControl::fixed &&
        params.time.time_step > limit)
      {
        std::ostringstream msg;
        msg << "Time stepping/Time step = " << params.time.time_step
            << " exceeds the stability limit min_p h/(c_p + |v_p|) = " << limit
            << " of the initial state; choose at most that, or "
            << "Time step control = CFL";
        throw InputError(msg.str());
      }
    // Mass-proportional damping scales the grid velocity by (1 - c dt) in
    // a step: above c dt = 1 it reverses the motion every step, above 2 it
    // grows without bound.
    const double first_dt =
      params.time.step_control == Parameters::TimeStepping::StepControl::fixed ?
        params.time.time_step :
        params.time.cfl_number * limit;
    if (params.time.damping * first_dt > 1.)
      {
        std::ostringstream msg;
        msg << "Time stepping/Damping coefficient = " << params.time.damping
            << " times the first time step " << first_dt << " is "
            << params.time.damping * first_dt
            << " > 1: the damping would reverse the velocity within a step "
            << "(explicit damping needs c dt <= 1); choose at most "
            << 1. / first_dt << " or a smaller step";
        throw InputError(msg.str());
      }
  }

  template <int dim>
  void
  Simulator<dim>::initialize_nodal_vectors()
  {
    background.initialize_vector(p2g, transfer::P2GLayout<dim>::n_components);
    background.initialize_vector(kinematics,
                                 KinematicsLayout<dim>::n_components);
    background.initialize_vector(remap, dim);
    for (const auto &body : bodies)
      if (body.prm.volumetric_smoothing == filters::VolumetricSmoothing::node)
        {
          background.initialize_vector(volume_sums, 3);
          break;
        }
  }

  template <int dim>
  void
  Simulator<dim>::repartition()
  {
    AssertThrow(balancer, ExcMessage("Load balancing is off"));
    TimerOutput::Scope t(timer, "repartition");
    // No nodal value lives from one step to the next, so the vectors are
    // only re-sized; the particles carry the whole state.
    balancer->repartition(params.boundary);
    initialize_nodal_vectors();
  }

  template <int dim>
  void
  Simulator<dim>::create_bodies()
  {
    bodies.resize(params.n_bodies);
    const unsigned int n_stress_in = dim == 1 ? 1 : dim == 2 ? 3 : 6;
    for (unsigned int b = 0; b < params.n_bodies; ++b)
      {
        const std::string where = "Bodies/" + Parameters::body_section(b);
        auto             &body  = bodies[b];
        body.index              = b;
        body.prm                = params.bodies[b];
        prm.enter_subsection("Bodies");
        prm.enter_subsection(Parameters::body_section(b));
        prm.enter_subsection("Material");
        const ConstantsScope scope(params.constants);
        body.material = materials::create_material(prm,
                                                   params.kinematics,
                                                   where + "/Material");
        prm.leave_subsection();
        prm.leave_subsection();
        prm.leave_subsection();

        const auto &c         = params.constants;
        body.initial_velocity = Expression<dim>(body.prm.initial_velocity,
                                                dim,
                                                spatial_variables(dim),
                                                c,
                                                false,
                                                where + "/Initial velocity");
        // 2D stress: xx; yy; xy and optionally zz
        const unsigned int n_given =
          Utilities::split_string_list(body.prm.initial_stress, ';').size();
        const unsigned int n_stress =
          (dim == 2 && n_given == 4) ? 4 : n_stress_in;
        body.initial_stress = Expression<dim>(body.prm.initial_stress,
                                              n_stress,
                                              spatial_variables(dim),
                                              c,
                                              false,
                                              where + "/Initial stress");
        body.body_force     = Expression<2 * dim>(body.prm.body_force,
                                              dim,
                                              load_variables(dim),
                                              c,
                                              true,
                                              where + "/Body force");
        body.traction       = Expression<2 * dim>(body.prm.traction,
                                            dim,
                                            load_variables(dim),
                                            c,
                                            true,
                                            where + "/Traction");
        layout.n_history =
          std::max(layout.n_history, body.material->n_history());
        any_convection_correction =
          any_convection_correction || body.prm.convection_correction;
        double E = 0, nu = 0;
        if (body.prm.assumed_stress_filter && body.prm.compliance_metric &&
            !body.material->elastic_moduli(E, nu))
          throw InputError(where +
                           "/Locking remedies: Filter metric = compliance "
                           "needs a material with elastic moduli; '" +
                           body.material->name() + "' has none");
        if (body.prm.assumed_stress_filter && body.prm.filter_force_only &&
            body.material->n_history() > 0)
          throw InputError(where +
                           "/Locking remedies: Filtered stress = force only "
                           "leaves the particles' stresses unfiltered, so '" +
                           body.material->name() +
                           "' would compute its plastic state from a locked "
                           "stress; use Filtered stress = written back");
        if (body.prm.assumed_stress_filter && body.prm.filter_force_only &&
            !params.time.apic)
          throw InputError(
            where +
            "/Locking remedies: Filtered stress = force only needs Time "
            "stepping/Velocity transfer = APIC: the stress the projection "
            "does not see accumulates in the particles, and with FLIP's "
            "transfer noise it grows until the step is unstable "
            "(doc/theory.md 4.13); use Filtered stress = written back");
        if (body.material->n_history() > 0 && history_names.empty())
          history_names = body.material->history_names();
      }
  }

  template <int dim>
  void
  Simulator<dim>::check_shape_functions()
  {
    const auto &family =
      shape_functions::family_traits(params.shape_functions.family);
    layout.has_corners = family.tracks_corners;
    layout.has_affine  = params.time.apic;
    // Loaded faces: the offset of the face from the particle, so that the
    // traction acts on the face and not a particle half-spacing inside it.
    layout.has_traction_offset =
      std::any_of(bodies.begin(), bodies.end(), [](const Body<dim> &b) {
        return !b.prm.traction_boundary_ids.empty();
      });
    for (auto &body : bodies)
      body.face_offset_slot = layout.traction_offset();
    family.check(
      {background.is_cartesian(), params.time.apic, any_convection_correction});
  }

  template <int dim>
  void
  Simulator<dim>::initial_properties(const Body<dim>         &body,
                                     const ParticleSeed<dim> &s,
                                     const double             rho,
                                     std::vector<double>     &p) const
  {
    using L = ParticleLayout<dim>;
    p.assign(layout.n_properties(), 0.);
    p[L::mass]    = rho * s.volume;
    p[L::volume0] = s.volume;
    p[L::volume]  = s.volume;
    p[L::body]    = body.index;
    body.initial_velocity.value(s.position, 0., &p[L::velocity]);
    for (unsigned int d = 0; d < dim; ++d)
      {
        p[L::X + d]           = s.position[d];
        p[L::F + d * dim + d] = 1.;
        for (unsigned int e = 0; e < dim; ++e)
          p[L::domain + d * dim + e] = s.domain[d][e];
      }
    p[L::traction_area] = s.traction_area;
    if (layout.has_traction_offset)
      for (unsigned int d = 0; d < dim; ++d)
        p[layout.traction_offset() + d] = s.traction_offset[d];
    if (layout.has_affine)
      {
        // APIC starts from the gradient of the initial velocity (central
        // differences of the expression)
        const double h = 1e-6 * std::max(1.,
                                         std::sqrt(s.domain.norm_square()) +
                                           std::sqrt(s.position.square()));
        for (unsigned int j = 0; j < dim; ++j)
          {
            Point<dim> plus = s.position, minus = s.position;
            plus[j] += h;
            minus[j] -= h;
            double vp[dim], vm[dim];
            body.initial_velocity.value(plus, 0., vp);
            body.initial_velocity.value(minus, 0., vm);
            for (unsigned int i = 0; i < dim; ++i)
              p[layout.affine() + i * dim + j] = (vp[i] - vm[i]) / (2 * h);
          }
      }
    if (layout.has_corners)
      for (unsigned int c = 0; c < (1u << dim); ++c)
        for (unsigned int d = 0; d < dim; ++d)
          p[layout.corners() + c * dim + d] = s.corners[c][d];
    // user order: 1D xx; 2D xx yy xy [zz]; 3D xx yy zz yz xz xy
    double sigma[6] = {};
    body.initial_stress.value(s.position, 0., sigma);
    double *out = &p[L::stress];
    if (dim == 1)
      out[0] = sigma[0];
    else if (dim == 2)
      {
        out[0] = sigma[0];
        out[1] = sigma[1];
        out[5] = sigma[2];
        out[2] = body.initial_stress.n_components() == 4 ? sigma[3] : 0.;
      }
    else
      std::copy(sigma, sigma + 6, out);
    // A model of F (the fluid's equation of state) starts at the J of the
    // initial pressure, so that the pressure is not lost at its first
    // update; the mass stays rho0 V0.
    const double J0 = body.material->initial_jacobian(load_stress(out));
    if (J0 != 1.)
      {
        const double stretch = std::pow(J0, 1. / dim);
        for (unsigned int d = 0; d < dim; ++d)
          p[L::F + d * dim + d] = stretch;
        p[L::volume] = J0 * s.volume;
      }
  }

  template <int dim>
  void
  Simulator<dim>::initialize_particle_handler()
  {
    using L = ParticleLayout<dim>;
    particle_handler.initialize(background.triangulation(),
                                background.mapping(),
                                layout.n_properties());
    particle_handler.signals.particle_lost.connect(
      [this](const typename Particles::ParticleIterator<dim> &p,
             const typename Triangulation<dim>::active_cell_iterator &) {
        const double m = p->get_properties()[L::mass];
        removed_mass += m;
        std::ostringstream s;
        s << "particle " << p->get_id() << " (body "
          << p->get_properties()[L::body] << ") left the grid in step "
          << current_step + 1 << ", position (" << p->get_location() << ")";
        lost_messages.push_back(s.str());
      });
  }

  template <int dim>
  std::vector<unsigned int>
  Simulator<dim>::count_planned_particles() const
  {
    // Only the seeds' positions are needed, chunk by chunk.
    std::vector<unsigned int> counts(
      background.triangulation().n_active_cells(), 0);
    const typename BackgroundGrid<dim>::OwnedCellLocator locator(background);
    const auto end_cell = background.triangulation().end_active(
      background.triangulation().n_levels() - 1);
    std::vector<Point<dim>> positions, xi;
    std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
    for (const auto &body : bodies)
      {
        Triangulation<dim> mesh;
        create_body_mesh(mesh,
                         body.prm,
                         input_folder,
                         "Bodies/" + Parameters::body_section(body.index));
        const unsigned int n       = body.prm.particles_per_direction;
        const unsigned int n_cells = mesh.n_active_cells();
        for (unsigned int first = 0; first < n_cells; first += seed_chunk_cells)
          {
            positions.clear();
            split_body_cell_positions(mesh,
                                      n,
                                      first,
                                      std::min(n_cells,
                                               first + seed_chunk_cells),
                                      positions);
            locator.locate(positions, cells, xi);
            for (const auto &c : cells)
              if (c != end_cell)
                ++counts[c->active_cell_index()];
          }
      }
    return counts;
  }

  template <int dim>
  void
  Simulator<dim>::create_particles(const std::vector<unsigned int> &planned)
  {
    initialize_particle_handler();
    // deal.II's particle storage allocated once at its final size (growing
    // it doubles the peak memory).
    particle_handler.reserve(owned_total(background, planned));
    types::particle_index id_offset = 0;
    for (const auto &body : bodies)
      {
        const std::string where =
          "Bodies/" + Parameters::body_section(body.index);
        Triangulation<dim> mesh;
        create_body_mesh(mesh, body.prm, input_folder, where);
        const unsigned int       n       = body.prm.particles_per_direction;
        const unsigned int       n_cells = mesh.n_active_cells();
        const unsigned long long expected =
          static_cast<unsigned long long>(n_cells) *
          Utilities::fixed_power<dim>(n);
        const double rho = body.material->reference_density();

        // Every rank walks the whole body mesh in chunks and keeps the
        // particles its owned cells contain (points on faces between
        // ranks go to exactly one of them). The locator's lattice over
        // the owned cells is built once, not per chunk.
        const typename BackgroundGrid<dim>::OwnedCellLocator locator(
          background);
        auto for_each_chunk = [&](const auto &work) {
          for (unsigned int first = 0; first < n_cells;
               first += seed_chunk_cells)
            {
              std::vector<ParticleSeed<dim>>  seeds;
              std::vector<unsigned long long> seed_ids;
              seeds.reserve(
                std::size_t(std::min(seed_chunk_cells, n_cells - first)) *
                Utilities::fixed_power<dim>(n));
              seed_ids.reserve(seeds.capacity());
              split_body_cells(mesh,
                               n,
                               body.prm.traction_boundary_ids,
                               first,
                               std::min(n_cells, first + seed_chunk_cells),
                               seeds,
                               seed_ids);
              std::vector<Point<dim>> positions(seeds.size()), xi;
              for (std::size_t i = 0; i < seeds.size(); ++i)
                positions[i] = seeds[i].position;
              std::vector<typename Triangulation<dim>::active_cell_iterator>
                cells;
              locator.locate(positions, cells, xi);
              work(seeds, seed_ids, cells, xi);
            }
        };
        const auto end_cell = background.triangulation().end_active(
          background.triangulation().n_levels() - 1);
        unsigned long long  inserted = 0;
        std::string         bad_value;
        std::vector<double> properties;
        for_each_chunk([&](const auto &seeds,
                           const auto &seed_ids,
                           const auto &cells,
                           const auto &xi) {
          // Insert in cell order: the particle data then lie in memory in
          // the order the cell-by-cell loops visit them.
          std::vector<std::size_t> order;
          for (std::size_t i = 0; i < seeds.size(); ++i)
            if (cells[i] != end_cell)
              order.push_back(i);
          std::sort(order.begin(),
                    order.end(),
                    [&](const auto a, const auto b) {
                      return cells[a]->active_cell_index() <
                             cells[b]->active_cell_index();
                    });
          for (const std::size_t i : order)
            {
              initial_properties(body, seeds[i], rho, properties);
              if (bad_value.empty())
                for (const double v : properties)
                  if (!std::isfinite(v))
                    {
                      std::ostringstream msg;
                      msg << where << ": the initial state is not finite "
                          << "(check Initial velocity and Initial stress) at "
                          << "the particle at (" << seeds[i].position << ")";
                      bad_value = msg.str();
                      break;
                    }
              particle_handler.insert_particle(seeds[i].position,
                                               xi[i],
                                               id_offset + seed_ids[i],
                                               cells[i],
                                               ArrayView<const double>(
                                                 properties));
              ++inserted;
            }
        });

        {
          const unsigned int rank   = Utilities::MPI::this_mpi_process(comm);
          const unsigned int nranks = Utilities::MPI::n_mpi_processes(comm);
          const unsigned int bad =
            Utilities::MPI::min(bad_value.empty() ? nranks : rank, comm);
          if (bad < nranks)
            throw InputError(Utilities::MPI::broadcast(comm, bad_value, bad));
        }
        if (Utilities::MPI::sum(inserted, comm) != expected)
          {
            // Name the first particle no rank took: the body sticks out.
            std::string outside;
            for_each_chunk([&](const auto &seeds,
                               const auto &,
                               const auto &cells,
                               const auto &) {
              if (!outside.empty())
                return;
              std::vector<unsigned int> mine(seeds.size()), any(seeds.size());
              for (std::size_t i = 0; i < seeds.size(); ++i)
                mine[i] = cells[i] != end_cell;
              Utilities::MPI::max(mine, comm, any);
              for (std::size_t i = 0; i < seeds.size() && outside.empty(); ++i)
                if (!any[i])
                  {
                    std::ostringstream s;
                    s << where << ": the particle at (" << seeds[i].position
                      << ") lies outside the background grid; every body must "
                      << "be inside the grid (check Grid/Lower corner, Upper "
                      << "corner and the body geometry)";
                    outside = s.str();
                  }
            });
            throw InputError(outside.empty() ?
                               where + ": particles were placed twice or lost "
                                       "at set-up (please report this)" :
                               outside);
          }
        id_offset += expected;
      }
    particle_handler.update_cached_numbers();
  }

  // -------------------------------------------------------------- the step
  template <int dim>
  void
  Simulator<dim>::do_time_step(const double dt)
  {
    using Scheme = Parameters::TimeStepping::Scheme;
    using transfer::P2GContent;
    last_dt = dt;
    if (balancer && balancer->due(current_step))
      repartition();
    // The particles moved (and may have changed cells or ranks) since the
    // stencils were built.
    if (domain_functions)
      domain_functions->forget_stencils();
    if (params.time.scheme == Scheme::usf)
      {
        particle_to_grid(P2GContent::mass_momentum);
        {
          TimerOutput::Scope t(timer, "grid update");
          const auto         e = nodal_velocity(background,
                                        p2g,
                                        p2g,
                                        transfer::P2GLayout<dim>::n_components,
                                        transfer::P2GLayout<dim>::momentum,
                                        min_nodal_mass,
                                        kinematics);
          if (local_error.empty())
            local_error = e;
        }
        update_stress(dt);
        // cpGIMP and CPDI take their domains from F, which the stress
        // update has just changed: the force pass and G2P see the new
        // domain, so mass and momentum must be mapped with it again, or
        // G2P's weights no longer sum to the nodal masses and momentum is
        // not conserved.
        const bool new_domains =
          shape_functions::family_traits(params.shape_functions.family)
            .domain_follows_deformation;
        if (new_domains)
          domain_functions->forget_stencils();
        particle_to_grid(new_domains ? P2GContent::mass_momentum_force :
                                       P2GContent::force);
        update_grid(dt);
        grid_to_particle(dt);
      }
    else
      {
        particle_to_grid(P2GContent::mass_momentum_force);
        update_grid(dt);
        grid_to_particle(dt);
        if (params.time.scheme == Scheme::musl)
          remap_momentum();
        update_stress(dt);
      }
    update_positions();
    current_time += dt;
    ++current_step;
    check_errors();
  }

  template <int dim>
  void
  Simulator<dim>::particle_to_grid(const transfer::P2GContent content)
  {
    // The 1D convection correction changes the forces of this pass only,
    // with the cells the particles are in now: the stresses are shifted
    // for the pass and put back after it, and the body-force correction is
    // added to the nodal forces (doc/theory.md, section 4.11).
    const bool correct = any_convection_correction &&
                         (content == transfer::P2GContent::force ||
                          content == transfer::P2GContent::mass_momentum_force);
    if (correct)
      {
        TimerOutput::Scope t(timer, "convection correction");
        convection_correction.apply(background,
                                    particle_handler,
                                    bodies,
                                    current_time);
      }
    {
      TimerOutput::Scope              t(timer, "P2G");
      const transfer::P2GContext<dim> context{
        transfer_context(), bodies, *stress_filter, current_time, content, p2g};
      const auto e = transfer::particle_to_grid(context);
      if (local_error.empty())
        local_error = e;
    }
    if (correct)
      convection_correction.finish(p2g);
  }

  template <int dim>
  transfer::TransferContext<dim>
  Simulator<dim>::transfer_context()
  {
    return {background,
            particle_handler,
            domain_functions.get(),
            layout.affine()};
  }

  template <int dim>
  void
  Simulator<dim>::update_grid(const double dt)
  {
    TimerOutput::Scope t(timer, "grid update");
    const auto         e = ::mpm::update_grid(
      background, p2g, dt, params.time.damping, min_nodal_mass, kinematics);
    if (local_error.empty())
      local_error = e;
  }

  template <int dim>
  void
  Simulator<dim>::grid_to_particle(const double dt)
  {
    TimerOutput::Scope t(timer, "G2P");
    // MUSL's re-map is fused into G2P (one pass over the particles).
    const bool fused_remap =
      params.time.scheme == Parameters::TimeStepping::Scheme::musl;
    const auto e = transfer::grid_to_particle(
      transfer::G2PContext<dim>{transfer_context(),
                                kinematics,
                                dt,
                                params.time.flip_fraction,
                                fused_remap ? &remap : nullptr});
    if (local_error.empty())
      local_error = e;
  }

  template <int dim>
  void
  Simulator<dim>::remap_momentum()
  {
    // The re-mapped momentum is in `remap` (G2P filled it).
    TimerOutput::Scope t(timer, "MUSL re-map");
    const auto         e = nodal_velocity(
      background, p2g, remap, dim, 0, min_nodal_mass, kinematics);
    if (local_error.empty())
      local_error = e;
  }

  template <int dim>
  void
  Simulator<dim>::update_stress(const double dt)
  {
    TimerOutput::Scope t(timer, "stress update");
    const auto         r = ::mpm::update_stress(background,
                                        particle_handler,
                                        bodies,
                                        kinematics,
                                        dt,
                                        &volume_sums,
                                        domain_functions.get());
    stable_dt            = r.stable_time_step;
    if (local_error.empty())
      local_error = r.error;
  }

  template <int dim>
  void
  Simulator<dim>::filter_stress()
  {
    if (!stress_filter->any())
      return;
    TimerOutput::Scope t(timer, "stress filter");
    stress_filter->apply(background, particle_handler);
  }

  template <int dim>
  void
  Simulator<dim>::update_positions()
  {
    TimerOutput::Scope t(timer, "position update");
    if (shape_functions::family_traits(params.shape_functions.family)
          .tracks_corners)
      {
        const auto e = transfer::move_domain_corners(
          background, particle_handler, kinematics, last_dt, *domain_functions);
        if (local_error.empty())
          local_error = e;
      }
    lost_messages.clear();
    if (!relocate_particles(background, particle_handler, comm))
      {
        particle_handler.sort_particles_into_subdomains_and_cells();
        ++n_global_sorts;
      }
    if (!lost_messages.empty() && !params.boundary.remove_lost_particles &&
        local_error.empty())
      local_error = lost_messages.front() +
                    " (set Boundary conditions/Particles leaving the grid = "
                    "remove to delete such particles instead)";
  }

  template <int dim>
  void
  Simulator<dim>::check_errors()
  {
    // One collective per step: the stable step and the first failing rank.
    const unsigned int rank   = Utilities::MPI::this_mpi_process(comm);
    const unsigned int nranks = Utilities::MPI::n_mpi_processes(comm);
    double local[2] = {stable_dt, double(local_error.empty() ? nranks : rank)};
    double global[2];
    Utilities::MPI::min(ArrayView<const double>(local, 2),
                        comm,
                        ArrayView<double>(global, 2));
    stable_dt = global[0];
    if (global[1] < nranks)
      {
        const std::string msg =
          Utilities::MPI::broadcast(comm,
                                    local_error,
                                    static_cast<unsigned int>(global[1]));
        std::ostringstream s;
        s << "at step " << current_step << " (t = " << current_time
          << "): " << msg;
        throw RuntimeError(s.str());
      }
  }

  template <int dim>
  double
  Simulator<dim>::stable_time_step()
  {
    return Utilities::MPI::min(stable_dt, comm);
  }

  // ------------------------------------------------------------ time loop
  template <int dim>
  void
  Simulator<dim>::run()
  {
    using StepControl = Parameters::TimeStepping::StepControl;
    const auto &out   = params.output;
    print_header();

    // Only now, with the input checked, touch the output folder (rank 0;
    // every rank learns whether that worked).
    std::string problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          std::filesystem::create_directories(out.directory);
        }
      catch (const std::exception &e)
        {
          problem = e.what();
        }
    throw_if_any<InputError>("Output/Directory = '" + out.directory +
                               "' cannot be created: ",
                             problem);
    writer          = std::make_unique<OutputWriter<dim>>(comm,
                                                 out.directory,
                                                 layout,
                                                 history_names);
    statistics_file = std::make_unique<StatisticsFile<dim>>();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          // A restart continues the statistics file of the checkpoint: the
          // rows written after it (by the interrupted run) are dropped.
          if (resumed())
            statistics_file->resume(out.directory + "/statistics.txt",
                                    checkpoint::read_file(resume_folder +
                                                          "/statistics.txt"));
          else
            statistics_file->open(out.directory + "/statistics.txt",
                                  benchmark ? benchmark->columns() :
                                              std::vector<std::string>());
          // Every entry of this run (defaults included, no comments), so
          // that scripts/recompute_measures.py finds the benchmark, its
          // constants and the grid beside the output.
          prm.print_parameters(out.directory + "/parameters.prm",
                               ParameterHandler::ShortPRM);
        }
      catch (const std::exception &e)
        {
          problem = e.what();
        }
    throw_if_any<InputError>("", problem);

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
        problem.clear();
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          try
            {
              writer->write_series();
            }
          catch (const std::exception &e)
            {
              problem = e.what();
            }
        throw_if_any<RuntimeError>("", problem);
      }
    else
      {
        // The first output has no grid fields yet: fill them from the
        // state.
        particle_to_grid(transfer::P2GContent::mass_momentum);
        nodal_velocity(background,
                       p2g,
                       p2g,
                       transfer::P2GLayout<dim>::n_components,
                       transfer::P2GLayout<dim>::momentum,
                       min_nodal_mass,
                       kinematics);
        write_output();
        next_output_time = out.interval;
      }

    wall_start = last_progress        = wall_seconds();
    last_checkpoint_wall              = wall_start;
    double             output_seconds = 0;
    const unsigned int first_step     = current_step;
    const double       end            = params.time.end_time;
    const double       tiny           = 1e-12 * std::max(end, 1e-300);
    while (current_time < end - tiny &&
           (params.time.max_steps == 0 || current_step < params.time.max_steps))
      {
        double dt = params.time.step_control == StepControl::fixed ?
                      params.time.time_step :
                      params.time.cfl_number * stable_dt;
        if (current_time + dt > end - tiny)
          dt = end - current_time;
        do_time_step(dt);
        if (current_time >= next_output_time - 1e-9 * dt ||
            current_time >= end - tiny)
          {
            const double before = wall_seconds();
            write_output();
            output_seconds += wall_seconds() - before;
            // next multiple of the interval (Interval = 0: every step)
            next_output_time =
              out.interval > 0 ?
                out.interval *
                  (std::floor(current_time / out.interval + 1e-9) + 1) :
                current_time;
          }
        if (checkpoint_due())
          {
            const double before = wall_seconds();
            write_checkpoint();
            output_seconds += wall_seconds() - before;
          }
        print_progress(false);
      }
    // Throughput of the time loop without output: the slowest rank counts.
    const double loop_seconds =
      Utilities::MPI::max(wall_seconds() - wall_start - output_seconds, comm);
    if (last_output_step != current_step)
      write_output(); // stopped by the step limit
    print_progress(true);
    const double updates = double(particle_handler.n_global_particles()) *
                           (current_step - first_step);
    pcout << "  time loop: " << loop_seconds << " s wall (without output) for "
          << current_step - first_step
          << " steps = " << updates / std::max(loop_seconds, 1e-300) / 1e6
          << " M particle-updates/s" << std::endl;

    if (!out.test_summary.empty())
      {
        // Written by rank 0; a failure stops every rank (collective check).
        std::string problem;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          try
            {
              std::ostringstream s;
              for (const auto &r : summary_rows)
                s << r << '\n';
              write_file_atomically(out.test_summary, s.str());
            }
          catch (const std::exception &e)
            {
              problem = e.what();
            }
        throw_if_any<RuntimeError>("while writing Output/Test summary file: ",
                                   problem);
      }
    if (stress_filter->any())
      pcout << "  stress filter: "
            << Utilities::MPI::sum(stress_filter->n_fallbacks, comm)
            << " cell projections fell back to constant stress" << std::endl;
    if (balancer)
      {
        const auto b = LoadBalancer<dim>::balance(particle_handler, comm);
        pcout << "  load balancing: " << balancer->n_repartitions
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
    const double n = std::max<double>(1, particle_handler.n_global_particles());
    const double grid =
      Utilities::MPI::sum(double(
                            background.triangulation().memory_consumption() +
                            background.dof_handler().memory_consumption()),
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

  template <int dim>
  GlobalStatistics<dim>
  Simulator<dim>::statistics()
  {
    GlobalStatistics<dim> s;
    s.compute(particle_handler, bodies, comm);
    s.removed_mass = Utilities::MPI::sum(removed_mass, comm);
    return s;
  }

  template <int dim>
  std::vector<double>
  Simulator<dim>::benchmark_values()
  {
    return benchmark ?
             benchmark->measure(particle_handler, current_time, comm) :
             std::vector<double>();
  }

  template <int dim>
  void
  Simulator<dim>::write_output()
  {
    // The stress the next force will be computed from (the filter is a
    // projection: applying it here changes nothing else).
    filter_stress();
    TimerOutput::Scope t(timer, "output");
    particle_handler.update_cached_numbers();
    const auto &out   = params.output;
    const auto  stats = statistics();
    const auto  extra = benchmark_values();
    last_output_step  = current_step;

    // Each writer has collective parts; a failure on one rank (a full
    // disk, say) is collected and reported on all ranks afterwards, so no
    // rank waits for another that has given up.
    std::string problem;
    auto        attempt = [&](const auto &write) {
      try
        {
          write();
        }
      catch (const std::exception &e)
        {
          if (problem.empty())
            problem = clean_dealii_message(e.what());
        }
    };
    attempt([&]() {
      statistics_file->write_row(
        current_time, current_step, last_dt, stats, extra);
    });
    if (out.write_vtu)
      {
        attempt([&]() {
          writer->write_particles_vtu(particle_handler, current_time);
        });
        if (out.write_grid)
          attempt([&]() {
            writer->write_grid_vtu(background, p2g, kinematics, current_time);
          });
      }
    if (out.write_csv)
      attempt(
        [&]() { writer->write_particles_csv(particle_handler, current_time); });
    writer->advance();
    throw_if_any<RuntimeError>("while writing output at step " +
                                 std::to_string(current_step) + ": ",
                               problem);

    if (!out.test_summary.empty())
      {
        // Few digits, scaled quantities: stable across ranks and compilers.
        std::ostringstream s;
        s << std::scientific << std::setprecision(6) << "t " << current_time
          << " step " << current_step << " n " << stats.n_particles << " mass "
          << stats.mass << " removed " << stats.removed_mass << " Ekin "
          << stats.kinetic_energy << " Estrain " << stats.strain_energy;
        for (unsigned int d = 0; d < dim; ++d)
          s << " p" << d << ' ' << stats.momentum[d];
        if (dim >= 2)
          s << " Lz " << stats.angular_momentum[2];
        for (const double e : extra)
          s << " b " << e;
        summary_rows.push_back(s.str());
      }
  }

  template <int dim>
  void
  Simulator<dim>::print_header()
  {
    const auto &p = params;
    pcout << "mpm: " << p.file_name << '\n'
          << "  dimension " << dim << " (" << to_string(p.kinematics) << "), "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)\n"
          << "  grid: " << background.n_global_cells() << " cells, "
          << background.n_global_nodes() << " nodes"
          << (background.is_cartesian() ? " (Cartesian)" : " (general Q1)")
          << '\n';
    for (const auto &b : bodies)
      pcout << "  body " << b.index << ": " << b.material->name()
            << ", rho0 = " << b.material->reference_density() << ", "
            << b.prm.particles_per_direction << "^" << dim
            << " particles per body cell\n";
    pcout << "  particles: " << particle_handler.n_global_particles() << '\n'
          << "  scheme " << scheme_name(p.time.scheme) << ", FLIP fraction "
          << p.time.flip_fraction << ", end time " << p.time.end_time << '\n'
          << "  time step: "
          << (p.time.step_control ==
                  Parameters::TimeStepping::StepControl::fixed ?
                "fixed " + Utilities::to_string(p.time.time_step) :
                "CFL " + Utilities::to_string(p.time.cfl_number))
          << " (stability limit now " << stable_time_step() << ")\n"
          << "  output: " << p.output.directory << "/ every "
          << p.output.interval << " s" << std::endl;
    if (resumed())
      pcout << "  resumed from the checkpoint " << resume_folder << " at step "
            << current_step << ", t = " << current_time << std::endl;
    if (balancer)
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
      params.time.end_time > 0 ? current_time / params.time.end_time : 1.;
    const double       elapsed = now - wall_start;
    std::ostringstream s;
    s << "  step " << std::setw(8) << current_step << "  t = " << std::setw(11)
      << std::setprecision(5) << current_time << "  dt = " << std::setw(11)
      << last_dt << "  " << std::fixed << std::setprecision(1) << std::setw(5)
      << 100 * done << "%  elapsed " << elapsed << " s";
    if (done > 0 && done < 1)
      s << "  left ~" << elapsed * (1 - done) / done << " s";
    pcout << s.str() << std::endl;
  }

  template class Simulator<1>;
  template class Simulator<2>;
  template class Simulator<3>;
} // namespace mpm
