#include <mpm/remedies/volumetric_smoothing.h>
#include <mpm/grid/grid_update.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/solver/stress_update.h>
#include <mpm/transfer/velocity_gradient.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mpm
{
  using namespace dealii;

  namespace
  {
    /// Nodal sums of the node-smoothed particles: m, m J, m tr L.
    constexpr unsigned int n_volume_components = 3;

    /// The step's kinematics of the particle with properties @p prop:
    /// L_p = @p grad_v and F = (I + dt L) F_old.
    template <int dim>
    struct StepKinematics
    {
      Tensor<2, dim> grad_v, F;
    };

    template <int dim>
    inline StepKinematics<dim>
    step_kinematics(const Tensor<2, dim> &grad_v,
                    const double         *prop,
                    const double          dt)
    {
      using L                    = ParticleLayout<dim>;
      const Tensor<2, dim> F_old = load_matrix<dim>(prop + L::F);
      return {grad_v, F_old + dt * grad_v * F_old};
    }

    /// Per-body sums of one cell for the cell average.
    struct CellVolumeSums
    {
      double V0 = 0, V = 0, V_old = 0, V_old_trL = 0;
    };
  } // namespace

  template <int dim>
  StressUpdateResult
  update_stress(const BackgroundGrid<dim>       &grid,
                Particles::ParticleHandler<dim> &particles,
                const std::vector<Body<dim>>    &bodies,
                const NodalVector               &kinematics,
                const double                     dt,
                NodalVector                     *volume_scratch,
                const shape_functions::DomainShapeFunctions<dim> *domains)
  {
    using L                       = ParticleLayout<dim>;
    using Smoothing               = remedies::VolumetricSmoothing;
    constexpr unsigned int     nv = shape_functions::n_q1<dim>;
    const double              *in = kinematics.begin();
    StressUpdateResult         result;
    double                     N[nv];
    Tensor<1, dim>             G[nv];
    materials::PointKinematics pk;
    pk.dt = dt;

    std::vector<Smoothing> smoothing(bodies.size());
    bool                   any_cell = false, any_node = false;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        smoothing[b] = bodies[b].prm.volumetric_smoothing;
        any_cell     = any_cell || smoothing[b] == Smoothing::cell;
        any_node     = any_node || smoothing[b] == Smoothing::node;
      }
    auto body_of = [&](const double *prop) {
      return static_cast<unsigned int>(prop[L::body]);
    };

    // L_p and F_p of the step, and the cell's Q1 values N at the particle
    // (for the node average). Standard MPM takes grad N of the cell; the
    // domain families their stencil. False for a bad particle domain.
    shape_functions::Stencil<dim> stencil;
    auto                          kinematics_of = [&](const auto          &p,
                             const auto          &geo,
                             const unsigned int  *nodes,
                             const unsigned int   cell_index,
                             const unsigned int   ordinal,
                             const double        *prop,
                             StepKinematics<dim> &k) {
      if (!domains)
        {
          geo.values_and_gradients(p.get_reference_location(), N, G);
          k =
            step_kinematics<dim>(transfer::velocity_gradient<dim>(in, nodes, G),
                                 prop,
                                 dt);
          return true;
        }
      if (any_node) // the node average's Q1 values
        geo.values(p.get_reference_location(), N);
      if (!domains->evaluate(cell_index, ordinal, p, stencil, result.error))
        return false;
      k = step_kinematics<dim>(transfer::velocity_gradient<dim>(in, stencil),
                               prop,
                               dt);
      return true;
    };

    // Node average: m, m J and m tr L of the new state to the nodes.
    if (any_node)
      {
        Assert(volume_scratch, ExcInternalError());
        NodalVector &sums = *volume_scratch;
        sums              = 0.;
        double *out       = sums.begin();
        if (domains)
          domains->begin_pass(particles.n_locally_owned_particles());
        for_each_cell_with_particles(
          grid, particles, [&](const auto &cell, const auto &pic) {
            const auto         &geo   = grid.geometry(cell);
            const unsigned int *nodes = grid.nodes(cell);
            unsigned int        next  = 0; // the particle's place in the cell
            for (const auto &p : pic)
              {
                const unsigned int ordinal = next++;
                const double      *prop    = p.get_properties().data();
                if (smoothing[body_of(prop)] != Smoothing::node)
                  continue;
                StepKinematics<dim> k;
                if (!kinematics_of(p,
                                   geo,
                                   nodes,
                                   cell->active_cell_index(),
                                   ordinal,
                                   prop,
                                   k))
                  continue;
                const auto &[grad_v, F] = k;
                const double J          = determinant(F);
                const double m          = prop[L::mass];
                for (unsigned int v = 0; v < nv; ++v)
                  {
                    double *node = out + nodes[v] * n_volume_components;
                    node[0] += N[v] * m;
                    node[1] += N[v] * m * J;
                    node[2] += N[v] * m * trace(grad_v);
                  }
              }
          });
        if (domains)
          domains->end_pass(result.error.empty());
        sums.compress(VectorOperation::add);
        sums.update_ghost_values();
      }

    // The material update of one particle with kinematics L, F (new).
    auto update_particle = [&](auto                 &p,
                               double               *prop,
                               const double          h,
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
      result.stable_time_step =
        std::min(result.stable_time_step, h / (c + std::sqrt(speed2)));

      if (!std::isfinite(sigma.norm()) && result.error.empty())
        {
          std::ostringstream s;
          s << "non-finite stress of particle " << p.get_id() << " at ("
            << p.get_location() << ")";
          result.error = s.str();
        }
    };

    // Models whose state is J alone (the fluid) keep the smoothed volume
    // (Material::state_is_volume_ratio).
    auto keep_smoothed_volume = [&](double *prop, const Tensor<2, dim> &F) {
      if (bodies[body_of(prop)].material->state_is_volume_ratio())
        {
          store_matrix<dim>(F, prop + L::F);
          prop[L::volume] = determinant(F) * prop[L::volume0];
        }
    };

    // Kinematics of the cell's particles, kept while the cell averages
    // are summed.
    struct Buffered
    {
      Tensor<2, dim> grad_v, F;
    };
    std::vector<Buffered>       buffer;
    std::vector<CellVolumeSums> cell_sums(bodies.size());
    const double *const         volume_sums =
      any_node ? volume_scratch->begin() : nullptr;

    if (domains)
      domains->begin_pass(particles.n_locally_owned_particles());
    for_each_cell_with_particles(
      grid, particles, [&](const auto &cell, const auto &pic) {
        const auto         &geo   = grid.geometry(cell);
        const unsigned int *nodes = grid.nodes(cell);
        const double        h     = grid.cell_height(cell);
        if (!any_cell && !any_node)
          {
            // no smoothing: one pass
            unsigned int ordinal = 0;
            for (auto &p : pic)
              {
                double             *prop = p.get_properties().data();
                StepKinematics<dim> k;
                if (!kinematics_of(p,
                                   geo,
                                   nodes,
                                   cell->active_cell_index(),
                                   ordinal++,
                                   prop,
                                   k))
                  continue;
                const auto &[grad_v, F] = k;
                store_matrix<dim>(F, prop + L::F);
                prop[L::volume] = determinant(F) * prop[L::volume0];
                update_particle(p, prop, h, grad_v, F);
              }
            return;
          }
        buffer.clear();
        if (any_cell)
          std::fill(cell_sums.begin(), cell_sums.end(), CellVolumeSums());
        unsigned int ordinal = 0;
        for (auto &p : pic)
          {
            double             *prop = p.get_properties().data();
            StepKinematics<dim> k;
            if (!kinematics_of(
                  p, geo, nodes, cell->active_cell_index(), ordinal++, prop, k))
              {
                // keep the cell average's bookkeeping in step
                if (smoothing[body_of(prop)] == Smoothing::cell)
                  buffer.push_back(
                    {Tensor<2, dim>(), load_matrix<dim>(prop + L::F)});
                continue;
              }
            auto &[grad_v, F] = k;
            store_matrix<dim>(F, prop + L::F);
            const double J      = determinant(F);
            const double V_old  = prop[L::volume];
            prop[L::volume]     = J * prop[L::volume0];
            const Smoothing how = smoothing[body_of(prop)];
            if (how == Smoothing::none)
              update_particle(p, prop, h, grad_v, F);
            else if (how == Smoothing::node)
              {
                // J and tr L interpolated from the nodal mass averages
                double m = 0, mJ = 0, mtr = 0;
                for (unsigned int v = 0; v < nv; ++v)
                  {
                    const double *node =
                      volume_sums + nodes[v] * n_volume_components;
                    if (node[0] > 0)
                      {
                        m += N[v];
                        mJ += N[v] * node[1] / node[0];
                        mtr += N[v] * node[2] / node[0];
                      }
                  }
                if (m > 0 && J > 0)
                  {
                    remedies::smooth_volume_change<dim>(
                      grad_v, F, J, mJ / m, mtr / m);
                    keep_smoothed_volume(prop, F);
                  }
                update_particle(p, prop, h, grad_v, F);
              }
            else
              {
                auto &sum = cell_sums[body_of(prop)];
                sum.V0 += prop[L::volume0];
                sum.V += prop[L::volume];
                sum.V_old += V_old;
                sum.V_old_trL += V_old * trace(grad_v);
                buffer.push_back({grad_v, F});
              }
          }
        if (buffer.empty())
          return;
        // Cell average: J_bar = sum V / sum V0, theta_bar = sum V tr L /
        // sum V (volumes before the step), per body.
        unsigned int k = 0;
        for (auto &p : pic)
          {
            double *prop = p.get_properties().data();
            if (smoothing[body_of(prop)] != Smoothing::cell)
              continue;
            auto &[grad_v, F] = buffer[k++];
            const auto  &sum  = cell_sums[body_of(prop)];
            const double J    = determinant(F);
            if (J > 0)
              {
                remedies::smooth_volume_change<dim>(
                  grad_v, F, J, sum.V / sum.V0, sum.V_old_trL / sum.V_old);
                keep_smoothed_volume(prop, F);
              }
            update_particle(p, prop, h, grad_v, F);
          }
      });
    if (domains)
      domains->end_pass(result.error.empty());
    return result;
  }

  template <int dim>
  double
  stable_time_step(const BackgroundGrid<dim>       &grid,
                   Particles::ParticleHandler<dim> &particles,
                   const std::vector<Body<dim>>    &bodies)
  {
    using L   = ParticleLayout<dim>;
    double dt = std::numeric_limits<double>::max();
    for_each_cell_with_particles(
      grid, particles, [&](const auto &cell, const auto &pic) {
        const double h = grid.cell_height(cell);
        for (const auto &p : pic)
          {
            const double *prop = p.get_properties().data();
            double        v2   = 0;
            for (unsigned int d = 0; d < dim; ++d)
              v2 += prop[L::velocity + d] * prop[L::velocity + d];
            const auto &material =
              *bodies[static_cast<unsigned int>(prop[L::body])].material;
            const double c = material.wave_speed(
              embed<dim>(load_matrix<dim>(prop + L::F), 1.));
            dt = std::min(dt, h / (c + std::sqrt(v2)));
          }
      });
    return dt;
  }

  template StressUpdateResult
  update_stress<1>(const BackgroundGrid<1> &,
                   Particles::ParticleHandler<1> &,
                   const std::vector<Body<1>> &,
                   const NodalVector &,
                   double,
                   NodalVector *,
                   const shape_functions::DomainShapeFunctions<1> *);
  template StressUpdateResult
  update_stress<2>(const BackgroundGrid<2> &,
                   Particles::ParticleHandler<2> &,
                   const std::vector<Body<2>> &,
                   const NodalVector &,
                   double,
                   NodalVector *,
                   const shape_functions::DomainShapeFunctions<2> *);
  template StressUpdateResult
  update_stress<3>(const BackgroundGrid<3> &,
                   Particles::ParticleHandler<3> &,
                   const std::vector<Body<3>> &,
                   const NodalVector &,
                   double,
                   NodalVector *,
                   const shape_functions::DomainShapeFunctions<3> *);
  template double
  stable_time_step<1>(const BackgroundGrid<1> &,
                      Particles::ParticleHandler<1> &,
                      const std::vector<Body<1>> &);
  template double
  stable_time_step<2>(const BackgroundGrid<2> &,
                      Particles::ParticleHandler<2> &,
                      const std::vector<Body<2>> &);
  template double
  stable_time_step<3>(const BackgroundGrid<3> &,
                      Particles::ParticleHandler<3> &,
                      const std::vector<Body<3>> &);
} // namespace mpm
