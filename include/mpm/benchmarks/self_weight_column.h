#pragma once

#include <mpm/benchmarks/benchmark.h>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * BENCHMARKS.md section 5: laterally confined column of height H under
     * gravity g, plane strain, base at y = 0 (constants H, rho, g, nu). Exact
     * static state: sigma_yy = -rho g (H - Y), sigma_xx = nu/(1-nu) sigma_yy,
     * sigma_zz = nu (sigma_xx + sigma_yy), with Y the material coordinate.
     * Columns, all divided by rho g H:
     * - sigma_yy_error: sum_p |sigma_yy - exact| V_p / sum_p V_p
     *   (Coombs et al. 2018);
     * - pressure_error: the same for p = -tr(sigma)/3;
     * - checkerboard: RMS over all pairs of face-neighbouring background
     *   cells holding particles of the jump of the cell's volume-averaged
     *   pressure error. A smooth error has small jumps; an oscillating
     *   one from cell to cell does not.
     */
    template <int dim>
    class SelfWeightColumn : public Benchmark<dim>
    {
    public:
      SelfWeightColumn(const double height,
                       const double rho,
                       const double g,
                       const double nu);

      std::vector<std::string>
      columns() const override;

      std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const override;

    private:
      double height, rho, g, nu;
    };
  } // namespace benchmarks
} // namespace mpm
