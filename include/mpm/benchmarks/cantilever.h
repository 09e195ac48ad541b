#pragma once

#include <mpm/benchmarks/benchmark.h>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * BENCHMARKS.md section 2: vibrating cantilever of length L and depth H
     * (constants L, H), clamped at x = 0. Column: the vertical displacement
     * of the tip, the mass-weighted mean of y - Y over the particles with
     * X > L - H/2. scripts/beam_period.py takes the period from it (mean
     * interval between zero crossings of the same sign).
     */
    template <int dim>
    class Cantilever : public Benchmark<dim>
    {
    public:
      Cantilever(const double length, const double depth)
        : length(length)
        , depth(depth)
      {}

      std::vector<std::string>
      columns() const override;

      std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const override;

    private:
      double length, depth;
    };
  } // namespace benchmarks
} // namespace mpm
