#pragma once

#include <mpm/benchmarks/benchmark.h>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * BENCHMARKS.md section 3: a plane-stress disk of radius a spinning at
     * omega about the origin in its steady state. Columns: mass-weighted
     * RMS of (sigma_rr - exact)/sigma0, RMS sigma_rt/sigma0 and RMS radial
     * velocity/(omega a), with sigma0 = rho omega^2 (3+nu) a^2/8 and polar
     * components taken at the particle's current position.
     */
    template <int dim>
    class SpinningDisk : public Benchmark<dim>
    {
    public:
      SpinningDisk(const double a,
                   const double omega,
                   const double nu,
                   const double rho);

      std::vector<std::string>
      columns() const override;

      std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const override;

    private:
      double a, omega, nu, rho, sigma0;
    };
  } // namespace benchmarks
} // namespace mpm
