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
        "convecting bar",
        "a stressed bar in quasi-static equilibrium with the body force "
        "b0 cos(pi (X - x0)/L) per unit length, convected at v0",
        {required_constant("L", "length of the bar [m]"),
         required_constant("A", "cross-section [m^2]"),
         required_constant("b0", "body-force amplitude per unit length [N/m]"),
         required_constant("v0", "velocity of the bar [m/s]"),
         required_constant("x0", "x of the left end at t = 0 [m]")},
        {"sigma_rms_error", "v_rms_error"}};

      /**
       * Convecting bar (doc/benchmarks/convecting_bar.md): a bar of length L
       * and cross-section A in quasi-static equilibrium with the body force
       * b0 cos(pi xi) per unit length, xi = (X - x0)/L, convected at v0.
       * Exact: sigma_xx = -sigma0 sin(pi xi), sigma0 = b0 L/(pi A), and
       * v = v0. Columns: the mass-weighted RMS of (sigma_xx - exact)/sigma0
       * and of (v_x - v0)/v0 (in m/s if v0 = 0); x components, so a 2D strip
       * is measured the same way.
       */
      template <int dim>
      class ConvectingBar : public Benchmark<dim>
      {
      public:
        explicit ConvectingBar(const BenchmarkConstants &c)
          : Benchmark<dim>(declaration.columns)
          , length(c["L"])
          , sigma0(c["b0"] * length / (M_PI * c["A"]))
          , v0(c["v0"])
          , x0(c["x0"])
        {}

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double,
                const MPI_Comm comm) const override
        {
          using L         = ParticleLayout<dim>;
          double local[3] = {};
          for (const auto &p : particles)
            {
              const double *prop = p.get_properties().data();
              const double  m    = prop[L::mass];
              const double  xi   = (prop[L::X] - x0) / length;
              const double  ds = prop[L::stress] + sigma0 * std::sin(M_PI * xi);
              const double  dv = prop[L::velocity] - v0;
              local[0] += m;
              local[1] += m * ds * ds;
              local[2] += m * dv * dv;
            }
          const auto g = global_sums(local, comm);
          // v0 = 0 (the bar at rest): the velocity error in m/s
          return {std::sqrt(g[1] / g[0]) / sigma0,
                  std::sqrt(g[2] / g[0]) / (v0 != 0 ? std::abs(v0) : 1.)};
        }

      private:
        double length, sigma0, v0, x0;
      };
    } // namespace

    MPM_REGISTER_BENCHMARK(ConvectingBar, declaration, 1, 2, 3)
  } // namespace benchmarks
} // namespace mpm
