#include <mpm/materials/newtonian_fluid.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

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
        if (!(J > 0))
          throw RuntimeError("Newtonian fluid: det F = " + std::to_string(J) +
                             " is not positive");
        return J;
      }
    } // namespace



    void
    NewtonianFluid::declare_parameters(dealii::ParameterHandler &prm)
    {
      // Ranges are checked in parse_parameters().
      prm.declare_entry("Viscosity",
                        "1e-3",
                        mpm::NumberOrConstant(),
                        "Dynamic (shear) viscosity mu [Pa s], "
                        "non-negative.");
      prm.declare_entry("Equation of state",
                        "linear",
                        dealii::Patterns::Selection("linear|Tait"),
                        "Pressure as a function of J = det F = rho0/rho: "
                        "'linear': p = K (1/J - 1); "
                        "'Tait': p = K/gamma (J^-gamma - 1).");
      prm.declare_entry("Bulk modulus",
                        "2.2e9",
                        mpm::NumberOrConstant(),
                        "Bulk modulus K at the reference density [Pa], "
                        "positive. An initial pressure at or below -K "
                        "(linear) or -K/gamma (Tait) has no volume ratio "
                        "and is refused.");
      prm.declare_entry("Tait exponent",
                        "7",
                        mpm::NumberOrConstant(),
                        "Exponent gamma of the Tait equation of state [-], "
                        ">= 1. Not used by the linear law.");
    }



    std::string
    NewtonianFluid::name() const
    {
      return "Newtonian fluid";
    }



    bool
    NewtonianFluid::supports(const KinematicAssumption k) const
    {
      // Plane stress / uniaxial stress make no sense for a fluid.
      return k == KinematicAssumption::three_dimensional ||
             k == KinematicAssumption::plane_strain ||
             k == KinematicAssumption::uniaxial_strain;
    }



    void
    NewtonianFluid::parse_parameters(dealii::ParameterHandler &prm)
    {
      mu    = mpm::get_number(prm, "Viscosity");
      eos   = prm.get("Equation of state") == "Tait" ? EquationOfState::tait :
                                                       EquationOfState::linear;
      K     = mpm::get_number(prm, "Bulk modulus");
      gamma = mpm::get_number(prm, "Tait exponent");

      if (!(mu >= 0) || !std::isfinite(mu))
        throw InputError("Viscosity = " + prm.get("Viscosity") +
                         " must be non-negative");
      if (!(K > 0) || !std::isfinite(K))
        throw InputError("Bulk modulus = " + prm.get("Bulk modulus") +
                         " must be positive");
      if (!(gamma >= 1) || !std::isfinite(gamma))
        throw InputError("Tait exponent = " + prm.get("Tait exponent") +
                         " must be >= 1");
    }



    double
    NewtonianFluid::pressure(const double J) const
    {
      if (eos == EquationOfState::linear)
        return K * (1 / J - 1);
      // expm1 keeps the relative accuracy for J close to one.
      return K / gamma * std::expm1(-gamma * std::log(J));
    }



    double
    NewtonianFluid::pressure_derivative(const double J) const
    {
      // linear: -K / J^2; Tait: -K J^(-gamma - 1)
      return -K * std::pow(J, -exponent() - 1);
    }

    bool
    NewtonianFluid::stress_tangent(const PointKinematics &point,
                                   const SymmetricTensor<2, 3> &,
                                   const ArrayView<const double> &,
                                   Tensor<4, 3> &tangent) const
    {
      const Tensor<2, 3> f_inverse = point.step_inverse();
      const double       J         = jacobian(point.F);
      const double       dp_dJ     = pressure_derivative(J);
      const double       eta       = mu / point.dt;
      tangent                      = Tensor<4, 3>();
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              tangent[i][j][k][l] =
                (i == j ?
                   -dp_dJ * J * f_inverse[l][k] - (k == l ? 2 * eta / 3 : 0.) :
                   0.) +
                eta *
                  ((i == k && j == l ? 1. : 0.) + (i == l && j == k ? 1. : 0.));
      return true;
    }

    double
    NewtonianFluid::initial_jacobian(const SymmetricTensor<2, 3> &stress) const
    {
      const double p0 = -dealii::trace(stress) / 3;
      if (p0 == 0)
        return 1.;
      // linear: 1/J = 1 + p0/K; Tait: J^-gamma = 1 + gamma p0/K
      const double base = 1 + exponent() * p0 / K;
      // NaN: set-up reports a non-finite initial state (on every rank)
      if (!(base > 0) || !std::isfinite(base))
        return std::nan("");
      return std::pow(base, -1 / exponent());
    }



    void
    NewtonianFluid::update_stress(const PointKinematics &point,
                                  SymmetricTensor<2, 3> &stress,
                                  const ArrayView<double> &) const
    {
      const double J = jacobian(point.F);
      stress =
        -pressure(J) * dealii::unit_symmetric_tensor<3>() +
        2 * mu * dealii::deviator(dealii::symmetrize(point.velocity_gradient));
    }



    double
    NewtonianFluid::strain_energy_density(const SymmetricTensor<2, 3> &,
                                          const Tensor<2, 3> &F,
                                          const ArrayView<const double> &) const
    {
      const double J = jacobian(F);
      // For gamma = 1 the Tait law is the linear law; the general formula
      // would divide by zero.
      if (eos == EquationOfState::linear || gamma == 1)
        return K * (J - 1 - std::log(J));
      return K / gamma *
             ((J - 1) - std::expm1((1 - gamma) * std::log(J)) / (1 - gamma));
    }



    double
    NewtonianFluid::wave_speed(const Tensor<2, 3> &F) const
    {
      // rho = rho0 / J, so dp/drho = K/rho0 J^(1-gamma).
      const double J = jacobian(F);
      return std::sqrt(K / density * std::pow(J, 1 - exponent()));
    }
  } // namespace materials
} // namespace mpm

using mpm::materials::NewtonianFluid;
MPM_REGISTER_MATERIAL(NewtonianFluid,
                      "Newtonian fluid",
                      "compressible Newtonian fluid, sigma = -p(J) I + "
                      "2 mu dev D, with a linear or Tait equation of state. "
                      "The pressure of an Initial stress is kept (the "
                      "particle starts at the J of that pressure, its mass "
                      "unchanged), so a hydrostatic initial stress is in "
                      "equilibrium; the deviatoric part is replaced at the "
                      "first stress update. The stable time step uses the "
                      "sound speed only (no viscous limit). Three "
                      "dimensional, plane strain and uniaxial strain.")
