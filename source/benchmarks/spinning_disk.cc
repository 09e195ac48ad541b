#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/benchmarks/global_sums.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    namespace
    {
      const BenchmarkDeclaration declaration{
        "spinning disk",
        "plane-stress disk of radius a spinning at omega about the origin "
        "in its steady state, sigma_rr and sigma_tt fixed in polar "
        "components",
        {required_constant("a", "radius of the disk [m]"),
         required_constant("omega", "angular velocity [1/s]"),
         required_constant("nu", "Poisson's ratio"),
         required_constant("rho", "density [kg/m^3]")},
        {"sigma_rr_rms_error", "sigma_rt_rms", "v_r_rms"}};

      /**
       * Spinning disk (doc/benchmarks/spinning_disk.md): a plane-stress disk of
       * radius a spinning at omega about the origin in its steady state.
       * Columns: mass-weighted RMS of (sigma_rr - exact)/sigma0, RMS
       * sigma_rt/sigma0 and RMS radial velocity/(omega a), with
       * sigma0 = rho omega^2 (3+nu) a^2/8 and polar components taken at
       * the particle's current position.
       */
      template <int dim>
      class SpinningDisk : public Benchmark<dim>
      {
      public:
        explicit SpinningDisk(const BenchmarkConstants &c)
          : Benchmark<dim>(declaration.columns)
          , a(c["a"])
          , omega(c["omega"])
          , nu(c["nu"])
          , rho(c["rho"])
          , sigma0(rho * omega * omega * (3 + nu) * a * a / 8)
        {}

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double,
                const MPI_Comm comm) const override
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
              const double  c = r > 0 ? x[0] / r : 1.,
                           sn = r > 0 ? x[1] / r : 0.;
              // polar components of the Cartesian stress (xx yy zz yz xz xy)
              const double srr =
                c * c * s[0] + sn * sn * s[1] + 2 * c * sn * s[5];
              const double srt =
                (s[1] - s[0]) * c * sn + (c * c - sn * sn) * s[5];
              const double vr = c * v[0] + sn * v[1];
              const double exact =
                rho * omega * omega / 8 * (3 + nu) * (a * a - r * r);
              local[0] += m;
              local[1] += m * (srr - exact) * (srr - exact);
              local[2] += m * srt * srt;
              local[3] += m * vr * vr;
            }
          const auto g = global_sums(local, comm);
          return {std::sqrt(g[1] / g[0]) / sigma0,
                  std::sqrt(g[2] / g[0]) / sigma0,
                  std::sqrt(g[3] / g[0]) / (omega * a)};
        }

      private:
        double a, omega, nu, rho, sigma0;
      };
    } // namespace

    MPM_REGISTER_BENCHMARK(SpinningDisk, declaration, 2)
  } // namespace benchmarks
} // namespace mpm
