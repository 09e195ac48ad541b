#include <deal.II/base/exceptions.h>

#include <mpm/materials/von_mises_plasticity.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <algorithm>
#include <cmath>

namespace mpm
{
  namespace materials
  {
    void
    VonMisesPlasticity::declare_parameters(dealii::ParameterHandler &prm)
    {
      elasticity::declare_parameters(prm);
      elasticity::declare_increment_parameter(prm);
      prm.declare_entry("Yield stress",
                        "1e6",
                        mpm::NumberOrConstant(),
                        "Initial uniaxial yield stress sigma_y [Pa]. Must "
                        "be positive.");
      prm.declare_entry("Hardening modulus",
                        "0",
                        mpm::NumberOrConstant(),
                        "Linear isotropic hardening modulus H [Pa]: the "
                        "yield stress is sigma_y + H alpha. Must be "
                        "non-negative; 0 is perfect plasticity.");
    }



    std::string
    VonMisesPlasticity::name() const
    {
      return "von Mises plasticity";
    }



    bool
    VonMisesPlasticity::supports(const KinematicAssumption k) const
    {
      // Plane stress and uniaxial stress need a constrained return mapping.
      return k == KinematicAssumption::three_dimensional ||
             k == KinematicAssumption::plane_strain ||
             k == KinematicAssumption::uniaxial_strain;
    }



    void
    VonMisesPlasticity::parse_parameters(dealii::ParameterHandler &prm)
    {
      constants = elasticity::parse_parameters(prm);
      increment = elasticity::parse_increment_parameter(prm);
      sigma_y   = mpm::get_number(prm, "Yield stress");
      H         = mpm::get_number(prm, "Hardening modulus");
      if (!(sigma_y > 0) || !std::isfinite(sigma_y))
        throw InputError("Yield stress = " + prm.get("Yield stress") +
                         " must be positive");
      if (!(H >= 0) || !std::isfinite(H))
        throw InputError("Hardening modulus = " + prm.get("Hardening modulus") +
                         " must be non-negative");
    }



    unsigned int
    VonMisesPlasticity::n_history() const
    {
      return 1;
    }



    std::vector<std::string>
    VonMisesPlasticity::history_names() const
    {
      return {"equivalent plastic strain"};
    }



    double
    VonMisesPlasticity::yield_function(const SymmetricTensor<2, 3> &stress,
                                       const double                 alpha) const
    {
      return dealii::deviator(stress).norm() -
             std::sqrt(2. / 3.) * (sigma_y + H * alpha);
    }



    void
    VonMisesPlasticity::update_stress(const PointKinematics   &point,
                                      SymmetricTensor<2, 3>   &stress,
                                      const ArrayView<double> &history) const
    {
      AssertDimension(history.size(), 1);
      double &alpha = history[0];

      // Elastic trial state.
      elasticity::hypoelastic_update(
        constants, point, kinematic_assumption(), increment, stress);

      return_to_yield_surface(stress, alpha);
    }



    bool
    VonMisesPlasticity::stress_tangent(const PointKinematics         &point,
                                       const SymmetricTensor<2, 3>   &stress_n,
                                       const ArrayView<const double> &history_n,
                                       Tensor<4, 3> &tangent) const
    {
      AssertDimension(history_n.size(), 1);
      const KinematicAssumption k = kinematic_assumption();
      elasticity::hypoelastic_tangent(
        constants, point, k, increment, stress_n, tangent);
      SymmetricTensor<2, 3> trial = stress_n;
      elasticity::hypoelastic_update(constants, point, k, increment, trial);
      // A trial state on the yield surface to round-off (a particle that
      // yielded in the last step, at the first iteration of the next one)
      // takes the elastoplastic tangent: otherwise round-off would pick
      // the tangent, and with it Newton's path.
      const double f      = yield_function(trial, history_n[0]);
      const double radius = std::sqrt(2. / 3.) * (sigma_y + H * history_n[0]);
      if (f <= -1e-10 * radius)
        return true;
      const double                mu      = constants.mu();
      const double                c       = 2 * mu + 2. / 3. * H;
      const SymmetricTensor<2, 3> s       = dealii::deviator(trial);
      const double                s_norm  = s.norm();
      const SymmetricTensor<2, 3> n       = s / s_norm;
      const double                d_gamma = std::max(f, 0.) / c;
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          {
            SymmetricTensor<2, 3> d_trial;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = i; j < 3; ++j)
                d_trial[i][j] = tangent[i][j][a][b];
            const SymmetricTensor<2, 3> ds   = dealii::deviator(d_trial);
            const double                n_ds = n * ds;
            const SymmetricTensor<2, 3> d_sigma =
              d_trial -
              2 * mu * (n_ds / c * n + d_gamma / s_norm * (ds - n_ds * n));
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                tangent[i][j][a][b] = d_sigma[i][j];
          }
      return true;
    }



    void
    VonMisesPlasticity::make_admissible(SymmetricTensor<2, 3>   &stress,
                                        const ArrayView<double> &history) const
    {
      AssertDimension(history.size(), 1);
      return_to_yield_surface(stress, history[0]);
    }



    void
    VonMisesPlasticity::return_to_yield_surface(SymmetricTensor<2, 3> &stress,
                                                double &alpha) const
    {
      const double f = yield_function(stress, alpha);
      if (f <= 0)
        return;

      // Radial return; with linear hardening the consistency condition is
      // linear in the multiplier, so this is exact.
      const double                mu      = constants.mu();
      const SymmetricTensor<2, 3> s       = dealii::deviator(stress);
      const SymmetricTensor<2, 3> n       = s / s.norm();
      const double                d_gamma = f / (2 * mu + 2. / 3. * H);
      stress -= 2 * mu * d_gamma * n;
      alpha += std::sqrt(2. / 3.) * d_gamma;
    }



    double
    VonMisesPlasticity::strain_energy_density(
      const SymmetricTensor<2, 3> &stress,
      const Tensor<2, 3>          &F,
      const ArrayView<const double> &) const
    {
      return dealii::determinant(F) *
             elasticity::complementary_energy(constants, stress);
    }



    double
    VonMisesPlasticity::wave_speed(const Tensor<2, 3> &F) const
    {
      // Plastic flow only softens; the elastic speed bounds it.
      const double J = dealii::determinant(F);
      return std::sqrt(constants.p_wave_modulus(kinematic_assumption()) *
                       std::max(J, 1.0) / density);
    }
  } // namespace materials
} // namespace mpm

using mpm::materials::VonMisesPlasticity;
MPM_REGISTER_MATERIAL(VonMisesPlasticity,
                      "von Mises plasticity",
                      "hypoelastic-plastic material: the Hughes-Winget "
                      "elastic trial stress, then radial return to the von "
                      "Mises surface |dev sigma| = sqrt(2/3) (sigma_y + H "
                      "alpha) with linear isotropic hardening; the "
                      "equivalent plastic strain alpha is stored per "
                      "particle (output equivalent_plastic_strain). Three "
                      "dimensional, plane strain and uniaxial strain.")
