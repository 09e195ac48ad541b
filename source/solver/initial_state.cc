// The initial state of a run: the bodies with their materials and loads,
// the shape-function family's checks, and the particles the bodies'
// meshes are split into.

#include <deal.II/base/utilities.h>

#include <mpm/particles/body_overlap.h>
#include <mpm/shape_functions/family_registry.h>
#include <mpm/solver/simulator.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mpm
{
  using namespace dealii;

  namespace
  {
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
  void
  Simulator<dim>::create_initial_state(const bool balance_now)
  {
    create_bodies();
    check_shape_functions();
    // Balance by the particles the bodies will place, before they
    // exist: no particle data travels.
    auto planned = count_planned_particles();
    setup_balance[0] =
      LoadBalancer<dim>::balance(owned_total(state.background, planned), comm);
    if (balance_now)
      {
        state.balancer->weigh_by(&planned);
        const bool repartition = state.balancer->unbalanced();
        if (repartition)
          state.balancer->repartition(params.boundary);
        state.balancer->weigh_by(nullptr);
        if (repartition)
          planned = count_planned_particles();
      }
    create_particles(planned);
    check_bodies_do_not_overlap(state.bodies,
                                state.particle_handler,
                                input_folder,
                                comm);
  }

  template <int dim>
  void
  Simulator<dim>::create_bodies()
  {
    state.bodies.resize(params.n_bodies);
    const unsigned int n_stress_in = dim == 1 ? 1 : dim == 2 ? 3 : 6;
    for (unsigned int b = 0; b < params.n_bodies; ++b)
      {
        const std::string where = "Bodies/" + Parameters::body_section(b);
        auto             &body  = state.bodies[b];
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
        const bool rigid    = body.material->name() == "rigid";
        if (rigid != body.is_rigid())
          throw InputError(
            where + (rigid ? "/Material/Model = rigid needs a Prescribed "
                             "velocity of the body" :
                             "/Prescribed velocity needs Material/Model = "
                             "rigid"));
        if (rigid)
          {
            if (params.time.integrator ==
                  Parameters::TimeStepping::Integrator::explicit_dynamics &&
                !params.contact.enabled())
              throw InputError(where +
                               "/Prescribed velocity: a body of prescribed "
                               "motion needs Time stepping/Integrator = "
                               "quasi-static or Newmark, or a Contact/Contact "
                               "law other than none");
            body.prescribed_velocity =
              Expression<dim>(body.prm.prescribed_velocity,
                              dim,
                              spatial_variables(dim),
                              c,
                              true,
                              where + "/Prescribed velocity");
          }
        state.layout.n_history =
          std::max(state.layout.n_history, body.material->n_history());
        body.prm.locking_remedies.check({where,
                                         dim,
                                         *body.material,
                                         params.shape_functions.family,
                                         params.time});
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
    state.layout.has_corners = family.tracks_corners;
    state.layout.has_affine  = params.time.apic;
    // Loaded faces: the offset of the face from the particle, so that the
    // traction acts on the face and not a particle half-spacing inside it.
    state.layout.has_traction_offset =
      std::any_of(state.bodies.begin(),
                  state.bodies.end(),
                  [](const Body<dim> &b) {
                    return !b.prm.traction_boundary_ids.empty();
                  });
    for (auto &body : state.bodies)
      body.face_offset_slot = state.layout.traction_offset();
    family.check({state.background.is_cartesian(),
                  params.time.apic,
                  params.implicit.fixed_geometry});
  }

  template <int dim>
  void
  Simulator<dim>::initial_properties(const Body<dim>         &body,
                                     const ParticleSeed<dim> &s,
                                     const double             rho,
                                     std::vector<double>     &p) const
  {
    using L = ParticleLayout<dim>;
    p.assign(state.layout.n_properties(), 0.);
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
    if (state.layout.has_traction_offset)
      for (unsigned int d = 0; d < dim; ++d)
        p[state.layout.traction_offset() + d] = s.traction_offset[d];
    if (state.layout.has_affine)
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
              p[state.layout.affine() + i * dim + j] =
                (vp[i] - vm[i]) / (2 * h);
          }
      }
    if (state.layout.has_corners)
      for (unsigned int c = 0; c < (1u << dim); ++c)
        for (unsigned int d = 0; d < dim; ++d)
          p[state.layout.corners() + c * dim + d] = s.corners[c][d];
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
    state.particle_handler.initialize(state.background.triangulation(),
                                      state.background.mapping(),
                                      state.layout.n_properties());
    state.particle_handler.signals.particle_lost.connect(
      [this](const typename Particles::ParticleIterator<dim> &p,
             const typename Triangulation<dim>::active_cell_iterator &) {
        const double m = p->get_properties()[L::mass];
        state.removed_mass += m;
        std::ostringstream s;
        s << "particle " << p->get_id() << " (body "
          << p->get_properties()[L::body] << ") left the grid in step "
          << state.current_step + 1 << ", position (" << p->get_location()
          << ")";
        state.lost_messages.push_back(s.str());
      });
  }

  template <int dim>
  std::vector<unsigned int>
  Simulator<dim>::count_planned_particles() const
  {
    // Only the seeds' positions are needed, chunk by chunk.
    std::vector<unsigned int> counts(
      state.background.triangulation().n_active_cells(), 0);
    const typename BackgroundGrid<dim>::OwnedCellLocator locator(
      state.background);
    const auto end_cell = state.background.triangulation().end_active(
      state.background.triangulation().n_levels() - 1);
    std::vector<Point<dim>> positions, xi;
    std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
    for (const auto &body : state.bodies)
      {
        if (body.prm.geometry == Parameters::Body<dim>::Geometry::none)
          continue;
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
    state.particle_handler.reserve(owned_total(state.background, planned));
    types::particle_index id_offset = 0;
    for (const auto &body : state.bodies)
      {
        if (body.prm.geometry == Parameters::Body<dim>::Geometry::none)
          continue;
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
          state.background);
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
        const auto end_cell = state.background.triangulation().end_active(
          state.background.triangulation().n_levels() - 1);
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
              state.particle_handler.insert_particle(seeds[i].position,
                                                     xi[i],
                                                     id_offset + seed_ids[i],
                                                     cells[i],
                                                     ArrayView<const double>(
                                                       properties));
              ++inserted;
            }
        });

        throw_if_any<InputError>(comm, "", bad_value);
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
    state.particle_handler.update_cached_numbers();
    state.background.particles_changed_cells();
  }

#define MPM_INSTANTIATE(d)                                                     \
  template void Simulator<d>::create_initial_state(bool);                      \
  template void Simulator<d>::create_bodies();                                 \
  template void Simulator<d>::check_shape_functions();                         \
  template void Simulator<d>::initial_properties(const Body<d> &,              \
                                                 const ParticleSeed<d> &,      \
                                                 double,                       \
                                                 std::vector<double> &) const; \
  template void Simulator<d>::initialize_particle_handler();                   \
  template std::vector<unsigned int> Simulator<d>::count_planned_particles()   \
    const;                                                                     \
  template void Simulator<d>::create_particles(                                \
    const std::vector<unsigned int> &);
  MPM_INSTANTIATE(1)
  MPM_INSTANTIATE(2)
  MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
} // namespace mpm
