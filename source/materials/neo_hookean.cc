#include <deal.II/base/symmetric_tensor.h>

#include <mpm/materials/neo_hookean.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <cmath>

namespace mpm
{
  namespace materials
  {
    namespace
    {
      double
      jacobian(const Tensor<2, 3> &F)
      {
        const double J = dealii::determinant(F);
        // ln J is undefined for an inverted or collapsed element.
        if (!(J > 0))
          throw RuntimeError("neo-Hookean material: det F = " +
                             std::to_string(J) + " is not positive");
        return J;
      }

      /// The largest eigenvalue of the symmetric @p b. With b_xz = b_yz =
      /// 0 (plane strain, uniaxial strain) in closed form from the
      /// in-plane block and b_zz: deal.II's general 3x3 eigenvalues (acos
      /// and cos) cost about 330 instructions per particle and step.
      double
      largest_eigenvalue(const SymmetricTensor<2, 3> &b)
      {
        if (b[0][2] == 0 && b[1][2] == 0)
          {
            const double mean = 0.5 * (b[0][0] + b[1][1]);
            const double half = 0.5 * (b[0][0] - b[1][1]);
            return std::max(b[2][2],
                            mean + std::sqrt(half * half + b[0][1] * b[0][1]));
          }
        return dealii::eigenvalues(b)[0]; // sorted descending
      }
    } // namespace



    void
    NeoHookean::declare_parameters(dealii::ParameterHandler &prm)
    {
      elasticity::declare_parameters(prm);
    }



    std::string
    NeoHookean::name() const
    {
      return "neo-Hookean";
    }



    bool
    NeoHookean::supports(const KinematicAssumption k) const
    {
      // Plane stress would need an iteration for F_zz with sigma_zz = 0.
      return k == KinematicAssumption::three_dimensional ||
             k == KinematicAssumption::plane_strain ||
             k == KinematicAssumption::uniaxial_strain;
    }



    void
    NeoHookean::parse_parameters(dealii::ParameterHandler &prm)
    {
      constants = elasticity::parse_parameters(prm);
    }



    SymmetricTensor<2, 3>
    NeoHookean::cauchy_stress(const Tensor<2, 3> &F) const
    {
      const double                J = jacobian(F);
      const SymmetricTensor<2, 3> I = dealii::unit_symmetric_tensor<3>();
      const SymmetricTensor<2, 3> b =
        dealii::symmetrize(F * dealii::transpose(F));
      return (constants.mu() * (b - I) + constants.lambda() * std::log(J) * I) /
             J;
    }



    void
    NeoHookean::update_stress(const PointKinematics &point,
                              SymmetricTensor<2, 3> &stress,
                              const ArrayView<double> &) const
    {
      stress = cauchy_stress(point.F);
    }



    bool
    NeoHookean::stress_tangent(const PointKinematics &point,
                               const SymmetricTensor<2, 3> &,
                               const ArrayView<const double> &,
                               Tensor<4, 3> &tangent) const
    {
      const Tensor<2, 3> I         = dealii::unit_symmetric_tensor<3>();
      const Tensor<2, 3> f_inverse = point.step_inverse();
      const double       J         = jacobian(point.F);
      const Tensor<2, 3> b         = point.F * dealii::transpose(point.F);
      const Tensor<2, 3> sigma     = cauchy_stress(point.F);
      const double       mu = constants.mu(), lambda = constants.lambda();
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          {
            Tensor<2, 3> dl; // (e_k x e_l) f^-1
            for (unsigned int m = 0; m < 3; ++m)
              dl[k][m] = f_inverse[l][m];
            const double       tr_dl = dl[k][k];
            const Tensor<2, 3> d_tau =
              mu * (dl * b + b * dealii::transpose(dl)) + lambda * tr_dl * I;
            const Tensor<2, 3> d_sigma = d_tau / J - tr_dl * sigma;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                tangent[i][j][k][l] = d_sigma[i][j];
          }
      return true;
    }



    double
    NeoHookean::strain_energy_density(const SymmetricTensor<2, 3> &,
                                      const Tensor<2, 3> &F,
                                      const ArrayView<const double> &) const
    {
      const double J     = jacobian(F);
      const double log_J = std::log(J);
      const double I1    = dealii::scalar_product(F, F);
      const double mu    = constants.mu();
      return 0.5 * mu * (I1 - 3) - mu * log_J +
             0.5 * constants.lambda() * log_J * log_J;
    }



    double
    NeoHookean::wave_speed(const Tensor<2, 3> &F) const
    {
      // Acoustic tensor per current volume for direction n, with
      // rho = rho0 / J (Kirchhoff tangent lambda I x I + 2(mu - lambda ln J) II
      // plus the initial-stress term):
      //   rho0 c^2 = lambda (1 - ln J) + mu (1 + b_nn)   (longitudinal)
      //   rho0 c^2 = mu b_nn                              (transverse)
      // Maximised over n with b_nn <= largest eigenvalue of b. At F = I
      // this is the small-strain p-wave speed sqrt((lambda + 2 mu) / rho0).
      const double                J      = jacobian(F);
      const double                lambda = constants.lambda();
      const double                mu     = constants.mu();
      const SymmetricTensor<2, 3> b =
        dealii::symmetrize(F * dealii::transpose(F));
      const double b_max        = largest_eigenvalue(b);
      const double longitudinal = lambda * (1 - std::log(J)) + mu * (1 + b_max);
      return std::sqrt(std::max(longitudinal, mu * b_max) / density);
    }
  } // namespace materials
} // namespace mpm

using mpm::materials::NeoHookean;
MPM_REGISTER_MATERIAL(NeoHookean,
                      "neo-Hookean",
                      "compressible neo-Hookean hyperelastic material, "
                      "psi = mu/2 (I_1 - 3) - mu ln J + lambda/2 (ln J)^2 "
                      "with lambda and mu from E and nu. The stress follows "
                      "from F alone, so an Initial stress acts only until "
                      "the first stress update. Three dimensional, plane "
                      "strain and uniaxial strain.")
