#include <mpm/filters/assumed_stress.h>
#include <mpm/filters/stress_filter.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <memory>

namespace mpm
{
  namespace filters
  {
    using namespace dealii;

    template <int dim>
    unsigned int
    apply_stress_filter(const BackgroundGrid<dim>       &grid,
                        Particles::ParticleHandler<dim> &particles,
                        const std::vector<Body<dim>>    &bodies,
                        CellStressField<dim>            &field)
    {
      using L                 = ParticleLayout<dim>;
      unsigned int n_fallback = 0;
      if constexpr (dim == 1)
        {
          (void)grid, (void)particles, (void)bodies, (void)field;
          return 0;
        }
      else
        {
          // Per filtered body: metric and compliance.
          std::vector<char>                    filtered(bodies.size(), 0);
          std::vector<Metric>                  metric(bodies.size());
          std::vector<SymmetricTensor<4, dim>> compliance(bodies.size());
          for (unsigned int b = 0; b < bodies.size(); ++b)
            {
              filtered[b] = bodies[b].prm.assumed_stress_filter;
              metric[b] = bodies[b].prm.compliance_metric ? Metric::compliance :
                                                            Metric::mass;
              double E = 0, nu = 0;
              if (bodies[b].material->elastic_moduli(E, nu))
                compliance[b] = isotropic_compliance<dim>(
                  E,
                  nu,
                  bodies[b].material->kinematic_assumption() ==
                    KinematicAssumption::plane_stress);
            }

          field.clear();
          Point<dim> centre;
          for (unsigned int d = 0; d < dim; ++d)
            centre[d] = 0.5;
          std::vector<std::unique_ptr<AssumedStressProjection<dim>>> projection(
            bodies.size());
          std::vector<Tensor<2, dim>>    last_J0(bodies.size());
          std::vector<StressSample<dim>> samples;
          std::vector<double *>          targets;
          for_each_cell_with_particles(
            grid, particles, [&](const auto &cell, const auto &pic) {
              const Tensor<2, dim> J0 = grid.geometry(cell).jacobian(centre);
              for (unsigned int b = 0; b < bodies.size(); ++b)
                {
                  if (!filtered[b])
                    continue;
                  samples.clear();
                  targets.clear();
                  for (auto &p : pic)
                    {
                      double *prop = p.get_properties().data();
                      if (static_cast<unsigned int>(prop[L::body]) != b)
                        continue;
                      StressSample<dim> s;
                      s.xi     = p.get_reference_location();
                      s.weight = metric[b] == Metric::mass ? prop[L::mass] :
                                                             prop[L::volume];
                      const auto sigma = load_stress(prop + L::stress);
                      for (unsigned int i = 0; i < dim; ++i)
                        for (unsigned int j = i; j < dim; ++j)
                          s.stress[i][j] = sigma[i][j];
                      samples.push_back(s);
                      targets.push_back(prop + L::stress);
                    }
                  if (samples.empty())
                    continue;
                  // Cells of a uniform grid share J0: build the projection
                  // only when the geometry changes.
                  if (!projection[b] || !(J0 == last_J0[b]))
                    {
                      projection[b] =
                        std::make_unique<AssumedStressProjection<dim>>(
                          J0, metric[b], compliance[b]);
                      last_J0[b] = J0;
                    }
                  const auto &P = *projection[b];
                  double      beta[AssumedStressProjection<dim>::n_beta];
                  const auto  result = P.project(samples, beta);
                  if (result != AssumedStressProjection<dim>::Result::full)
                    ++n_fallback;
                  if (result ==
                      AssumedStressProjection<dim>::Result::unchanged)
                    continue;
                  std::copy(beta,
                            beta + AssumedStressProjection<dim>::n_beta,
                            field.store(b, cell->active_cell_index()));
                  for (unsigned int k = 0; k < samples.size(); ++k)
                    {
                      SymmetricTensor<2, 3> sigma = load_stress(targets[k]);
                      for (unsigned int i = 0; i < dim; ++i)
                        for (unsigned int j = i; j < dim; ++j)
                          sigma[i][j] = samples[k].stress[i][j];
                      store_stress(sigma, targets[k]);
                    }
                }
            });
        }
      return n_fallback;
    }

    template unsigned int
    apply_stress_filter<1>(const BackgroundGrid<1> &,
                           Particles::ParticleHandler<1> &,
                           const std::vector<Body<1>> &,
                           CellStressField<1> &);
    template unsigned int
    apply_stress_filter<2>(const BackgroundGrid<2> &,
                           Particles::ParticleHandler<2> &,
                           const std::vector<Body<2>> &,
                           CellStressField<2> &);
    template unsigned int
    apply_stress_filter<3>(const BackgroundGrid<3> &,
                           Particles::ParticleHandler<3> &,
                           const std::vector<Body<3>> &,
                           CellStressField<3> &);
  } // namespace filters
} // namespace mpm
