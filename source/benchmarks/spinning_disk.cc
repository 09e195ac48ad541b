#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/benchmark.h>
#include <mpm/benchmarks/spinning_disk.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    template <int dim>
    SpinningDisk<dim>::SpinningDisk(const double a,
                                    const double omega,
                                    const double nu,
                                    const double rho)
      : a(a)
      , omega(omega)
      , nu(nu)
      , rho(rho)
      , sigma0(rho * omega * omega * (3 + nu) * a * a / 8)
    {}

    template <int dim>
    std::vector<std::string>
    SpinningDisk<dim>::columns() const
    {
      return {"sigma_rr_rms_error", "sigma_rt_rms", "v_r_rms"};
    }

    template <int dim>
    std::vector<double>
    SpinningDisk<dim>::measure(Particles::ParticleHandler<dim> &particles,
                               const double,
                               const MPI_Comm comm) const
    {
      using L         = ParticleLayout<dim>;
      double local[4] = {};
      for (const auto &p : particles)
        {
          const double *s = p.get_properties().data() + L::stress;
          const double *v = p.get_properties().data() + L::velocity;
          const double  m = p.get_properties()[L::mass];
          const auto    x = p.get_location();
          const double  r = x.norm();
          const double  c = r > 0 ? x[0] / r : 1., sn = r > 0 ? x[1] / r : 0.;
          // polar components of the Cartesian stress (xx yy zz yz xz xy)
          const double srr = c * c * s[0] + sn * sn * s[1] + 2 * c * sn * s[5];
          const double srt = (s[1] - s[0]) * c * sn + (c * c - sn * sn) * s[5];
          const double vr  = c * v[0] + sn * v[1];
          const double exact =
            rho * omega * omega / 8 * (3 + nu) * (a * a - r * r);
          local[0] += m;
          local[1] += m * (srr - exact) * (srr - exact);
          local[2] += m * srt * srt;
          local[3] += m * vr * vr;
        }
      double g[4];
      Utilities::MPI::sum(ArrayView<const double>(local, 4),
                          comm,
                          ArrayView<double>(g, 4));
      return {std::sqrt(g[1] / g[0]) / sigma0,
              std::sqrt(g[2] / g[0]) / sigma0,
              std::sqrt(g[3] / g[0]) / (omega * a)};
    }

    template class SpinningDisk<2>;
  } // namespace benchmarks
} // namespace mpm
