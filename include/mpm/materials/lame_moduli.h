#pragma once

#include <mpm/materials/material.h>
#include <mpm/utilities/input_error.h>

#include <limits>

namespace mpm
{
  namespace materials
  {
    /**
     * The in-plane Lame constants of the model: 3D and plane strain use
     * lambda = E nu/((1+nu)(1-2nu)); plane stress eliminates sigma_zz = 0,
     * which leaves lambda* = 2 lambda mu/(lambda + 2 mu) = E nu/(1-nu^2).
     * The FE reference's mixed formulation needs 1/lambda, finite at
     * nu = 0.5 (zero in plane strain and 3D); the implicit MPM step's
     * cell-pressure preconditioner splits the lambda part off.
     */
    struct LameModuli
    {
      double mu             = 0;
      double lambda         = 0; ///< infinite at nu = 0.5 (plane strain, 3D)
      double inverse_lambda = 0; ///< infinite at nu = 0

      LameModuli(const double E, const double nu, const KinematicAssumption k)
      {
        mu = E / (2 * (1 + nu));
        if (k == KinematicAssumption::plane_stress)
          {
            lambda         = E * nu / (1 - nu * nu);
            inverse_lambda = nu > 0 ? (1 - nu * nu) / (E * nu) :
                                      std::numeric_limits<double>::infinity();
          }
        else
          {
            lambda         = nu < 0.5 ? E * nu / ((1 + nu) * (1 - 2 * nu)) :
                                        std::numeric_limits<double>::infinity();
            inverse_lambda = nu > 0 ? (1 + nu) * (1 - 2 * nu) / (E * nu) :
                                      std::numeric_limits<double>::infinity();
          }
      }
    };
  } // namespace materials
} // namespace mpm
