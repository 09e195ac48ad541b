#pragma once

#include <mpm/materials/material.h>

namespace mpm
{
  namespace materials
  {
    /**
     * Compressible Newtonian fluid, sigma = -p(J) I + 2 mu dev(D), with
     * D = sym(L) and the pressure from a barotropic equation of state:
     *   linear: p = K (1/J - 1)
     *   Tait:   p = K/gamma (J^-gamma - 1).
     * Supports three-dimensional, plane strain and uniaxial strain models.
     */
    class NewtonianFluid : public Material
    {
    public:
      enum class EquationOfState
      {
        linear,
        tait
      };

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

      /// d sigma / d h of the step's displacement gradient h = dt L:
      /// the equation of state's through dJ = J tr(f^-1 dh), the
      /// viscous stress's 2 mu dev(sym dh) / dt.
      bool
      stress_tangent(const PointKinematics         &kinematics,
                     const SymmetricTensor<2, 3>   &stress_n,
                     const ArrayView<const double> &history_n,
                     Tensor<4, 3>                  &tangent) const override;

      /// psi(J) with p = -dpsi/dJ and psi(1) = 0; viscous work is
      /// dissipated, not stored.
      double
      strain_energy_density(
        const SymmetricTensor<2, 3>   &stress,
        const Tensor<2, 3>            &F,
        const ArrayView<const double> &history) const override;

      /// Sound speed sqrt(dp/drho) = sqrt(K/rho0 J^(1-gamma)) (gamma = 1
      /// for the linear law). Does not include a viscous limit.
      double
      wave_speed(const Tensor<2, 3> &F) const override;

      /// The J of the pressure -tr(stress)/3: the inverse of the
      /// equation of state, so that an initial hydrostatic stress
      /// persists (NaN if the pressure is at or below the law's limit,
      /// -K for the linear law, -K/gamma for Tait: set-up then reports a
      /// non-finite initial state).
      double
      initial_jacobian(const SymmetricTensor<2, 3> &stress) const override;

      bool
      state_is_volume_ratio() const override
      {
        return true;
      }

      bool
      stress_from_deformation_gradient() const override
      {
        return true;
      }

      bool
      has_static_shear_stiffness() const override
      {
        return false;
      }

      /// Pressure p(J) from the equation of state.
      double
      pressure(const double J) const;

      /// dp/dJ of the equation of state.
      double
      pressure_derivative(const double J) const;

      double
      viscosity() const
      {
        return mu;
      }

      double
      bulk_modulus() const
      {
        return K;
      }

      /// gamma for Tait, 1 for the linear law.
      double
      exponent() const
      {
        return eos == EquationOfState::tait ? gamma : 1.0;
      }

    private:
      double          mu    = 0;
      EquationOfState eos   = EquationOfState::linear;
      double          K     = 1;
      double          gamma = 7;
    };
  } // namespace materials
} // namespace mpm
