#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <mpm/materials/material.h>

namespace mpm
{
  namespace materials
  {
    /**
     * Building blocks shared by the isotropic (hypo)elastic models: elastic
     * constants, the elastic law for every kinematic assumption, the
     * complementary energy and the Hughes-Winget objective update.
     */
    namespace elasticity
    {
      /// Isotropic elastic constants, given as Young's modulus and
      /// Poisson's ratio (the parameters the user gives); the Lame
      /// parameters are derived once here, not in every particle's update.
      class IsotropicConstants
      {
      public:
        IsotropicConstants(const double youngs_modulus = 1,
                           const double poissons_ratio = 0);

        double
        youngs_modulus() const
        {
          return E;
        }

        double
        poissons_ratio() const
        {
          return nu;
        }

        /// First Lame parameter.
        double
        lambda() const
        {
          return lame_lambda;
        }

        /// The in-plane lambda of plane stress, 2 lambda mu / (lambda +
        /// 2 mu): eliminating eps_zz with sigma_zz = 0.
        double
        plane_stress_lambda() const
        {
          return 2 * lame_lambda * shear_modulus /
                 (lame_lambda + 2 * shear_modulus);
        }

        /// Shear modulus.
        double
        mu() const
        {
          return shear_modulus;
        }

        /// Bulk modulus.
        double
        bulk_modulus() const;

        /// Modulus of a longitudinal (p-) wave under assumption @p k:
        /// lambda + 2 mu (3D, plane strain, uniaxial strain), E/(1-nu^2)
        /// (plane stress) or E (uniaxial stress).
        double
        p_wave_modulus(const KinematicAssumption k) const
        {
          switch (k)
            {
              case KinematicAssumption::plane_stress:
                return E / (1 - nu * nu);
              case KinematicAssumption::uniaxial_stress:
                return E;
              default:
                return lambda() + 2 * mu();
            }
        }

      private:
        double E, nu, lame_lambda, shear_modulus;
      };



      /// The configuration on which the rate models (linear elastic,
      /// von Mises) take the gradient of a step's displacement h x
      /// (h = dt L, L on the start-of-step configuration).
      enum class StrainIncrement
      {
        /// h itself: first order in dt; a rigid rotation of angle
        /// omega dt strains the material by (omega dt)^2 / 2
        start_of_step,
        /// h (I + h/2)^-1 (Hughes and Winget 1980): exactly skew for a
        /// rigid rotation of any angle, second order in dt otherwise
        midpoint
      };

      /// Declare "Strain increment" in the current subsection.
      void
      declare_increment_parameter(dealii::ParameterHandler &prm);

      /// Read the entry declared by declare_increment_parameter().
      StrainIncrement
      parse_increment_parameter(dealii::ParameterHandler &prm);

      /// Declare "Young's modulus" and "Poisson's ratio" in the current
      /// subsection.
      void
      declare_parameters(dealii::ParameterHandler &prm);

      /// Read and validate the entries declared by declare_parameters().
      /// Throws mpm::InputError naming the offending parameter.
      IsotropicConstants
      parse_parameters(dealii::ParameterHandler &prm);

      // The particle loops call the inline functions below for every
      // particle and step: defined here so that the compiler inlines them.

      /**
       * Elastic stress increment for the strain increment @p d_eps (an
       * embedded 3x3 tensor) under the assumption @p k. Components that the
       * assumption keeps at zero stay zero.
       */
      inline __attribute__((always_inline)) dealii::SymmetricTensor<2, 3>
      stress_increment(const IsotropicConstants            &c,
                       const dealii::SymmetricTensor<2, 3> &d_eps,
                       const KinematicAssumption            k)
      {
        const double                  mu = c.mu();
        dealii::SymmetricTensor<2, 3> d_sigma;
        switch (k)
          {
              case KinematicAssumption::plane_stress: {
                const double lambda_star = c.plane_stress_lambda();
                const double trace_2d    = d_eps[0][0] + d_eps[1][1];
                for (unsigned int i = 0; i < 2; ++i)
                  for (unsigned int j = i; j < 2; ++j)
                    d_sigma[i][j] = 2 * mu * d_eps[i][j];
                d_sigma[0][0] += lambda_star * trace_2d;
                d_sigma[1][1] += lambda_star * trace_2d;
                break;
              }
            case KinematicAssumption::uniaxial_stress:
              d_sigma[0][0] = c.youngs_modulus() * d_eps[0][0];
              break;
            default:
              // 3D, plane strain and uniaxial strain: the constrained
              // strains are zero in d_eps, the stresses follow from the
              // full law.
              d_sigma = c.lambda() * dealii::trace(d_eps) *
                          dealii::unit_symmetric_tensor<3>() +
                        2 * mu * d_eps;
          }
        return d_sigma;
      }

      /**
       * d sigma_ij / d h_kl of hypoelastic_update() (h = dt L): with the
       * increment gradient G (h, or h (I + h/2)^-1 with dG = (I - G/2) dh
       * (I + h/2)^-1 at the midpoint); the Hughes-Winget rotation of @p
       * stress_n moves by dR = (I - A)^-1 dA (I + R) with A = skew(G) / 2, and
       * the elastic part by the moduli under the assumption @p k applied to
       * sym(dG).
       */
      void
      hypoelastic_tangent(const IsotropicConstants            &c,
                          const PointKinematics               &kinematics,
                          const KinematicAssumption            k,
                          const StrainIncrement                increment,
                          const dealii::SymmetricTensor<2, 3> &stress_n,
                          dealii::Tensor<4, 3>                &tangent);

      /// Complementary energy per unit current volume,
      /// 1/(2E) [(1+nu) s:s - nu (tr s)^2].
      double
      complementary_energy(const IsotropicConstants            &c,
                           const dealii::SymmetricTensor<2, 3> &stress);

      /// Hughes-Winget incremental rotation
      /// R = (I - dt W/2)^-1 (I + dt W/2), W = skew(L). R is orthogonal to
      /// round-off for any dt (a Cayley transform).
      dealii::Tensor<2, 3>
      hughes_winget_rotation(const dealii::Tensor<2, 3> &velocity_gradient,
                             const double                dt);

      /// R sigma R^T.
      dealii::SymmetricTensor<2, 3>
      rotate(const dealii::SymmetricTensor<2, 3> &stress,
             const dealii::Tensor<2, 3>          &R);

      /// R sigma R^T for the Hughes-Winget rotation of a velocity gradient
      /// without out-of-plane shear (L_xz = L_yz = L_zx = L_zy = 0, every
      /// 2D model): a rotation about z by the Cayley transform of
      /// w = dt (L_xy - L_yx) / 4, in closed form. The same result as
      /// rotate(stress, hughes_winget_rotation(L, dt)) to round-off, at a
      /// fraction of its cost.
      inline __attribute__((always_inline)) dealii::SymmetricTensor<2, 3>
      rotate_about_z(const dealii::SymmetricTensor<2, 3> &stress,
                     const double                         w)
      {
        // R = [[c, s, 0], [-s, c, 0], [0, 0, 1]] with
        // c = (1 - w^2) / (1 + w^2), s = 2 w / (1 + w^2).
        const double k = 1. / (1. + w * w);
        const double c = (1. - w * w) * k, s = 2. * w * k;
        const double xx = stress[0][0], yy = stress[1][1], xy = stress[0][1];
        const double xz = stress[0][2], yz = stress[1][2];
        dealii::SymmetricTensor<2, 3> r;
        r[0][0] = c * c * xx + 2. * c * s * xy + s * s * yy;
        r[1][1] = s * s * xx - 2. * c * s * xy + c * c * yy;
        r[0][1] = c * s * (yy - xx) + (c * c - s * s) * xy;
        r[0][2] = c * xz + s * yz;
        r[1][2] = c * yz - s * xz;
        r[2][2] = stress[2][2];
        return r;
      }

      /// Set the components that the assumption @p k keeps at zero to zero
      /// (plane stress: zz, xz, yz; uniaxial stress: all but xx).
      inline __attribute__((always_inline)) void
      zero_constrained_components(dealii::SymmetricTensor<2, 3> &stress,
                                  const KinematicAssumption      k)
      {
        switch (k)
          {
            case KinematicAssumption::plane_stress:
              stress[2][2] = 0;
              stress[0][2] = 0;
              stress[1][2] = 0;
              break;
              case KinematicAssumption::uniaxial_stress: {
                const double sigma_xx = stress[0][0];
                stress                = 0;
                stress[0][0]          = sigma_xx;
                break;
              }
            default:
              break;
          }
      }

      /// M with G = h M for the midpoint configuration: (I + h/2)^-1.
      dealii::Tensor<2, 3>
      midpoint_map(const dealii::Tensor<2, 3> &h);

      /// Gradient G of the step's displacement h x (h = dt L) on the
      /// configuration chosen by @p increment.
      inline dealii::Tensor<2, 3>
      increment_gradient(const PointKinematics &kinematics,
                         const StrainIncrement  increment)
      {
        dealii::Tensor<2, 3> G = kinematics.dt * kinematics.velocity_gradient;
        if (increment == StrainIncrement::midpoint)
          G = G * midpoint_map(G);
        return G;
      }

      /**
       * hypoelastic_update() with the start-of-step increment G = dt L for a
       * velocity gradient without out-of-plane shear (every 2D and 1D
       * model): the same operations in the same order on the components
       * that are not zero, so the same bits at a fraction of the cost of
       * the 3x3 algebra. False (and @p stress untouched) if L has
       * out-of-plane shear.
       */
      inline __attribute__((always_inline)) bool
      planar_hypoelastic_update(const IsotropicConstants      &c,
                                const PointKinematics         &kinematics,
                                const KinematicAssumption      k,
                                dealii::SymmetricTensor<2, 3> &stress)
      {
        const dealii::Tensor<2, 3> &L  = kinematics.velocity_gradient;
        const double                dt = kinematics.dt;
        if (!(dt * L[0][2] == 0. && dt * L[1][2] == 0. && dt * L[2][0] == 0. &&
              dt * L[2][1] == 0.))
          return false;
        const double g00 = dt * L[0][0], g01 = dt * L[0][1];
        const double g10 = dt * L[1][0], g11 = dt * L[1][1];
        const double g22    = dt * L[2][2];
        stress              = rotate_about_z(stress, 0.25 * (g01 - g10));
        const double e01    = (g01 + g10) * 0.5; // sym(G)_xy
        const double two_mu = 2 * c.mu();
        switch (k)
          {
              case KinematicAssumption::plane_stress: {
                const double lambda_star = c.plane_stress_lambda();
                const double trace_2d    = g00 + g11;
                stress[0][0] += two_mu * g00 + lambda_star * trace_2d;
                stress[1][1] += two_mu * g11 + lambda_star * trace_2d;
                stress[0][1] += two_mu * e01;
                break;
              }
            case KinematicAssumption::uniaxial_stress:
              stress[0][0] += c.youngs_modulus() * g00;
              break;
              default: {
                // lambda tr(eps) I + 2 mu eps; the off-diagonal term keeps
                // the 0 + of the tensor sum for a signed zero
                const double lambda_trace = c.lambda() * ((g00 + g11) + g22);
                stress[0][0] += lambda_trace + g00 * two_mu;
                stress[1][1] += lambda_trace + g11 * two_mu;
                stress[2][2] += lambda_trace + g22 * two_mu;
                stress[0][1] += 0. + e01 * two_mu;
              }
          }
        zero_constrained_components(stress, k);
        return true;
      }

      /**
       * Incrementally objective hypoelastic update (Jaumann rate) of
       * Hughes and Winget (1980): with the increment gradient G,
       * stress <- R stress R^T + C : sym(G), R the Cayley transform of
       * skew(G)/2. With the midpoint gradient a rigid rotation of any step
       * turns the stress exactly and strains it not at all.
       */
      inline __attribute__((always_inline)) void
      hypoelastic_update(const IsotropicConstants      &c,
                         const PointKinematics         &kinematics,
                         const KinematicAssumption      k,
                         const StrainIncrement          increment,
                         dealii::SymmetricTensor<2, 3> &stress)
      {
        if (increment == StrainIncrement::start_of_step &&
            planar_hypoelastic_update(c, kinematics, k, stress))
          return;
        const dealii::Tensor<2, 3> G =
          increment_gradient(kinematics, increment);
        if (G[0][2] == 0. && G[1][2] == 0. && G[2][0] == 0. && G[2][1] == 0.)
          stress = rotate_about_z(stress, 0.25 * (G[0][1] - G[1][0]));
        else
          stress = rotate(stress, hughes_winget_rotation(G, 1.));
        stress += stress_increment(c, dealii::symmetrize(G), k);
        zero_constrained_components(stress, k);
      }
    } // namespace elasticity
  }   // namespace materials
} // namespace mpm
