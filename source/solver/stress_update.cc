#include <mpm/grid/grid_update.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/remedies/cell_pressure_force.h>
#include <mpm/remedies/volumetric_smoothing.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/solver/stress_update.h>
#include <mpm/transfer/velocity_gradient.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

namespace mpm
{
  using namespace dealii;

  namespace
  {
    /// The step's kinematics of the particle with properties @p prop:
    /// L_p = @p grad_v and F = (I + dt L) F_old; with @p small_strain
    /// L_p = sym(grad_v) and F = F_old.
    template <int dim, bool small_strain>
    inline __attribute__((always_inline)) void
    step_kinematics(const Tensor<2, dim> &grad_v,
                    const double         *prop,
                    const double          dt,
                    Tensor<2, dim>       &L_p,
                    Tensor<2, dim>       &F)
    {
      using L                    = ParticleLayout<dim>;
      const Tensor<2, dim> F_old = load_matrix<dim>(prop + L::F);
      if constexpr (small_strain)
        {
          L_p = symmetrize(grad_v);
          F   = F_old;
          return;
        }
      L_p = grad_v;
      F   = F_old + dt * grad_v * F_old;
    }
  } // namespace

  /// update_stress() with the kinematics chosen at compile time (the hot
  /// loop has no branch for it).
  template <int dim, bool small_strain>
  StressUpdateResult
  update_stress_with(const BackgroundGrid<dim>       &grid,
                     Particles::ParticleHandler<dim> &particles,
                     const std::vector<Body<dim>>    &bodies,
                     const NodalVector               &kinematics,
                     const double                     dt,
                     NodalVector                     *volume_scratch,
                     const shape_functions::DomainShapeFunctions<dim> *domains,
                     const FieldSelection                             &only,
                     const bool pressure_over_cell)
  {
    using L                       = ParticleLayout<dim>;
    constexpr unsigned int     nv = shape_functions::n_q1<dim>;
    const double              *in = kinematics.begin();
    StressUpdateResult         result;
    double                     N[nv];
    Tensor<1, dim>             G[nv];
    materials::PointKinematics pk;
    pk.dt = dt;

    remedies::VolumetricSmoothing<dim> smoothing(bodies);
    const bool                         any_node = smoothing.any_node_average();
    auto                               body_of  = [&](const double *prop) {
      return static_cast<unsigned int>(prop[L::body]);
    };

    // A rigid body (quasi-static runs) has no kinematics of its own.
    std::vector<char> rigid(bodies.size());
    bool              any_rigid = false;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      any_rigid = (rigid[b] = bodies[b].is_rigid()) || any_rigid;

    // L_p and F_p of the step, and the cell's Q1 values N at the particle
    // (for the node average). Standard MPM takes grad N of the cell; the
    // domain families their stencil. False for a bad particle domain, a
    // rigid body's particle and a particle not in the pass.
    shape_functions::Stencil<dim> stencil;
    auto                          kinematics_of = [&](const auto         &p,
                             const auto         &geo,
                             const unsigned int *nodes,
                             const unsigned int  cell_index,
                             const unsigned int  ordinal,
                             const double       *prop,
                             Tensor<2, dim>     &grad_v,
                             Tensor<2, dim> &F) __attribute__((always_inline))
    {
      if ((any_rigid && rigid[body_of(prop)]) || only.template skips<dim>(prop))
        return false;
      if (!domains)
        {
          if (any_node) // the node average's Q1 values too
            geo.values_and_gradients(p.get_reference_location(), N, G);
          else
            geo.gradients(p.get_reference_location(), G);
          step_kinematics<dim, small_strain>(
            transfer::velocity_gradient<dim>(in, nodes, G),
            prop,
            dt,
            grad_v,
            F);
          return true;
        }
      if (any_node) // the node average's Q1 values
        geo.values(p.get_reference_location(), N);
      if (!domains->evaluate(cell_index, ordinal, p, stencil, result.error))
        return false;
      step_kinematics<dim, small_strain>(
        transfer::velocity_gradient<dim>(in, stencil), prop, dt, grad_v, F);
      return true;
    };

    // One pass over the cells with particles; a domain family keeps the
    // pass's stencils for the next one.
    auto cell_pass = [&](const auto &cell_body) {
      if (domains)
        domains->begin_pass(particles.n_locally_owned_particles());
      for_each_cell_with_particles(grid, particles, cell_body);
      if (domains)
        domains->end_pass(result.error.empty());
    };

    // Node average: m, m J and m tr L of the new state to the nodes.
    if (any_node)
      {
        Assert(volume_scratch, ExcInternalError());
        NodalVector &sums = *volume_scratch;
        sums              = 0.;
        double *out       = sums.begin();
        cell_pass([&](const auto &cell, const auto &pic) {
          const auto         &geo   = grid.geometry(cell);
          const unsigned int *nodes = grid.nodes(cell);
          unsigned int        next  = 0; // the particle's place in the cell
          for (const auto &p : pic)
            {
              const unsigned int ordinal = next++;
              const double      *prop    = p.get_properties().data();
              if (smoothing.average(body_of(prop)) !=
                  remedies::VolumeAverage::node)
                continue;
              Tensor<2, dim> grad_v, F;
              if (kinematics_of(p,
                                geo,
                                nodes,
                                cell->active_cell_index(),
                                ordinal,
                                prop,
                                grad_v,
                                F))
                smoothing.add_to_nodes(out, nodes, N, prop[L::mass], grad_v, F);
            }
        });
        sums.compress(VectorOperation::add);
        sums.update_ghost_values();
      }

    // The material update of one particle with kinematics L, F (new).
    // The largest c + |v| of the cell's particles: one division per cell
    // gives the cell's stable step (h / max = min of h / each, exactly).
    double cell_fastest    = 0;
    auto   update_particle = [&](auto                 &p,
                               double               *prop,
                               const Tensor<2, dim> &grad_v,
                               const Tensor<2, dim> &F)
      __attribute__((always_inline))
    {
      const double J        = determinant(F);
      const auto  &material = *bodies[body_of(prop)].material;
      // An inverted particle stops the run on every rank (through the
      // step's collective error check), never inside the material.
      if (!(J > 0 && std::isfinite(J)))
        {
          if (result.error.empty())
            {
              std::ostringstream s;
              s << "non-positive volume (det F = " << J << ") of particle "
                << p.get_id() << " at (" << p.get_location() << ")";
              result.error = s.str();
            }
          return;
        }
      pk.velocity_gradient        = embed<dim>(grad_v, 0.);
      pk.F                        = embed<dim>(F, 1.);
      SymmetricTensor<2, 3> sigma = load_stress(prop + L::stress);
      try
        {
          material.update_stress(pk,
                                 sigma,
                                 ArrayView<double>(prop + L::history,
                                                   material.n_history()));
        }
      catch (const std::exception &e)
        {
          if (result.error.empty())
            {
              std::ostringstream s;
              s << "the material of particle " << p.get_id() << " at ("
                << p.get_location() << ") failed: " << e.what();
              result.error = s.str();
            }
          return;
        }
      store_stress(sigma, prop + L::stress);

      double speed2 = 0;
      for (unsigned int d = 0; d < dim; ++d)
        speed2 += prop[L::velocity + d] * prop[L::velocity + d];
      const double c = material.wave_speed(pk.F);
      cell_fastest   = std::max(cell_fastest, c + std::sqrt(speed2));

      // finite exactly when the norm is, without its square root
      if (!std::isfinite(sigma * sigma) && result.error.empty())
        {
          std::ostringstream s;
          s << "non-finite stress of particle " << p.get_id() << " at ("
            << p.get_location() << ")";
          result.error = s.str();
        }
    };

    const double *const node_sums =
      any_node ? volume_scratch->begin() : nullptr;

    cell_pass([&](const auto &cell, const auto &pic) {
      const auto         &geo        = grid.geometry(cell);
      const unsigned int *nodes      = grid.nodes(cell);
      const unsigned int  cell_index = cell->active_cell_index();
      cell_fastest                   = 0;
      const auto fold_stable_step    = [&]() {
        if (cell_fastest > 0)
          result.stable_time_step =
            std::min(result.stable_time_step,
                     grid.cell_height(cell) / cell_fastest);
      };
      if (smoothing.any())
        {
          typename remedies::VolumetricSmoothing<dim>::CellRate cell_rate;
          const bool                                            over_cell =
            pressure_over_cell && smoothing.any_pressure_over_cell();
          if (over_cell)
            {
              cell_rate.mean_grad_v =
                remedies::cell_mean_velocity_gradient(geo, nodes, in);
              Tensor<2, dim> step = dt * cell_rate.mean_grad_v;
              for (unsigned int d = 0; d < dim; ++d)
                step[d][d] += 1;
              cell_rate.volume_growth = determinant(step);
            }
          smoothing.update_cell(
            pic,
            nodes,
            N,
            node_sums,
            over_cell ? &cell_rate : nullptr,
            [&](const auto        &p,
                const unsigned int ordinal,
                const double      *prop,
                Tensor<2, dim>    &grad_v,
                Tensor<2, dim>    &F) __attribute__((always_inline)) {
              return kinematics_of(
                p, geo, nodes, cell_index, ordinal, prop, grad_v, F);
            },
            [&](auto                 &p,
                double               *prop,
                const Tensor<2, dim> &grad_v,
                const Tensor<2, dim> &F) __attribute__((always_inline)) {
              update_particle(p, prop, grad_v, F);
            });
          fold_stable_step();
          return;
        }
      unsigned int ordinal = 0;
      for (auto &p : pic)
        {
          double        *prop = p.get_properties().data();
          Tensor<2, dim> grad_v, F;
          if (!kinematics_of(
                p, geo, nodes, cell_index, ordinal++, prop, grad_v, F))
            continue;
          store_matrix<dim>(F, prop + L::F);
          prop[L::volume] = determinant(F) * prop[L::volume0];
          update_particle(p, prop, grad_v, F);
        }
      fold_stable_step();
    });
    return result;
  }

  template <int dim>
  StressUpdateResult
  update_stress(const BackgroundGrid<dim>       &grid,
                Particles::ParticleHandler<dim> &particles,
                const std::vector<Body<dim>>    &bodies,
                const NodalVector               &kinematics,
                const double                     dt,
                NodalVector                     *volume_scratch,
                const shape_functions::DomainShapeFunctions<dim> *domains,
                const FieldSelection                             &only,
                const bool pressure_over_cell,
                const bool small_strain)
  {
    const auto with = [&](const auto linear) {
      return update_stress_with<dim, decltype(linear)::value>(
        grid,
        particles,
        bodies,
        kinematics,
        dt,
        volume_scratch,
        domains,
        only,
        pressure_over_cell);
    };
    return small_strain ? with(std::true_type()) : with(std::false_type());
  }

  namespace
  {
    /// A particle's stability limit h/(c + |v|), with its wave speed c
    /// and its speed |v| (from the state, no update).
    struct StabilityLimit
    {
      double limit, wave_speed, speed;
    };

    template <int dim>
    StabilityLimit
    stability_limit(const double                  h,
                    const double                 *prop,
                    const std::vector<Body<dim>> &bodies)
    {
      using L   = ParticleLayout<dim>;
      double v2 = 0;
      for (unsigned int d = 0; d < dim; ++d)
        v2 += prop[L::velocity + d] * prop[L::velocity + d];
      const auto &material =
        *bodies[static_cast<unsigned int>(prop[L::body])].material;
      const double c =
        material.wave_speed(embed<dim>(load_matrix<dim>(prop + L::F), 1.));
      const double speed = std::sqrt(v2);
      return {h / (c + speed), c, speed};
    }
  } // namespace

  template <int dim>
  double
  stable_time_step(const BackgroundGrid<dim>       &grid,
                   Particles::ParticleHandler<dim> &particles,
                   const std::vector<Body<dim>>    &bodies)
  {
    double dt = std::numeric_limits<double>::max();
    for_each_cell_with_particles(
      grid, particles, [&](const auto &cell, const auto &pic) {
        const double h = grid.cell_height(cell);
        for (const auto &p : pic)
          dt = std::min(
            dt, stability_limit(h, p.get_properties().data(), bodies).limit);
      });
    return dt;
  }

  template <int dim>
  std::pair<double, std::string>
  limiting_particle(const BackgroundGrid<dim>       &grid,
                    Particles::ParticleHandler<dim> &particles,
                    const std::vector<Body<dim>>    &bodies)
  {
    using L              = ParticleLayout<dim>;
    double      smallest = std::numeric_limits<double>::infinity();
    std::string which;
    bool        found_bad = false; // the first bad particle is reported
    for_each_cell_with_particles(
      grid, particles, [&](const auto &cell, const auto &pic) {
        const double h = grid.cell_height(cell);
        for (const auto &p : pic)
          {
            if (found_bad)
              return;
            const double *prop = p.get_properties().data();
            const auto    s    = stability_limit(h, prop, bodies);
            const bool    bad  = !(s.limit > 0) || !std::isfinite(s.limit);
            if (bad || s.limit < smallest)
              {
                smallest = bad ? 0. : s.limit;
                std::ostringstream text;
                text << "particle " << p.get_id() << " of body "
                     << static_cast<unsigned int>(prop[L::body]) << " at ("
                     << p.get_location() << "): h = " << h
                     << ", wave speed c = " << s.wave_speed << ", velocity (";
                for (unsigned int d = 0; d < dim; ++d)
                  text << (d > 0 ? " " : "") << prop[L::velocity + d];
                text << "), |v| = " << s.speed << ", h/(c + |v|) = " << s.limit;
                which     = text.str();
                found_bad = bad;
              }
          }
      });
    return {smallest, which};
  }

#define MPM_INSTANTIATE(d)                                             \
  template StressUpdateResult update_stress<d>(                        \
    const BackgroundGrid<d> &,                                         \
    Particles::ParticleHandler<d> &,                                   \
    const std::vector<Body<d>> &,                                      \
    const NodalVector &,                                               \
    double,                                                            \
    NodalVector *,                                                     \
    const shape_functions::DomainShapeFunctions<d> *,                  \
    const FieldSelection &,                                            \
    bool,                                                              \
    bool);                                                             \
  template std::pair<double, std::string> limiting_particle<d>(        \
    const BackgroundGrid<d> &,                                         \
    Particles::ParticleHandler<d> &,                                   \
    const std::vector<Body<d>> &);                                     \
  template double stable_time_step<d>(const BackgroundGrid<d> &,       \
                                      Particles::ParticleHandler<d> &, \
                                      const std::vector<Body<d>> &);
  MPM_INSTANTIATE(1)
  MPM_INSTANTIATE(2)
  MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
} // namespace mpm
