#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/checkerboard.h>
#include <mpm/benchmarks/thick_cylinder.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    template <int dim>
    ThickCylinder<dim>::ThickCylinder(const double a,
                                      const double b,
                                      const double p,
                                      const double E,
                                      const double nu)
      : a(a)
      , b(b)
      , p(p)
      , E(E)
      , nu(nu)
    {}

    template <int dim>
    std::vector<std::string>
    ThickCylinder<dim>::columns() const
    {
      return {"ur_inner_ratio",
              "pressure_error",
              "sigma_rr_error",
              "checkerboard"};
    }

    template <int dim>
    std::vector<double>
    ThickCylinder<dim>::measure(Particles::ParticleHandler<dim> &particles,
                                const double,
                                const MPI_Comm comm) const
    {
      using L        = ParticleLayout<dim>;
      const double k = p * a * a / (b * b - a * a);
      // the exact pressure -(1+nu)(sigma_rr + sigma_tt)/3 is uniform
      const double p_ex           = -(1 + nu) * 2 * k / 3;
      auto         pressure_error = [&](const double *prop) {
        const double *s = prop + L::stress;
        return -(s[0] + s[1] + s[2]) / 3 - p_ex;
      };
      // totals: V, |p error| V, |sigma_rr error| V, m u_r and m u_r exact
      // of the inner particles
      double local[5] = {};
      for (const auto &particle : particles)
        {
          const double *prop = particle.get_properties().data();
          const double  V    = prop[L::volume];
          const double  X = prop[L::X], Y = prop[L::X + 1];
          const double  R = std::hypot(X, Y), c = X / R, s = Y / R;
          const double *sig = prop + L::stress;
          // xx yy zz yz xz xy
          const double srr =
            c * c * sig[0] + s * s * sig[1] + 2 * c * s * sig[5];
          local[0] += V;
          local[1] += std::abs(pressure_error(prop)) * V;
          local[2] += std::abs(srr - k * (1 - b * b / (R * R))) * V;
          if (R < a + (b - a) / 8)
            {
              const auto   x  = particle.get_location();
              const double ur = c * (x[0] - X) + s * (x[1] - Y);
              const double m  = prop[L::mass];
              local[3] += m * ur;
              local[4] += m * (1 + nu) * k / E * ((1 - 2 * nu) * R + b * b / R);
            }
        }
      double sum[5];
      Utilities::MPI::sum(ArrayView<const double>(local, 5),
                          comm,
                          ArrayView<double>(sum, 5));
      return {sum[4] != 0 ? sum[3] / sum[4] : std::nan(""),
              sum[1] / (sum[0] * p),
              sum[2] / (sum[0] * p),
              checkerboard(particles, pressure_error, comm) / p};
    }

    template class ThickCylinder<2>;
  } // namespace benchmarks
} // namespace mpm
