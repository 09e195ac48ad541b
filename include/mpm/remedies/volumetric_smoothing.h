#pragma once

#include <deal.II/base/tensor.h>

#include <cmath>

namespace mpm
{
  namespace remedies
  {
    /**
     * The volumetric-locking remedy of a body (the seed's theta-bar):
     * the volume change that sets the pressure is an average over a
     * neighbourhood instead of the particle's own, the deviatoric part
     * stays the particle's.
     */
    enum class VolumetricSmoothing
    {
      none,
      cell, ///< volume-weighted over the body's particles in the cell
      node  ///< mass-weighted to the grid nodes and interpolated back
    };

    /**
     * Replace the volumetric part of one particle's kinematics by the
     * smoothed one, for both kinds of material:
     * - rate (the seed's theta-bar in rate form): L <- L + (theta_bar -
     *   tr L)/d I, theta_bar the average of tr L, so the volume-change
     *   rate that sets the pressure is the smoothed one; for models that
     *   integrate a stress rate (linear elastic, von Mises). With a linear
     *   elastic law the pressure grows by K theta_bar dt per step: p = K
     *   theta_bar of the seed, summed over the steps.
     * - total (F-bar): F <- (J_bar/J)^(1/d) F, so det F = J_bar, for
     *   models that compute stress from F (neo-Hookean, the fluid's
     *   equation of state).
     * d is the model dimension (in-plane for 2D, as in de Souza Neto's
     * plane-strain F-bar). L and F are only what the material sees; the
     * particle keeps its own compatible F and volume.
     */
    template <int dim>
    inline void
    smooth_volume_change(dealii::Tensor<2, dim> &L,
                         dealii::Tensor<2, dim> &F,
                         const double            J,
                         const double            J_bar,
                         const double            theta_bar)
    {
      F *= std::pow(J_bar / J, 1. / dim);
      const double l = (theta_bar - dealii::trace(L)) / dim;
      for (unsigned int d = 0; d < dim; ++d)
        L[d][d] += l;
    }
  } // namespace remedies
} // namespace mpm
