#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace mpm
{
  namespace filters
  {
    /// One particle's part in a cell's stress projection.
    template <int dim>
    struct StressSample
    {
      dealii::Point<dim>              xi;     ///< reference coords, [0,1]^dim
      double                          weight; ///< m_p or V_p (see Metric)
      dealii::SymmetricTensor<2, dim> stress; ///< in-plane Cauchy stress
    };

    /// The inner product of the projection.
    enum class Metric
    {
      mass,      ///< the seed's: W = I (Frobenius), weights m_p
      compliance ///< Hellinger-Reissner: W = C^-1, weights V_p
    };

    /**
     * The assumed-stress filter of one cell: the L2 projection of the
     * particle stresses onto the Pian-Sumihara field of the cell,
     *   H = sum_p S_p^T W S_p w_p,  R = sum_p S_p^T W sigma_p w_p,
     *   beta = H^-1 R,  sigma_p <- S_p beta.
     * S is the 5-beta field (2D) or the 18-beta field (3D) in natural
     * coordinates r = 2 xi - 1, mapped to Cartesian components with the
     * Jacobian J0 at the cell centre, sigma = J0 Sigma J0^T, so distorted
     * cells are handled. W is the Frobenius metric (rotation invariant,
     * shear counted twice) or the compliance C^-1 of the material.
     *
     * Cells whose H is singular or ill-conditioned (one particle,
     * collinear particles) fall back to the constant-stress subspace; a
     * cell without weight is left unchanged. Never produces NaN.
     *
     * The enriched field adds the missing linear terms of the normal
     * stresses: 2D sigma_ss += b6 s, sigma_tt += b7 t (7 betas); 3D
     * sigma_11 += b19 xi, sigma_22 += b20 eta, sigma_33 += b21 zeta (21).
     * Over a whole cell they do no work on Q1 velocities (so a filled
     * cell's stiffness is Pian-Sumihara's), but they keep a stress that
     * varies along its own direction, as in a bar moving along itself
     * (doc/theory.md 4.8).
     */
    template <int dim>
    class AssumedStressProjection
    {
    public:
      /// Coefficients of the largest field (the enriched one); the
      /// Pian-Sumihara field uses the first size() of them.
      static constexpr unsigned int n_beta  = dim == 2 ? 7 : 21;
      static constexpr unsigned int n_voigt = dim == 2 ? 3 : 6;

      /// What a projection did.
      enum class Result
      {
        full,     ///< the whole assumed-stress field
        constant, ///< fallback: the constant-stress subspace
        unchanged ///< nothing to project (no weight)
      };

      /**
       * @p J0: Jacobian dx/dxi of the cell at its centre. @p compliance:
       * the material's compliance, used with Metric::compliance.
       */
      AssumedStressProjection(const dealii::Tensor<2, dim> &J0,
                              const Metric                  metric,
                              const dealii::SymmetricTensor<4, dim>
                                &compliance = dealii::SymmetricTensor<4, dim>(),
                              const bool enriched = false);

      /// Number of coefficients of this field (5/18, or 7/21 enriched).
      unsigned int
      size() const
      {
        return n_active;
      }

      /// Replace the samples' stresses by the projected field; its
      /// coefficients go to @p beta (n_beta values) if given.
      Result
      project(std::vector<StressSample<dim>> &samples,
              double                         *beta = nullptr) const;

      /// The assumed-stress field at xi for coefficients beta (Cartesian).
      dealii::SymmetricTensor<2, dim>
      field(const dealii::Point<dim> &xi, const double *beta) const;

    private:
      unsigned int n_active; ///< 5 / 18, or 7 / 21 with the enriched field

      /// Cartesian Voigt components of natural unit stresses (columns): T.
      double transform[n_voigt][n_voigt];
      /// T^T W T and T^T W: the metric seen from the natural components.
      double TWT[n_voigt][n_voigt];
      double TW[n_voigt][n_voigt];
    };

    /// Isotropic linear elastic compliance of the in-plane stresses: plane
    /// strain (or 3D) if @p plane_stress is false.
    template <int dim>
    dealii::SymmetricTensor<4, dim>
    isotropic_compliance(const double youngs_modulus,
                         const double poissons_ratio,
                         const bool   plane_stress);
  } // namespace filters
} // namespace mpm
