#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cstdint>
#include <vector>

namespace mpm
{
  namespace remedies
  {
    /// One particle's part in a cell's stress projection.
    template <int dim>
    struct StressSample
    {
      dealii::Point<dim>              xi;     ///< reference coords, [0,1]^dim
      double                          weight; ///< m_p or V_p (see Metric)
      dealii::SymmetricTensor<2, dim> stress; ///< in-plane Cauchy stress
    };

    namespace internal
    {
      /// The natural field Sigma(r) = P(r) beta. Every column k of P has one
      /// nonzero: natural component row[k] (Voigt order) times the monomial
      /// mono[k] of the natural coordinates r in [-1, 1] (2D: 1, r0, r1;
      /// 3D: 1, r0, r1, r2, r1 r2, r0 r2, r0 r1). 2D Pian-Sumihara:
      /// ss = b1 + b4 t, tt = b2 + b5 s, st = b3, enriched + b6 s, b7 t;
      /// 3D: the 18-beta hexahedral field, enriched + b19 xi, b20 eta,
      /// b21 zeta on the normal stresses. So H_kl = (T^T W T)[row k][row l]
      /// sum_p w_p m_k m_l needs only the particles' monomial moments.
      template <int dim>
      struct BasisColumns;
      template <>
      struct BasisColumns<2>
      {
        static constexpr unsigned int n_mono  = 3;
        static constexpr unsigned int row[7]  = {0, 1, 2, 0, 1, 0, 1};
        static constexpr unsigned int mono[7] = {0, 0, 0, 2, 1, 1, 2};
        static void
        monomials(const double *r, double *m)
        {
          m[0] = 1, m[1] = r[0], m[2] = r[1];
        }
      };
      template <>
      struct BasisColumns<3>
      {
        static constexpr unsigned int n_mono   = 7;
        static constexpr unsigned int row[21]  = {0, 0, 0, 0, 1, 1, 1,
                                                  1, 2, 2, 2, 2, 3, 3,
                                                  4, 4, 5, 5, 0, 1, 2};
        static constexpr unsigned int mono[21] = {0, 2, 3, 4, 0, 1, 3,
                                                  5, 0, 1, 2, 6, 0, 1,
                                                  0, 2, 0, 3, 1, 2, 3};
        static void
        monomials(const double *r, double *m)
        {
          m[0] = 1, m[1] = r[0], m[2] = r[1], m[3] = r[2];
          m[4] = r[1] * r[2], m[5] = r[0] * r[2], m[6] = r[0] * r[1];
        }
      };
    } // namespace internal

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
     * (doc/theory/assumed_stress_filter.md).
     */
    template <int dim>
    class AssumedStressProjection
    {
    public:
      /// Coefficients of the largest field (the enriched one); the
      /// Pian-Sumihara field uses the first size() of them.
      static constexpr unsigned int n_beta  = dim == 2 ? 7 : 21;
      static constexpr unsigned int n_voigt = dim == 2 ? 3 : 6;
      /// Monomials of the natural coordinates the fields are made of.
      static constexpr unsigned int n_monomials = dim == 2 ? 3 : 7;

      /**
       * A cell's particle sums, added one particle at a time (add()) and
       * solved once (solve()): the monomial moments sum_p w m_i m_j and the
       * moments of the stress seen from the natural components,
       * sum_p w m_i (T^T W sigma)_a.
       */
      struct Moments
      {
        double moment[n_monomials][n_monomials];
        double rhs[n_voigt][n_monomials];
        double total;
        void
        clear()
        {
          *this = Moments{};
        }
      };

      /**
       * The field in Cartesian Voigt components (2D xx yy xy; 3D xx yy zz
       * yz xz xy) as coefficients of the monomials of r = 2 xi - 1:
       * sigma_a(r) = sum_i c[a][i] m_i(r). Evaluating it per particle costs
       * n_voigt x n_monomials products.
       */
      struct CartesianField
      {
        double c[n_voigt][n_monomials];

        dealii::SymmetricTensor<2, dim>
        value(const dealii::Point<dim> &xi) const;
      };

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

      /// Add one particle (reference coordinates @p xi, weight m_p or V_p,
      /// in-plane stress) to a cell's sums.
      void
      add(Moments                               &sums,
          const dealii::Point<dim>              &xi,
          const double                           weight,
          const dealii::SymmetricTensor<2, dim> &stress) const;

      /// The coefficients beta of the projection of the particles summed
      /// in @p sums (n_beta values; those beyond size() are zero).
      Result
      solve(const Moments &sums, double *beta) const;

      /// The assumed-stress field at xi for coefficients beta (Cartesian).
      dealii::SymmetricTensor<2, dim>
      field(const dealii::Point<dim> &xi, const double *beta) const;

      /// The field of coefficients @p beta as monomial coefficients.
      CartesianField
      cartesian_field(const double *beta) const;

    private:
      template <unsigned int n>
      Result
      solve_sized(const Moments &sums, double *beta) const;
      /// The fallback: the constant-stress columns of H beta = R alone.
      template <unsigned int n>
      Result
      solve_constant(const double (&H)[n][n],
                     const double (&R)[n],
                     double *beta) const;

      unsigned int n_active; ///< 5 / 18, or 7 / 21 with the enriched field

      /// Cartesian Voigt components of natural unit stresses (columns): T.
      double transform[n_voigt][n_voigt];
      /// T^T W T and T^T W: the metric seen from the natural components.
      double TWT[n_voigt][n_voigt];
      double TW[n_voigt][n_voigt];

      /// Bit k of coupled[j]: column k is coupled to column j through
      /// T^T W T, directly or through others (a box's mass metric
      /// decouples the stress components). The factorization visits only
      /// these; the entries it skips are zero, so the result is the dense
      /// one bit for bit.
      std::uint32_t coupled[n_beta];
    };

    template <int dim>
    inline dealii::SymmetricTensor<2, dim>
    AssumedStressProjection<dim>::CartesianField::value(
      const dealii::Point<dim> &xi) const
    {
      using C = internal::BasisColumns<dim>;
      double r[dim], m[n_monomials];
      for (unsigned int d = 0; d < dim; ++d)
        r[d] = 2 * xi[d] - 1;
      C::monomials(r, m);
      double s[n_voigt];
      for (unsigned int a = 0; a < n_voigt; ++a)
        {
          s[a] = 0;
          for (unsigned int i = 0; i < n_monomials; ++i)
            s[a] += c[a][i] * m[i];
        }
      dealii::SymmetricTensor<2, dim> sigma;
      if constexpr (dim == 2)
        {
          sigma[0][0] = s[0], sigma[1][1] = s[1], sigma[0][1] = s[2];
        }
      else
        {
          sigma[0][0] = s[0], sigma[1][1] = s[1], sigma[2][2] = s[2];
          sigma[1][2] = s[3], sigma[0][2] = s[4], sigma[0][1] = s[5];
        }
      return sigma;
    }

    /// Isotropic linear elastic compliance of the in-plane stresses: plane
    /// strain (or 3D) if @p plane_stress is false.
    template <int dim>
    dealii::SymmetricTensor<4, dim>
    isotropic_compliance(const double youngs_modulus,
                         const double poissons_ratio,
                         const bool   plane_stress);
  } // namespace remedies
} // namespace mpm
