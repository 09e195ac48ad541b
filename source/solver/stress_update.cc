#include <mpm/grid/grid_update.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/solver/stress_update.h>

#include <cmath>
#include <sstream>

namespace mpm
{
  using namespace dealii;

  template <int dim>
  StressUpdateResult
  update_stress(const BackgroundGrid<dim>       &grid,
                Particles::ParticleHandler<dim> &particles,
                const std::vector<Body<dim>>    &bodies,
                const NodalVector               &kinematics,
                const double                     dt)
  {
    using L                       = ParticleLayout<dim>;
    using K                       = KinematicsLayout<dim>;
    constexpr unsigned int     nv = shape_functions::n_q1<dim>;
    const double              *in = kinematics.begin();
    StressUpdateResult         result;
    double                     N[nv];
    Tensor<1, dim>             G[nv];
    materials::PointKinematics pk;
    pk.dt = dt;
    for_each_cell_with_particles(
      grid, particles, [&](const auto &cell, const auto &pic) {
        const auto         &geo   = grid.geometry(cell);
        const unsigned int *nodes = grid.nodes(cell);
        const double        h     = grid.cell_height(cell);
        for (auto &p : pic)
          {
            geo.values_and_gradients(p.get_reference_location(), N, G);
            Tensor<2, dim> grad_v;
            for (unsigned int v = 0; v < nv; ++v)
              {
                const double *k = in + nodes[v] * K::n_components;
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = 0; j < dim; ++j)
                    grad_v[i][j] += k[K::velocity + i] * G[v][j];
              }
            double              *prop  = p.get_properties().data();
            const Tensor<2, dim> F_old = load_matrix<dim>(prop + L::F);
            Tensor<2, dim>       F     = F_old + dt * grad_v * F_old;
            store_matrix<dim>(F, prop + L::F);
            const double J  = determinant(F);
            prop[L::volume] = J * prop[L::volume0];

            const auto &material =
              *bodies[static_cast<unsigned int>(prop[L::body])].material;
            // An inverted particle stops the run on every rank (through the
            // step's collective error check), never inside the material.
            if (!(J > 0 && std::isfinite(J)))
              {
                if (result.error.empty())
                  {
                    std::ostringstream s;
                    s << "non-positive volume (det F = " << J
                      << ") of particle " << p.get_id() << " at ("
                      << p.get_location() << ")";
                    result.error = s.str();
                  }
                continue;
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
                continue;
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
          }
      });
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
    for (const auto &cell : grid.triangulation().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const double h = grid.cell_height(cell);
        for (const auto &p : particles.particles_in_cell(cell))
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
      }
    return dt;
  }

  template StressUpdateResult
  update_stress<1>(const BackgroundGrid<1> &,
                   Particles::ParticleHandler<1> &,
                   const std::vector<Body<1>> &,
                   const NodalVector &,
                   double);
  template StressUpdateResult
  update_stress<2>(const BackgroundGrid<2> &,
                   Particles::ParticleHandler<2> &,
                   const std::vector<Body<2>> &,
                   const NodalVector &,
                   double);
  template StressUpdateResult
  update_stress<3>(const BackgroundGrid<3> &,
                   Particles::ParticleHandler<3> &,
                   const std::vector<Body<3>> &,
                   const NodalVector &,
                   double);
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
