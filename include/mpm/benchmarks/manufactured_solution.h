#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/benchmarks/benchmark.h>
#include <mpm/benchmarks/benchmark_constants.h>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * Manufactured solution (doc/benchmarks/manufactured_solution.md;
     * Wallstedt & Guilkey 2008): the unit square or cube in the motion
     * u_i = G sin(pi X_i) sin(c pi t + phi_i),
     * phi = (0, pi, pi), c = sqrt(E/rho), of a compressible neo-Hookean
     * solid (plane strain in 2D) held by the body force of
     * doc/benchmarks/manufactured_solution.md (constants G, E, nu, rho).
     * Columns, both divided by G:
     * - u_L2_error: sqrt(sum_p V0_p |u_p - u(X_p, t)|^2 / sum_p V0_p),
     *   u_p = x_p - X_p;
     * - u_max_error: max_p |u_p - u(X_p, t)|.
     * The body force and the initial velocity are set in the parameter file
     * (prm/manufactured_solution.prm); body_force() is the same closed form,
     * for the tests that check the file against it.
     */
    template <int dim>
    class ManufacturedSolution : public Benchmark<dim>
    {
    public:
      ManufacturedSolution(const double amplitude,
                           const double youngs_modulus,
                           const double poissons_ratio,
                           const double density);

      /// From the constants G, E, nu and rho.
      explicit ManufacturedSolution(const BenchmarkConstants &constants);

      std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const override;

      /// The exact displacement u(X, t).
      dealii::Tensor<1, dim>
      displacement(const dealii::Point<dim> &X, const double time) const;

      /// The exact velocity du/dt(X, t).
      dealii::Tensor<1, dim>
      velocity(const dealii::Point<dim> &X, const double time) const;

      /// The body force per unit mass d2u/dt2 - Div P / rho.
      dealii::Tensor<1, dim>
      body_force(const dealii::Point<dim> &X, const double time) const;

      /// The wave speed c = sqrt(E/rho) of the time factor.
      double
      wave_speed() const
      {
        return c;
      }

    private:
      /// sin(c pi t + phi_d): phi = 0 for x, pi for the others.
      double
      time_factor(const unsigned int d, const double time) const;

      double G, E, nu, rho, c;
    };
  } // namespace benchmarks
} // namespace mpm
