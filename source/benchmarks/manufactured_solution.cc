#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/benchmarks/global_sums.h>
#include <mpm/benchmarks/manufactured_solution.h>
#include <mpm/particles/particle_layout.h>

#include <algorithm>
#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    namespace
    {
      const BenchmarkDeclaration declaration{
        "manufactured solution",
        "large-deformation motion of a neo-Hookean unit square or cube held "
        "by its body force, u_i = G sin(pi X_i) sin(c pi t + phi_i) "
        "(Wallstedt & Guilkey 2008)",
        {positive_constant("G",
                           "displacement amplitude [m]",
                           "errors are divided by it"),
         required_constant("E", "Young's modulus [Pa]"),
         required_constant("nu", "Poisson's ratio"),
         required_constant("rho", "density [kg/m^3]")},
        {"u_L2_error", "u_max_error"}};
    } // namespace

    template <int dim>
    ManufacturedSolution<dim>::ManufacturedSolution(const double amplitude,
                                                    const double youngs_modulus,
                                                    const double poissons_ratio,
                                                    const double density)
      : Benchmark<dim>(declaration.columns)
      , G(amplitude)
      , E(youngs_modulus)
      , nu(poissons_ratio)
      , rho(density)
      , c(std::sqrt(youngs_modulus / density))
    {}

    template <int dim>
    ManufacturedSolution<dim>::ManufacturedSolution(
      const BenchmarkConstants &constants)
      : ManufacturedSolution(constants["G"],
                             constants["E"],
                             constants["nu"],
                             constants["rho"])
    {}

    template <int dim>
    double
    ManufacturedSolution<dim>::time_factor(const unsigned int d,
                                           const double       time) const
    {
      const double phase = d == 0 ? 0. : M_PI;
      return std::sin(c * M_PI * time + phase);
    }

    template <int dim>
    Tensor<1, dim>
    ManufacturedSolution<dim>::displacement(const Point<dim> &X,
                                            const double      time) const
    {
      Tensor<1, dim> u;
      for (unsigned int d = 0; d < dim; ++d)
        u[d] = G * std::sin(M_PI * X[d]) * time_factor(d, time);
      return u;
    }

    template <int dim>
    Tensor<1, dim>
    ManufacturedSolution<dim>::velocity(const Point<dim> &X,
                                        const double      time) const
    {
      Tensor<1, dim> v;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double phase = d == 0 ? 0. : M_PI;
          v[d]               = G * c * M_PI * std::sin(M_PI * X[d]) *
                 std::cos(c * M_PI * time + phase);
        }
      return v;
    }

    template <int dim>
    Tensor<1, dim>
    ManufacturedSolution<dim>::body_force(const Point<dim> &X,
                                          const double      time) const
    {
      // doc/benchmarks/manufactured_solution.md: F = diag(F_d), F_d = 1 + G pi
      // cos(pi X_d) s_d, b_d = k sin(pi X_d) s_d ((1 - 2 nu ln J) / F_d^2 - (1
      // - 4 nu^2)), k = G pi^2 E / (2 rho (1 + nu)(1 - 2 nu)).
      double F[dim], log_J = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          F[d] = 1 + G * M_PI * std::cos(M_PI * X[d]) * time_factor(d, time);
          log_J += std::log(F[d]);
        }
      const double k =
        G * M_PI * M_PI * E / (2 * rho * (1 + nu) * (1 - 2 * nu));
      Tensor<1, dim> b;
      for (unsigned int d = 0; d < dim; ++d)
        b[d] = k * std::sin(M_PI * X[d]) * time_factor(d, time) *
               ((1 - 2 * nu * log_J) / (F[d] * F[d]) - (1 - 4 * nu * nu));
      return b;
    }

    template <int dim>
    std::vector<double>
    ManufacturedSolution<dim>::measure(
      Particles::ParticleHandler<dim> &particles,
      const double                     time,
      const MPI_Comm                   comm) const
    {
      using L          = ParticleLayout<dim>;
      double local[2]  = {}; // sum V0, sum V0 |e|^2
      double max_error = 0;
      for (const auto &particle : particles)
        {
          const double *prop = particle.get_properties().data();
          Point<dim>    X;
          for (unsigned int d = 0; d < dim; ++d)
            X[d] = prop[L::X + d];
          const Tensor<1, dim> error =
            (particle.get_location() - X) - displacement(X, time);
          local[0] += prop[L::volume0];
          local[1] += prop[L::volume0] * error.norm_square();
          max_error = std::max(max_error, error.norm());
        }
      const auto sum = global_sums(local, comm);
      max_error      = Utilities::MPI::max(max_error, comm);
      return {std::sqrt(sum[1] / sum[0]) / G, max_error / G};
    }

    template class ManufacturedSolution<2>;
    template class ManufacturedSolution<3>;

    MPM_REGISTER_BENCHMARK(ManufacturedSolution, declaration, 2, 3)
  } // namespace benchmarks
} // namespace mpm
