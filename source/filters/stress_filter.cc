#include <mpm/filters/stress_filter.h>
#include <mpm/particles/cell_loop.h>

namespace mpm
{
  namespace filters
  {
    using namespace dealii;

    template <int dim>
    StressFilter<dim>::StressFilter(const std::vector<Body<dim>> &bodies)
      : is_filtered(bodies.size(), 0)
      , any_filtered(false)
      , metric(bodies.size(), Metric::mass)
      , compliance(bodies.size())
      , projections(bodies.size())
      , last_J0(bodies.size())
    {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          is_filtered[b] = bodies[b].prm.assumed_stress_filter;
          any_filtered   = any_filtered || is_filtered[b];
          metric[b] =
            bodies[b].prm.compliance_metric ? Metric::compliance : Metric::mass;
          double E = 0, nu = 0;
          if constexpr (dim > 1)
            if (bodies[b].material->elastic_moduli(E, nu))
              compliance[b] = isotropic_compliance<dim>(
              E,
              nu,
              bodies[b].material->kinematic_assumption() ==
                KinematicAssumption::plane_stress);
        }
    }

    template <int dim>
    typename StressFilter<dim>::Result
    StressFilter<dim>::project(const shape_functions::Q1Cell<dim> &geo,
                               const unsigned int                  b,
                               double                             *beta)
    {
      if constexpr (dim == 1)
        {
          // no assumed-stress field in 1D (the parameters refuse it)
          (void)geo, (void)b, (void)beta;
          return Result::unchanged;
        }
      else
      {
      if (samples.empty())
        return Result::unchanged;
      Point<dim> centre;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = 0.5;
      // Cells of a uniform grid share J0: build the projection only when
      // the geometry changes.
      const Tensor<2, dim> J0 = geo.jacobian(centre);
      if (!projections[b] || !(J0 == last_J0[b]))
        {
          projections[b] = std::make_unique<AssumedStressProjection<dim>>(
            J0, metric[b], compliance[b]);
          last_J0[b] = J0;
        }
      const Result result = projections[b]->project(samples, beta);
      if (result != Result::full)
        ++n_fallbacks;
      if (result == Result::unchanged)
        return result;
      for (unsigned int k = 0; k < samples.size(); ++k)
        {
          double     *v = targets[k];
          const auto &s = samples[k].stress;
          v[0]          = s[0][0];
          v[1]          = s[1][1];
          v[5]          = s[0][1];
          if constexpr (dim == 3)
            {
              v[2] = s[2][2];
              v[3] = s[1][2];
              v[4] = s[0][2];
            }
        }
      return result;
      }
    }

    template <int dim>
    void
    StressFilter<dim>::apply(const BackgroundGrid<dim>       &grid,
                             Particles::ParticleHandler<dim> &particles)
    {
      if (!any_filtered)
        return;
      double beta[n_beta];
      for_each_cell_with_particles(
        grid, particles, [&](const auto &cell, const auto &pic) {
          for (unsigned int b = 0; b < is_filtered.size(); ++b)
            if (is_filtered[b])
              filter_cell(grid.geometry(cell), pic, b, beta);
        });
    }

    template class StressFilter<1>;
    template class StressFilter<2>;
    template class StressFilter<3>;
  } // namespace filters
} // namespace mpm
