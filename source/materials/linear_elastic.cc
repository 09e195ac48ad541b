#include <mpm/materials/linear_elastic.h>

#include <algorithm>
#include <cmath>

namespace mpm
{
  namespace materials
  {
    void
    LinearElastic::declare_parameters(dealii::ParameterHandler &prm)
    {
      elasticity::declare_parameters(prm);
      elasticity::declare_increment_parameter(prm);
    }



    std::string
    LinearElastic::name() const
    {
      return "linear elastic";
    }



    bool
    LinearElastic::supports(const KinematicAssumption) const
    {
      return true;
    }



    void
    LinearElastic::parse_parameters(dealii::ParameterHandler &prm)
    {
      constants = elasticity::parse_parameters(prm);
      increment = elasticity::parse_increment_parameter(prm);
    }



    void
    LinearElastic::update_stress(const PointKinematics &point,
                                 SymmetricTensor<2, 3> &stress,
                                 const ArrayView<double> &) const
    {
      elasticity::hypoelastic_update(
        constants, point, kinematic_assumption(), increment, stress);
    }



    bool
    LinearElastic::stress_tangent(const PointKinematics       &point,
                                  const SymmetricTensor<2, 3> &stress_n,
                                  const ArrayView<const double> &,
                                  Tensor<4, 3> &tangent) const
    {
      elasticity::hypoelastic_tangent(
        constants, point, kinematic_assumption(), increment, stress_n, tangent);
      return true;
    }



    double
    LinearElastic::strain_energy_density(const SymmetricTensor<2, 3> &stress,
                                         const Tensor<2, 3>          &F,
                                         const ArrayView<const double> &) const
    {
      return dealii::determinant(F) *
             elasticity::complementary_energy(constants, stress);
    }



    double
    LinearElastic::wave_speed(const Tensor<2, 3> &F) const
    {
      // The moduli are constant per current volume, so c^2 = M / rho with
      // rho = rho0 / J. Compression is not allowed to lower the estimate
      // (the stress adds to the acoustic tensor, and a smaller speed only
      // saves little time).
      const double J = dealii::determinant(F);
      return std::sqrt(constants.p_wave_modulus(kinematic_assumption()) *
                       std::max(J, 1.0) / density);
    }
  } // namespace materials
} // namespace mpm

using mpm::materials::LinearElastic;
MPM_REGISTER_MATERIAL(LinearElastic,
                      "linear elastic",
                      "isotropic hypoelastic material, Jaumann rate of "
                      "the Cauchy stress = C : D with the incrementally "
                      "objective Hughes-Winget update; linear elasticity "
                      "for small strains. Every kinematic assumption.")
