#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/benchmarks/global_sums.h>
#include <mpm/particles/particle_layout.h>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    namespace
    {
      const BenchmarkDeclaration declaration{
        "cantilever",
        "vibrating cantilever clamped at x = 0, started in its first "
        "bending mode; the tip deflection gives the period",
        {required_constant("L", "length of the beam [m]"),
         required_constant("H", "depth of the beam [m]")},
        {"tip_displacement_y"}};

      /**
       * Vibrating cantilever (doc/benchmarks/cantilever.md) of length L
       * and depth H, clamped at x = 0. Column: the vertical displacement of
       * the tip, the mass-weighted mean of y - Y over the particles with
       * X > L - H/2. scripts/beam_period.py takes the period from it (mean
       * interval between zero crossings of the same sign).
       */
      template <int dim>
      class Cantilever : public Benchmark<dim>
      {
      public:
        explicit Cantilever(const BenchmarkConstants &c)
          : Benchmark<dim>(declaration.columns)
          , length(c["L"])
          , depth(c["H"])
        {}

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double,
                const MPI_Comm comm) const override
        {
          using L         = ParticleLayout<dim>;
          double local[2] = {};
          for (const auto &p : particles)
            {
              const double *prop = p.get_properties().data();
              if (prop[L::X] > length - depth / 2)
                {
                  local[0] += prop[L::mass];
                  local[1] +=
                    prop[L::mass] * (p.get_location()[1] - prop[L::X + 1]);
                }
            }
          const auto g = global_sums(local, comm);
          return {g[0] > 0 ? g[1] / g[0] : 0.};
        }

      private:
        double length, depth;
      };
    } // namespace

    MPM_REGISTER_BENCHMARK(Cantilever, declaration, 2, 3)
  } // namespace benchmarks
} // namespace mpm
