#pragma once

#include <mpm/benchmarks/benchmark.h>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * Thick-walled cylinder under internal pressure (the Lame problem), plane
     * strain, linear elastic: inner radius a, outer radius b, inner pressure
     * p, modulus E, Poisson's ratio nu (constants a, b, p, E, nu), centred at
     * the origin. Its incompressible limit deforms (u_r = C/r), so unlike the
     * self-weight column it shows volumetric locking. Exact static state at
     * the material radius R, with k = p a^2/(b^2 - a^2):
     *   u_r = (1+nu) k/E ((1-2nu) R + b^2/R),
     *   sigma_rr = k (1 - b^2/R^2), sigma_tt = k (1 + b^2/R^2),
     *   sigma_zz = nu (sigma_rr + sigma_tt), so the pressure is constant.
     * Polar components along the material direction X/|X|. Columns:
     * - ur_inner_ratio: mass-weighted mean u_r of the particles with
     *   R < a + (b-a)/8 over the exact mean at the same particles (a locked
     *   solution is too stiff: ratio < 1);
     * - pressure_error, sigma_rr_error: sum_p |e_p| V_p / (p sum_p V_p);
     * - checkerboard: as in SelfWeightColumn, of the pressure error, / p.
     */
    template <int dim>
    class ThickCylinder : public Benchmark<dim>
    {
    public:
      ThickCylinder(const double a,
                    const double b,
                    const double p,
                    const double E,
                    const double nu);

      std::vector<std::string>
      columns() const override;

      std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const override;

    private:
      double a, b, p, E, nu;
    };
  } // namespace benchmarks
} // namespace mpm
