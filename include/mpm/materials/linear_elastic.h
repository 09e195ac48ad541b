#pragma once

#include <mpm/materials/elasticity.h>
#include <mpm/materials/material.h>

namespace mpm
{
  namespace materials
  {
    /**
     * Isotropic hypoelastic material: the Jaumann rate of the Cauchy stress
     * is C : D, integrated with the incrementally objective Hughes-Winget
     * scheme. Supports every kinematic assumption. For small strains it is
     * linear elasticity.
     */
    class LinearElastic : public Material
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

      /// With Strain increment = start of step (midpoint takes h (I +
      /// h/2)^-1).
      bool
      small_strain_increment() const override
      {
        return increment == elasticity::StrainIncrement::start_of_step;
      }

      bool
      stress_tangent(const PointKinematics         &kinematics,
                     const SymmetricTensor<2, 3>   &stress_n,
                     const ArrayView<const double> &history_n,
                     Tensor<4, 3>                  &tangent) const override;

      /// J times the complementary energy of the stress.
      double
      strain_energy_density(
        const SymmetricTensor<2, 3>   &stress,
        const Tensor<2, 3>            &F,
        const ArrayView<const double> &history) const override;

      /// Longitudinal wave speed of the assumption, sqrt(M max(J,1)/rho0).
      double
      wave_speed(const Tensor<2, 3> &F) const override;

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
      elasticity::StrainIncrement    increment =
        elasticity::StrainIncrement::start_of_step;
    };
  } // namespace materials
} // namespace mpm
