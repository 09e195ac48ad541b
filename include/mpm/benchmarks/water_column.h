#pragma once

#include <mpm/benchmarks/benchmark.h>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * BENCHMARKS.md section 6: collapse of a water column of width a and
     * height 2a standing on the floor y = 0 against the wall x = 0
     * (constants a, g, rho; optional wall_band, default a/10). With
     * s_p = V_p^(1/dim) the side of a square (cube) of the particle's
     * current volume, columns:
     * - x_front: max_p (x_p + s_p/2), the surge front, the right edge of
     *   the particle furthest from the wall (the current volume rather
     *   than F times the domain vectors: a fluid's F is sheared without
     *   limit, its volume is not);
     * - height: max (y_p + s_p/2) over the particles with x_p < wall_band,
     *   the top of the column at the wall (0 if none is there);
     * - T = t sqrt(2g/a), Z = x_front/a (Martin & Moyce's front
     *   variables), tau = t sqrt(g/a), H = height/(2a) (their height
     *   variables);
     * - checkerboard: as in SelfWeightColumn, of p + rho g y (the pressure
     *   less its hydrostatic gradient, so that a smooth hydrostatic field
     *   gives 0), divided by rho g 2a;
     * - max_speed: max_p |v_p| (to check that the sound speed is at
     *   least 10 times the flow speed).
     * Both maxima start at a and 2a, the edges of the body.
     */
    template <int dim>
    class WaterColumn : public Benchmark<dim>
    {
    public:
      WaterColumn(const double a,
                  const double g,
                  const double rho,
                  const double wall_band);

      std::vector<std::string>
      columns() const override;

      std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const override;

    private:
      double a, g, rho, wall_band;
    };
  } // namespace benchmarks
} // namespace mpm
