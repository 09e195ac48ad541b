#pragma once

#include <mpm/materials/elasticity.h>
#include <mpm/materials/material.h>

namespace mpm
{
  namespace materials
  {
    /**
     * Hypoelastic-plastic material with a von Mises yield surface and
     * linear isotropic hardening. Each step rotates the stress with the
     * Hughes-Winget rotation, adds the elastic trial increment and returns
     * radially to the yield surface
     *   f = |s| - sqrt(2/3) (sigma_y + H alpha) <= 0,
     * where alpha is the equivalent plastic strain (the one history
     * variable). Supports three-dimensional, plane strain and uniaxial
     * strain models.
     */
    class VonMisesPlasticity : public Material
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

      /// 1: the equivalent plastic strain.
      unsigned int
      n_history() const override;

      std::vector<std::string>
      history_names() const override;

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

      /// Stored elastic energy: J times the complementary energy.
      double
      strain_energy_density(
        const SymmetricTensor<2, 3>   &stress,
        const Tensor<2, 3>            &F,
        const ArrayView<const double> &history) const override;

      /// Elastic p-wave speed, sqrt((lambda + 2 mu) max(J,1) / rho0).
      double
      wave_speed(const Tensor<2, 3> &F) const override;

      /// Radial return of a filtered stress, with the hardening it implies.
      /// The algorithmic (consistent) tangent of the radial return:
      /// d sigma = M : d sigma_trial with
      /// M = I - (2 mu / (2 mu + 2H/3)) n x n
      ///       - (2 mu d_gamma / |s_trial|) (I_dev - n x n),
      /// and d sigma_trial the hypoelastic tangent.
      bool
      stress_tangent(const PointKinematics         &kinematics,
                     const SymmetricTensor<2, 3>   &stress_n,
                     const ArrayView<const double> &history_n,
                     Tensor<4, 3>                  &tangent) const override;

      void
      make_admissible(SymmetricTensor<2, 3>   &stress,
                      const ArrayView<double> &history) const override;

      /// f(stress, alpha); positive outside the elastic domain.
      double
      yield_function(const SymmetricTensor<2, 3> &stress,
                     const double                 alpha) const;

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

      double
      yield_stress() const
      {
        return sigma_y;
      }

      double
      hardening_modulus() const
      {
        return H;
      }

    private:
      void
      return_to_yield_surface(SymmetricTensor<2, 3> &stress,
                              double                &alpha) const;

      elasticity::IsotropicConstants constants;
      elasticity::StrainIncrement    increment =
        elasticity::StrainIncrement::start_of_step;
      double sigma_y = 1;
      double H       = 0;
    };
  } // namespace materials
} // namespace mpm
