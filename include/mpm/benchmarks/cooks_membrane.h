#pragma once

#include <deal.II/base/point.h>

#include <mpm/benchmarks/benchmark.h>
#include <mpm/benchmarks/benchmark_constants.h>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * Cook's membrane (doc/benchmarks/cooks_membrane.md): the panel (0,0),
     * (48,44), (48,60), (0,44) clamped at x = 0 and loaded by the vertical
     * shear traction F/16 on its right edge (small strain, linear elastic, so
     * the displacement is proportional to F). Constants: F, the total load;
     * uy_ref, the FE reference of u_y at the corner (48,60) for F = 1;
     * uy_ref_mid, the same at the midpoint of the loaded edge (48,52);
     * r_fit, the radius of the fit below.
     *
     * The point displacement: the least-squares plane
     * u_y(X) = a + b.(X - X0) through the displacements u_y = y - Y of the
     * particles whose material point X lies within r_fit of X0, evaluated
     * at X0 (a). The corner and the loaded edge are where the particles
     * end, so a particle never sits at X0 (the nearest one is a quarter of
     * a body cell away, where u_y differs by the local rotation times that
     * distance: about 1% at h = 2); the plane removes that first-order
     * offset and leaves the curvature of u_y over r_fit. Columns:
     * - uy_corner, uy_mid: the fitted values at (48,60) and (48,52);
     * - corner_ratio, mid_ratio: those over F uy_ref and F uy_ref_mid;
     * - corner_nearest_ratio: u_y of the particle whose X is nearest the
     *   corner over F uy_ref, to show what the fit corrects.
     * A point with fewer than 3 particles in reach (or all on a line)
     * gives nan.
     */
    template <int dim>
    class CooksMembrane : public Benchmark<dim>
    {
    public:
      CooksMembrane(const double F,
                    const double uy_ref,
                    const double uy_ref_mid,
                    const double r_fit);

      /// From the constants F, uy_ref, uy_ref_mid and r_fit.
      explicit CooksMembrane(const BenchmarkConstants &constants);

      std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const override;

      /// Collective: the fitted u_y at @p X0 (nan if it is undetermined).
      double
      fitted_uy(dealii::Particles::ParticleHandler<dim> &particles,
                const dealii::Point<dim>                &X0,
                const MPI_Comm                           comm) const;

    private:
      double F, uy_ref, uy_ref_mid, r_fit;
    };
  } // namespace benchmarks
} // namespace mpm
