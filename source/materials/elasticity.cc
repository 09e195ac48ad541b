#include <mpm/materials/elasticity.h>
#include <mpm/materials/lame_moduli.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <cmath>
#include <sstream>

namespace mpm
{
  namespace materials
  {
    namespace elasticity
    {
      using dealii::SymmetricTensor;
      using dealii::Tensor;

      IsotropicConstants::IsotropicConstants(const double youngs_modulus,
                                             const double poissons_ratio)
        : E(youngs_modulus)
        , nu(poissons_ratio)
      {
        const LameModuli moduli(E, nu, KinematicAssumption::three_dimensional);
        lame_lambda   = moduli.lambda;
        shear_modulus = moduli.mu;
      }



      double
      IsotropicConstants::bulk_modulus() const
      {
        return E / (3 * (1 - 2 * nu));
      }



      void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        // Ranges are checked in parse_parameters() so that every violation
        // produces the same kind of message.
        prm.declare_entry("Young's modulus",
                          "1e6",
                          mpm::NumberOrConstant(),
                          "Young's modulus E [Pa]. Must be positive.");
        prm.declare_entry("Poisson's ratio",
                          "0.3",
                          mpm::NumberOrConstant(),
                          "Poisson's ratio nu [-], in [0, 0.5).");
      }



      void
      declare_increment_parameter(dealii::ParameterHandler &prm)
      {
        prm.declare_entry(
          "Strain increment",
          "start of step",
          dealii::Patterns::Selection("start of step|midpoint"),
          "Where the step's displacement gradient is taken for the strain "
          "increment and the rotation of the stress. start of step: "
          "h = dt L on the configuration at the start of the step (first "
          "order in dt: a rigid rotation by omega dt strains by "
          "(omega dt)^2 / 2 every step). midpoint: h (I + h/2)^-1 on the "
          "midpoint configuration (Hughes and Winget 1980): a rigid "
          "rotation of any step turns the stress exactly and strains it "
          "not at all; second order in dt otherwise. A body that turns "
          "for many steps (the spinning disk) needs midpoint.");
      }



      StrainIncrement
      parse_increment_parameter(dealii::ParameterHandler &prm)
      {
        return prm.get("Strain increment") == "midpoint" ?
                 StrainIncrement::midpoint :
                 StrainIncrement::start_of_step;
      }



      IsotropicConstants
      parse_parameters(dealii::ParameterHandler &prm)
      {
        const double E  = mpm::get_number(prm, "Young's modulus");
        const double nu = mpm::get_number(prm, "Poisson's ratio");
        if (!(E > 0) || !std::isfinite(E))
          throw InputError("Young's modulus = " + prm.get("Young's modulus") +
                           " must be positive");
        if (!(nu >= 0 && nu < 0.5))
          throw InputError("Poisson's ratio = " + prm.get("Poisson's ratio") +
                           " is out of range [0, 0.5)");
        return IsotropicConstants(E, nu);
      }



      double
      complementary_energy(const IsotropicConstants    &c,
                           const SymmetricTensor<2, 3> &stress)
      {
        const double nu = c.poissons_ratio();
        const double tr = dealii::trace(stress);
        return ((1 + nu) * (stress * stress) - nu * tr * tr) /
               (2 * c.youngs_modulus());
      }



      Tensor<2, 3>
      hughes_winget_rotation(const Tensor<2, 3> &velocity_gradient,
                             const double        dt)
      {
        const Tensor<2, 3> half_spin =
          0.25 * dt *
          (velocity_gradient - dealii::transpose(velocity_gradient));
        // Closed form of the Cayley transform (I - A)^-1 (I + A) for a skew
        // A with axial vector a: I + 2 (A + A^2) / (1 + |a|^2).
        const double a2 = half_spin[0][1] * half_spin[0][1] +
                          half_spin[0][2] * half_spin[0][2] +
                          half_spin[1][2] * half_spin[1][2];
        Tensor<2, 3> R = (2. / (1. + a2)) * (half_spin + half_spin * half_spin);
        for (unsigned int i = 0; i < 3; ++i)
          R[i][i] += 1.;
        return R;
      }



      SymmetricTensor<2, 3>
      rotate(const SymmetricTensor<2, 3> &stress, const Tensor<2, 3> &R)
      {
        const Tensor<2, 3> rotated =
          R * Tensor<2, 3>(stress) * dealii::transpose(R);
        // Symmetric up to round-off; averaging keeps it exactly symmetric.
        return dealii::symmetrize(rotated);
      }



      /// The step moves x_n to x_n + h x_n; the displacement's gradient
      /// on the midpoint configuration x_n + h x_n / 2 is h (I + h/2)^-1.
      /// For a rigid rotation the grid gives h = R - I exactly (positions
      /// move by it), and G = 2 (R - I)(R + I)^-1 is skew: no strain, and
      /// the Cayley rotation of its half is R.
      Tensor<2, 3>
      midpoint_map(const Tensor<2, 3> &h)
      {
        const Tensor<2, 3> I = dealii::unit_symmetric_tensor<3>();
        return dealii::invert(I + 0.5 * h);
      }



      void
      hypoelastic_tangent(const IsotropicConstants    &c,
                          const PointKinematics       &kinematics,
                          const KinematicAssumption    k,
                          const StrainIncrement        increment,
                          const SymmetricTensor<2, 3> &stress_n,
                          Tensor<4, 3>                &tangent)
      {
        const Tensor<2, 3> h = kinematics.dt * kinematics.velocity_gradient;
        const Tensor<2, 3> I = dealii::unit_symmetric_tensor<3>();
        const bool         midpoint    = increment == StrainIncrement::midpoint;
        const Tensor<2, 3> M           = midpoint ? midpoint_map(h) : I;
        const Tensor<2, 3> G           = h * M;
        const Tensor<2, 3> A           = 0.25 * (G - dealii::transpose(G));
        const Tensor<2, 3> R           = hughes_winget_rotation(G, 1.);
        const Tensor<2, 3> to_rotation = dealii::invert(I - A);
        const Tensor<2, 3> before_dh   = midpoint ? I - 0.5 * G : I;
        const Tensor<2, 3> S           = stress_n;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            {
              Tensor<2, 3> dh;
              dh[a][b] = 1.;
              // midpoint: dG = (I - G/2) dh (I + h/2)^-1
              const Tensor<2, 3>    dG    = before_dh * dh * M;
              const Tensor<2, 3>    dA    = 0.25 * (dG - dealii::transpose(dG));
              const Tensor<2, 3>    dR    = to_rotation * dA * (I + R);
              const Tensor<2, 3>    dRSRt = dR * S * dealii::transpose(R);
              SymmetricTensor<2, 3> d_sigma =
                dealii::symmetrize(dRSRt + dealii::transpose(dRSRt)) +
                stress_increment(c, dealii::symmetrize(dG), k);
              zero_constrained_components(d_sigma, k);
              for (unsigned int i = 0; i < 3; ++i)
                for (unsigned int j = 0; j < 3; ++j)
                  tangent[i][j][a][b] = d_sigma[i][j];
            }
      }
    } // namespace elasticity
  }   // namespace materials
} // namespace mpm
