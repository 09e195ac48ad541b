#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/checkerboard.h>
#include <mpm/benchmarks/water_column.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>
#include <limits>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    template <int dim>
    WaterColumn<dim>::WaterColumn(const double a,
                                  const double g,
                                  const double rho,
                                  const double wall_band)
      : a(a)
      , g(g)
      , rho(rho)
      , wall_band(wall_band)
    {}

    template <int dim>
    std::vector<std::string>
    WaterColumn<dim>::columns() const
    {
      return {
        "x_front", "height", "T", "Z", "tau", "H", "checkerboard", "max_speed"};
    }

    template <int dim>
    std::vector<double>
    WaterColumn<dim>::measure(Particles::ParticleHandler<dim> &particles,
                              const double                     time,
                              const MPI_Comm                   comm) const
    {
      using L = ParticleLayout<dim>;
      // local maxima: front, height at the wall, speed
      double local[3] = {-std::numeric_limits<double>::max(), 0., 0.};
      for (const auto &p : particles)
        {
          const double *prop = p.get_properties().data();
          const double  half = 0.5 * std::pow(prop[L::volume], 1. / dim);
          const auto    x    = p.get_location();
          local[0]           = std::max(local[0], x[0] + half);
          double v2          = 0;
          for (unsigned int d = 0; d < dim; ++d)
            v2 += prop[L::velocity + d] * prop[L::velocity + d];
          local[2] = std::max(local[2], std::sqrt(v2));
          if (x[0] < wall_band)
            local[1] = std::max(local[1], x[1] + half);
        }
      double global[3];
      Utilities::MPI::max(ArrayView<const double>(local, 3),
                          comm,
                          ArrayView<double>(global, 3));
      const double head       = rho * g * 2 * a;
      auto p_less_hydrostatic = [&](const double *prop, const Point<dim> &x) {
        const double *s = prop + L::stress;
        return -(s[0] + s[1] + s[2]) / 3 + rho * g * x[1];
      };
      const double cb =
        checkerboard_with_position<dim>(particles, p_less_hydrostatic, comm);
      return {global[0],
              global[1],
              time * std::sqrt(2 * g / a),
              global[0] / a,
              time * std::sqrt(g / a),
              global[1] / (2 * a),
              cb / head,
              global[2]};
    }

    template class WaterColumn<2>;
    template class WaterColumn<3>;
  } // namespace benchmarks
} // namespace mpm
