// The bodies' inlets: the particles that enter during the run
// (particles/inflow.h lays them out, here they are placed on the ranks).

#include <deal.II/base/mpi.h>

#include <mpm/solver/resource_estimate.h>
#include <mpm/solver/simulator.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mpm
{
  using namespace dealii;

  template <int dim>
  void
  Simulator<dim>::create_inflows()
  {
    inflows.clear();
    // The inlets' ids follow those the bodies' meshes gave at set-up
    // (cells times particles per cell), counted without building them.
    unsigned long long first_id = 0;
    for (const auto &body : state.bodies)
      first_id += static_cast<unsigned long long>(body_mesh_cells(
                    body.prm,
                    input_folder,
                    "Bodies/" + Parameters::body_section(body.index) + "/")) *
                  Utilities::fixed_power<dim>(body.prm.particles_per_direction);
    for (const auto &body : state.bodies)
      if (body.prm.inflow.enabled)
        inflows.emplace_back(body.prm.inflow,
                             body.index,
                             params.time.end_time,
                             "Bodies/" + Parameters::body_section(body.index) +
                               "/Inflow");
    if (inflows.empty())
      return;
    if (params.time.integrator !=
        Parameters::TimeStepping::Integrator::explicit_dynamics)
      throw InputError(inflows[0].where() +
                       "/Enabled = true: an inflow needs Time stepping/"
                       "Integrator = explicit");
    unsigned long long stride = 0, max_layers = 0;
    for (const auto &in : inflows)
      {
        stride += in.n_per_layer();
        max_layers = std::max(max_layers, in.n_layers());
      }
    for (auto &in : inflows)
      {
        in.set_ids(first_id, stride);
        first_id += in.n_per_layer();
      }
    if (first_id - stride + max_layers * stride >
        std::numeric_limits<types::particle_index>::max())
      throw InputError(inflows[0].where() +
                       ": the inlets would create more particles than a "
                       "32-bit particle id can number; shorten End time, "
                       "lower Volume or coarsen Particle spacing");

    // Every point of the inlet, and one layer downstream, must lie in a
    // cell: an inlet outside the grid or across a wall is refused.
    inlet_locator =
      std::make_unique<typename BackgroundGrid<dim>::OwnedCellLocator>(
        state.background);
    const auto end_cell = state.background.triangulation().end_active(
      state.background.triangulation().n_levels() - 1);
    inflow_stable_dt.assign(inflows.size(), std::numeric_limits<double>::max());
    std::vector<ParticleSeed<dim>>  seeds;
    std::vector<unsigned long long> ids;
    std::vector<double>             properties;
    for (unsigned int i = 0; i < inflows.size(); ++i)
      {
        const auto &in   = inflows[i];
        const auto &body = state.bodies[in.body()];
        // the entering particle's wave speed and speed (its initial state)
        seeds.clear();
        ids.clear();
        in.layer(0, 0., seeds, ids);
        initial_properties(body,
                           seeds[0],
                           body.material->reference_density(),
                           properties);
        using L        = ParticleLayout<dim>;
        const double c = body.material->wave_speed(
          embed<dim>(load_matrix<dim>(properties.data() + L::F), 1.));
        const double speed = in.velocity().norm();
        // at the inlet, then as far downstream as a particle travels in
        // the longest step the inlet allows
        for (const unsigned int pass : {0u, 1u})
          {
            const double d      = pass == 0 ? 0. : speed * inflow_stable_dt[i];
            const auto   points = in.points_at(d);
            std::vector<typename Triangulation<dim>::active_cell_iterator>
                                    cells;
            std::vector<Point<dim>> xi;
            inlet_locator->locate(points, cells, xi);
            std::vector<unsigned int> found(points.size()), any(points.size());
            for (std::size_t j = 0; j < points.size(); ++j)
              {
                found[j] = cells[j] != end_cell;
                if (found[j] && pass == 0)
                  inflow_stable_dt[i] =
                    std::min(inflow_stable_dt[i],
                             state.background.cell_height(cells[j]) /
                               (c + speed));
              }
            Utilities::MPI::max(found, comm, any);
            for (std::size_t j = 0; j < points.size(); ++j)
              if (!any[j])
                {
                  std::ostringstream s;
                  s << in.where() << "/Center: the inlet's point (" << points[j]
                    << ")"
                    << (d > 0 ? ", where the entering particles go," : "")
                    << " lies outside the grid or inside a wall; the inlet "
                       "must lie inside the grid, clear of its boundary "
                       "(check Center, Radius and Direction)";
                  throw InputError(s.str());
                }
            if (pass == 0)
              inflow_stable_dt[i] =
                Utilities::MPI::min(inflow_stable_dt[i], comm);
          }
      }
    // the layers the current state holds: none at a fresh start, those up
    // to the checkpoint's time on a resume
    inflow_layers_done.assign(inflows.size(), 0);
    if (resumed())
      for (unsigned int i = 0; i < inflows.size(); ++i)
        inflow_layers_done[i] = inflows[i].layers_at(state.current_time);
  }

  template <int dim>
  void
  Simulator<dim>::inject_particles()
  {
    if (inflows.empty())
      return;
    using L = ParticleLayout<dim>;
    if (!inlet_locator)
      inlet_locator =
        std::make_unique<typename BackgroundGrid<dim>::OwnedCellLocator>(
          state.background);
    const auto end_cell = state.background.triangulation().end_active(
      state.background.triangulation().n_levels() - 1);
    bool                            any_layer = false;
    std::vector<ParticleSeed<dim>>  seeds;
    std::vector<unsigned long long> ids;
    std::vector<Point<dim>>         positions, xi;
    std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
    std::vector<double>                                            properties;
    std::string                                                    bad_value;
    for (unsigned int i = 0; i < inflows.size(); ++i)
      {
        const auto              &in     = inflows[i];
        const unsigned long long target = in.layers_at(state.current_time);
        if (target <= inflow_layers_done[i])
          continue;
        any_layer = true;
        seeds.clear();
        ids.clear();
        for (unsigned long long k = inflow_layers_done[i]; k < target; ++k)
          in.layer(k, state.current_time, seeds, ids);
        positions.resize(seeds.size());
        for (std::size_t j = 0; j < seeds.size(); ++j)
          positions[j] = seeds[j].position;
        inlet_locator->locate(positions, cells, xi);
        const auto        &body     = state.bodies[in.body()];
        const double       rho      = body.material->reference_density();
        const auto         v        = in.velocity();
        unsigned long long inserted = 0;
        for (std::size_t j = 0; j < seeds.size(); ++j)
          if (cells[j] != end_cell)
            {
              initial_properties(body, seeds[j], rho, properties);
              // the inlet's velocity, uniform (no affine part)
              for (unsigned int d = 0; d < dim; ++d)
                properties[L::velocity + d] = v[d];
              if (state.layout.has_affine)
                std::fill_n(properties.begin() + state.layout.affine(),
                            dim * dim,
                            0.);
              if (bad_value.empty())
                for (const double value : properties)
                  if (!std::isfinite(value))
                    {
                      std::ostringstream s;
                      s << in.where() << ": the entering particle at ("
                        << seeds[j].position
                        << ") has a state that is not finite (check the "
                           "body's Initial stress)";
                      bad_value = s.str();
                      break;
                    }
              state.particle_handler.insert_particle(
                seeds[j].position,
                xi[j],
                static_cast<types::particle_index>(ids[j]),
                cells[j],
                ArrayView<const double>(properties));
              ++inserted;
            }
        if (Utilities::MPI::sum(inserted, comm) != seeds.size())
          {
            // name the first particle no rank took
            std::vector<unsigned int> mine(seeds.size()), any(seeds.size());
            for (std::size_t j = 0; j < seeds.size(); ++j)
              mine[j] = cells[j] != end_cell;
            Utilities::MPI::max(mine, comm, any);
            const auto         missing = std::find(any.begin(), any.end(), 0u);
            std::ostringstream s;
            s << "at step " << state.current_step
              << " (t = " << state.current_time << "): " << in.where()
              << ": the entering particle at ("
              << seeds[missing - any.begin()].position
              << ") lies outside the grid (the inlet lies closer to the "
                 "grid's boundary than the particles travel in a step)";
            throw RuntimeError(s.str());
          }
        inflow_layers_done[i] = target;
      }
    throw_if_any<RuntimeError>(comm, "", bad_value);
    if (any_layer)
      {
        state.particle_handler.update_cached_numbers();
        state.background.particles_changed_cells();
      }
  }

  template <int dim>
  void
  Simulator<dim>::bound_step_by_inflows()
  {
    for (unsigned int i = 0; i < inflows.size(); ++i)
      if (inflow_layers_done[i] < inflows[i].n_layers() ||
          inflows[i].layers_at(state.current_time - state.last_dt) <
            inflow_layers_done[i])
        state.stable_dt = std::min(state.stable_dt, inflow_stable_dt[i]);
  }

  template <int dim>
  double
  Simulator<dim>::injected_mass() const
  {
    double m = 0;
    for (unsigned int i = 0; i < inflows.size(); ++i)
      m += inflow_layers_done[i] * inflows[i].n_per_layer() *
           inflows[i].particle_volume() *
           state.bodies[inflows[i].body()].material->reference_density();
    return m;
  }

#define MPM_INSTANTIATE(d)                               \
  template void   Simulator<d>::create_inflows();        \
  template void   Simulator<d>::inject_particles();      \
  template void   Simulator<d>::bound_step_by_inflows(); \
  template double Simulator<d>::injected_mass() const;
  MPM_INSTANTIATE(1)
  MPM_INSTANTIATE(2)
  MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
} // namespace mpm
