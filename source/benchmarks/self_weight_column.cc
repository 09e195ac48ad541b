#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/checkerboard.h>
#include <mpm/benchmarks/self_weight_column.h>
#include <mpm/particles/particle_layout.h>

#include <array>
#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    template <int dim>
    SelfWeightColumn<dim>::SelfWeightColumn(const double height,
                                            const double rho,
                                            const double g,
                                            const double nu)
      : height(height)
      , rho(rho)
      , g(g)
      , nu(nu)
    {}

    template <int dim>
    std::vector<std::string>
    SelfWeightColumn<dim>::columns() const
    {
      return {"sigma_yy_error", "pressure_error", "checkerboard"};
    }

    template <int dim>
    std::vector<double>
    SelfWeightColumn<dim>::measure(Particles::ParticleHandler<dim> &particles,
                                   const double,
                                   const MPI_Comm comm) const
    {
      using L = ParticleLayout<dim>;
      // exact stresses at the material coordinate Y: xx, yy, zz
      auto exact = [&](const double *prop) {
        const double yy = -rho * g * (height - prop[L::X + 1]);
        const double xx = nu / (1 - nu) * yy;
        return std::array<double, 3>{{xx, yy, dim == 2 ? nu * (xx + yy) : xx}};
      };
      auto pressure_error = [&](const double *prop) {
        const auto    e    = exact(prop);
        const double *s    = prop + L::stress;
        const double  p_ex = -(e[0] + e[1] + e[2]) / 3;
        const double  p_mp = -(s[0] + s[1] + s[2]) / 3;
        return p_mp - p_ex;
      };
      // totals: V, |yy error| V, |p error| V
      double local[3] = {};
      for (const auto &p : particles)
        {
          const double *prop = p.get_properties().data();
          const double  V    = prop[L::volume];
          local[0] += V;
          local[1] += std::abs(prop[L::stress + 1] - exact(prop)[1]) * V;
          local[2] += std::abs(pressure_error(prop)) * V;
        }
      double sum[3];
      Utilities::MPI::sum(ArrayView<const double>(local, 3),
                          comm,
                          ArrayView<double>(sum, 3));
      const double scale = rho * g * height;
      return {sum[1] / (sum[0] * scale),
              sum[2] / (sum[0] * scale),
              checkerboard(particles, pressure_error, comm) / scale};
    }

    template class SelfWeightColumn<2>;
    template class SelfWeightColumn<3>;
  } // namespace benchmarks
} // namespace mpm
