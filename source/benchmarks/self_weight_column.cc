#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/benchmarks/checkerboard.h>
#include <mpm/benchmarks/global_sums.h>
#include <mpm/particles/particle_layout.h>

#include <array>
#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    namespace
    {
      const BenchmarkDeclaration declaration{
        "self-weight column",
        "laterally confined column under gravity, plane strain, against "
        "its exact static state sigma_yy = -rho g (H - Y)",
        {required_constant("H", "height of the column [m]"),
         required_constant("rho", "density [kg/m^3]"),
         required_constant("g", "gravity [m/s^2]"),
         required_constant("nu", "Poisson's ratio")},
        {"sigma_yy_error", "pressure_error", "checkerboard"}};

      /**
       * Self-weight column (doc/benchmarks/self_weight_column.md): laterally
       * confined column of height H under gravity g, plane strain, base at
       * y = 0. Exact static state: sigma_yy = -rho g (H - Y),
       * sigma_xx = nu/(1-nu) sigma_yy, sigma_zz = nu (sigma_xx + sigma_yy),
       * with Y the material coordinate. Columns, all divided by rho g H:
       * - sigma_yy_error: sum_p |sigma_yy - exact| V_p / sum_p V_p
       *   (Coombs et al. 2018);
       * - pressure_error: the same for p = -tr(sigma)/3;
       * - checkerboard: RMS over all pairs of face-neighbouring background
       *   cells holding particles of the jump of the cell's
       *   volume-averaged pressure error. A smooth error has small jumps;
       *   an oscillating one from cell to cell does not.
       */
      template <int dim>
      class SelfWeightColumn : public Benchmark<dim>
      {
      public:
        explicit SelfWeightColumn(const BenchmarkConstants &c)
          : Benchmark<dim>(declaration.columns)
          , height(c["H"])
          , rho(c["rho"])
          , g(c["g"])
          , nu(c["nu"])
        {}

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double,
                const MPI_Comm comm) const override
        {
          using L = ParticleLayout<dim>;
          // exact stresses at the material coordinate Y: xx, yy, zz
          auto exact = [&](const double *prop) {
            const double yy = -rho * g * (height - prop[L::X + 1]);
            const double xx = nu / (1 - nu) * yy;
            return std::array<double, 3>{
              {xx, yy, dim == 2 ? nu * (xx + yy) : xx}};
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
          const auto   sum   = global_sums(local, comm);
          const double scale = rho * g * height;
          return {sum[1] / (sum[0] * scale),
                  sum[2] / (sum[0] * scale),
                  checkerboard(particles, pressure_error, comm) / scale};
        }

      private:
        double height, rho, g, nu;
      };
    } // namespace

    MPM_REGISTER_BENCHMARK(SelfWeightColumn, declaration, 2, 3)
  } // namespace benchmarks
} // namespace mpm
