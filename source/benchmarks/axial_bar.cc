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
        "axial bar",
        "axial vibration of a fixed-free elastic bar in its first mode, "
        "against the exact standing wave",
        {required_constant("L", "length of the bar [m]"),
         required_constant("E", "Young's modulus [Pa]"),
         required_constant("rho", "density [kg/m^3]"),
         required_constant("v0", "velocity amplitude [m/s]"),
         optional_constant("x0", "x of the fixed end [m]", "0")},
        {"v_cm", "v_cm_exact", "v_rms_error"}};

      /**
       * Axial bar (doc/benchmarks/axial_bar.md): fixed-free bar of length L
       * (fixed at X = 0 of the bar), modulus E, density rho, initial velocity
       * v0 sin(beta X). Exact: v = v0 cos(omega t) sin(beta X),
       * beta = pi/(2L), omega = beta c. Columns: centre-of-mass velocity,
       * its exact value v0 cos(omega t)/(beta L), and the mass-weighted
       * RMS of (v_p - v_exact(X_p)) / v0. X is measured from the constant
       * x0 (the fixed end).
       */
      template <int dim>
      class AxialBar : public Benchmark<dim>
      {
      public:
        explicit AxialBar(const BenchmarkConstants &c)
          : Benchmark<dim>(declaration.columns)
          , L(c["L"])
          , v0(c["v0"])
          , x0(c.value_or("x0", 0.))
          , beta(M_PI / (2 * L))
          , omega(beta * std::sqrt(c["E"] / c["rho"]))
        {}

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double                     t,
                const MPI_Comm                   comm) const override
        {
          using Lay       = ParticleLayout<dim>;
          double local[3] = {};
          for (const auto &p : particles)
            {
              const double *prop = p.get_properties().data();
              const double  m    = prop[Lay::mass];
              const double  X    = prop[Lay::X] - x0;
              const double  v    = prop[Lay::velocity];
              const double  ve = v0 * std::cos(omega * t) * std::sin(beta * X);
              local[0] += m;
              local[1] += m * v;
              local[2] += m * (v - ve) * (v - ve);
            }
          const auto g = global_sums(local, comm);
          return {g[1] / g[0],
                  v0 * std::cos(omega * t) / (beta * L),
                  std::sqrt(g[2] / g[0]) / v0};
        }

      private:
        double L, v0, x0, beta, omega;
      };
    } // namespace

    MPM_REGISTER_BENCHMARK(AxialBar, declaration, 1, 2, 3)
  } // namespace benchmarks
} // namespace mpm
