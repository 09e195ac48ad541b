#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/benchmarks/checkerboard.h>
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
        "thick cylinder",
        "thick-walled cylinder under internal pressure, plane strain (the "
        "Lame problem)",
        {required_constant("a", "inner radius [m]"),
         required_constant("b", "outer radius [m]"),
         required_constant("p", "inner pressure [Pa]"),
         required_constant("E", "Young's modulus [Pa]"),
         required_constant("nu", "Poisson's ratio")},
        {"ur_inner_ratio", "pressure_error", "sigma_rr_error", "checkerboard"}};

      /**
       * Thick-walled cylinder under internal pressure (the Lame problem),
       * plane strain, linear elastic: inner radius a, outer radius b,
       * inner pressure p, modulus E, Poisson's ratio nu, centred at the
       * origin. Its incompressible limit deforms (u_r = C/r), so unlike
       * the self-weight column it shows volumetric locking. Exact static
       * state at the material radius R, with k = p a^2/(b^2 - a^2):
       *   u_r = (1+nu) k/E ((1-2nu) R + b^2/R),
       *   sigma_rr = k (1 - b^2/R^2), sigma_tt = k (1 + b^2/R^2),
       *   sigma_zz = nu (sigma_rr + sigma_tt), so the pressure is constant.
       * Polar components along the material direction X/|X|. Columns:
       * - ur_inner_ratio: mass-weighted mean u_r of the particles with
       *   R < a + (b-a)/8 over the exact mean at the same particles (a
       *   locked solution is too stiff: ratio < 1);
       * - pressure_error, sigma_rr_error: sum_p |e_p| V_p / (p sum_p V_p);
       * - checkerboard: as in the self-weight column, of the pressure
       *   error, / p.
       */
      template <int dim>
      class ThickCylinder : public Benchmark<dim>
      {
      public:
        explicit ThickCylinder(const BenchmarkConstants &c)
          : Benchmark<dim>(declaration.columns)
          , a(c["a"])
          , b(c["b"])
          , p(c["p"])
          , E(c["E"])
          , nu(c["nu"])
        {}

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double,
                const MPI_Comm comm) const override
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
                  local[4] +=
                    m * (1 + nu) * k / E * ((1 - 2 * nu) * R + b * b / R);
                }
            }
          const auto sum = global_sums(local, comm);
          return {sum[4] != 0 ? sum[3] / sum[4] : std::nan(""),
                  sum[1] / (sum[0] * p),
                  sum[2] / (sum[0] * p),
                  checkerboard(particles, pressure_error, comm) / p};
        }

      private:
        double a, b, p, E, nu;
      };
    } // namespace

    MPM_REGISTER_BENCHMARK(ThickCylinder, declaration, 2)
  } // namespace benchmarks
} // namespace mpm
