#pragma once

#include <mpm/benchmarks/benchmark.h>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * BENCHMARKS.md section 1: a bar of length L and cross-section A in
     * quasi-static equilibrium with the body force b0 cos(pi xi) per unit
     * length, xi = (X - x0)/L, convected at v0. Exact: sigma_xx =
     * -sigma0 sin(pi xi), sigma0 = b0 L/(pi A), and v = v0. Columns: the
     * mass-weighted RMS of (sigma_xx - exact)/sigma0 and of (v_x - v0)/v0
     * (in m/s if v0 = 0); x components, so a 2D strip is measured the same
     * way.
     */
    template <int dim>
    class ConvectingBar : public Benchmark<dim>
    {
    public:
      ConvectingBar(const double length,
                    const double area,
                    const double b0,
                    const double v0,
                    const double x0)
        : length(length)
        , sigma0(b0 * length / (M_PI * area))
        , v0(v0)
        , x0(x0)
      {}

      std::vector<std::string>
      columns() const override;

      std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const override;

    private:
      double length, sigma0, v0, x0;
    };
  } // namespace benchmarks
} // namespace mpm
