#pragma once

#include <mpm/materials/elasticity.h>
#include <mpm/materials/material.h>

namespace mpm
{
  namespace materials
  {
    /**
     * Compressible neo-Hookean hyperelastic material,
     * psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, with
     * sigma = (mu (b - I) + lambda ln J I) / J evaluated from F (the
     * previous stress is not used). The Lame parameters are given as
     * Young's modulus and Poisson's ratio. Supports three-dimensional,
     * plane strain and uniaxial strain models.
     */
    class NeoHookean : public Material
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      std::string
      name() const override;

      bool
      supports(const KinematicAssumption k) const override;

      void
      parse_parameters(dealii::ParameterHandler &prm) override;

      void
      update_stress(const PointKinematics   &kinematics,
                    SymmetricTensor<2, 3>   &stress,
                    const ArrayView<double> &history) const override;

      /// psi(F); the stress argument is not used.
      double
      strain_energy_density(
        const SymmetricTensor<2, 3>   &stress,
        const Tensor<2, 3>            &F,
        const ArrayView<const double> &history) const override;

      /// Largest eigenvalue of the acoustic tensor of the current state.
      double
      wave_speed(const Tensor<2, 3> &F) const override;

      /// Cauchy stress for the deformation gradient F.
      /// Exact: d tau = mu (dl b + b dl^T) + lambda tr(dl) I with
      /// dl = dh f^-1, f = I + h, and sigma = tau / J.
      bool
      stress_tangent(const PointKinematics         &kinematics,
                     const SymmetricTensor<2, 3>   &stress_n,
                     const ArrayView<const double> &history_n,
                     Tensor<4, 3>                  &tangent) const override;

      bool
      has_symmetric_tangent() const override
      {
        return true;
      }

      bool
      stress_from_deformation_gradient() const override
      {
        return true;
      }

      SymmetricTensor<2, 3>
      cauchy_stress(const Tensor<2, 3> &F) const;

      const elasticity::IsotropicConstants &
      elastic_constants() const
      {
        return constants;
      }

      bool
      elastic_moduli(double &E, double &nu) const override
      {
        E  = constants.youngs_modulus();
        nu = constants.poissons_ratio();
        return true;
      }

    private:
      elasticity::IsotropicConstants constants;
    };
  } // namespace materials
} // namespace mpm
