#define BOOST_TEST_MODULE material_tangents
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
// Each material's stress_tangent() against central differences of its own
// update_stress() (the implicit integrator's Newton tangent): the largest
// difference relative to the largest entry at most 1e-6, at a finite
// step with rotation and from a non-zero initial stress.
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <mpm/materials/linear_elastic.h>
#include <mpm/materials/material.h>
#include <mpm/materials/neo_hookean.h>
#include <mpm/materials/newtonian_fluid.h>
#include <mpm/materials/von_mises_plasticity.h>

#include <algorithm>
#include <cmath>

#include <boost/test/unit_test.hpp>

using namespace mpm;
using namespace mpm::materials;
using dealii::ArrayView;
using dealii::SymmetricTensor;
using dealii::Tensor;

namespace
{
  template <typename T>
  T
  make_model(const KinematicAssumption k,
             const double              nu           = 0.3,
             const std::string        &yield_stress = "",
             const std::string        &increment    = "")
  {
    dealii::ParameterHandler prm;
    T::declare_parameters(prm);
    prm.set("Young's modulus", "1e6");
    prm.set("Poisson's ratio", std::to_string(nu));
    if (!increment.empty())
      prm.set("Strain increment", increment);
    if (!yield_stress.empty())
      {
        prm.set("Yield stress", yield_stress);
        prm.set("Hardening modulus", "2e5");
      }
    T model;
    model.set_common(1000, k);
    model.parse_parameters(prm);
    return model;
  }

  /// The kinematics of the step h from F_n (dt = 0.1).
  PointKinematics
  step(const Tensor<2, 3> &h, const Tensor<2, 3> &F_n)
  {
    PointKinematics k;
    k.dt                = 0.1;
    k.velocity_gradient = h / k.dt;
    Tensor<2, 3> f      = dealii::unit_symmetric_tensor<3>();
    f += h;
    k.F = f * F_n;
    return k;
  }

  /// Which components of h the assumption lets vary.
  unsigned int
  varying(const KinematicAssumption k)
  {
    return k == KinematicAssumption::three_dimensional ? 3 :
           k == KinematicAssumption::uniaxial_stress ||
               k == KinematicAssumption::uniaxial_strain ?
                                                         1 :
                                                         2;
  }

  /// max |tangent - central difference| / max |tangent|.
  double
  tangent_error(const Material           &m,
                const KinematicAssumption kind,
                const double              alpha_n = 0)
  {
    const unsigned int n = varying(kind);
    Tensor<2, 3>       h, F_n = dealii::unit_symmetric_tensor<3>();
    // a finite step: stretch, shear and a rotation of a few degrees
    const double values[3][3]   = {{0.031, -0.052, 0.017},
                                   {0.071, -0.024, 0.043},
                                   {-0.012, 0.028, 0.019}};
    const double previous[3][3] = {{0.05, 0.02, -0.01},
                                   {0.01, -0.03, 0.02},
                                   {0.03, 0.01, 0.04}};
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          h[i][j] = values[i][j];
          F_n[i][j] += previous[i][j];
        }
    SymmetricTensor<2, 3> stress_n;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i; j < n; ++j)
        stress_n[i][j] = 1e4 * (1. + i + 2. * j) * (i == j ? 1. : -0.5);
    if (kind == KinematicAssumption::uniaxial_stress)
      stress_n = SymmetricTensor<2, 3>(), stress_n[0][0] = 2e4;
    const std::vector<double> history(m.n_history(), alpha_n);

    Tensor<4, 3> tangent;
    BOOST_REQUIRE(m.stress_tangent(
      step(h, F_n), stress_n, ArrayView<const double>(history), tangent));
    auto stress_at = [&](const Tensor<2, 3> &hh) {
      SymmetricTensor<2, 3> s = stress_n;
      std::vector<double>   scratch(history);
      m.update_stress(step(hh, F_n), s, ArrayView<double>(scratch));
      return s;
    };
    const double eps     = 1e-6;
    double       largest = 0, difference = 0;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
        {
          Tensor<2, 3> plus = h, minus = h;
          plus[k][l] += eps;
          minus[k][l] -= eps;
          const SymmetricTensor<2, 3> fd =
            (stress_at(plus) - stress_at(minus)) / (2 * eps);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              {
                largest    = std::max(largest, std::abs(tangent[i][j][k][l]));
                difference = std::max(difference,
                                      std::abs(tangent[i][j][k][l] - fd[i][j]));
              }
        }
    BOOST_TEST_MESSAGE(m.name()
                       << " (" << to_string(kind) << "): relative difference "
                       << difference / largest);
    return difference / largest;
  }
} // namespace

BOOST_AUTO_TEST_CASE(linear_elastic_every_assumption)
{
  for (const auto k : {KinematicAssumption::three_dimensional,
                       KinematicAssumption::plane_strain,
                       KinematicAssumption::plane_stress,
                       KinematicAssumption::uniaxial_strain,
                       KinematicAssumption::uniaxial_stress})
    for (const double nu : {0., 0.3, 0.4999})
      for (const char *increment : {"start of step", "midpoint"})
        BOOST_TEST(
          tangent_error(make_model<LinearElastic>(k, nu, "", increment), k) <
          1e-6);
}

BOOST_AUTO_TEST_CASE(neo_hookean)
{
  for (const auto k : {KinematicAssumption::three_dimensional,
                       KinematicAssumption::plane_strain,
                       KinematicAssumption::uniaxial_strain})
    for (const double nu : {0., 0.3, 0.4999})
      BOOST_TEST(tangent_error(make_model<NeoHookean>(k, nu), k) < 1e-6);
}

BOOST_AUTO_TEST_CASE(von_mises_elastic_and_plastic_steps)
{
  // Yield stress 1e9: the step stays elastic. 1e4: the trial stress
  // (about 4e4) is far outside the yield surface, the return is plastic,
  // with a plastic strain 0.01 from before and linear hardening.
  for (const auto k : {KinematicAssumption::three_dimensional,
                       KinematicAssumption::plane_strain,
                       KinematicAssumption::uniaxial_strain})
    for (const char *yield : {"1e9", "1e4"})
      for (const double nu : {0., 0.3, 0.49})
        for (const char *increment : {"start of step", "midpoint"})
          BOOST_TEST(tangent_error(
                       make_model<VonMisesPlasticity>(k, nu, yield, increment),
                       k,
                       0.01) < 1e-6);
}

BOOST_AUTO_TEST_CASE(newtonian_fluid_both_equations_of_state)
{
  // Bulk modulus 1e6 and viscosities from none to a viscous stress of the
  // pressure's order (mu / dt = 1e5 at dt = 0.1).
  for (const auto k : {KinematicAssumption::three_dimensional,
                       KinematicAssumption::plane_strain,
                       KinematicAssumption::uniaxial_strain})
    for (const char *eos : {"linear", "Tait"})
      for (const char *mu : {"0", "1e2", "1e4"})
        {
          dealii::ParameterHandler prm;
          NewtonianFluid::declare_parameters(prm);
          prm.set("Equation of state", eos);
          prm.set("Bulk modulus", "1e6");
          prm.set("Viscosity", mu);
          NewtonianFluid fluid;
          fluid.set_common(1000, k);
          fluid.parse_parameters(prm);
          BOOST_TEST(tangent_error(fluid, k) < 1e-6);
        }
}

BOOST_AUTO_TEST_CASE(symmetry_is_declared_only_for_hyperelastic_models)
{
  using K = KinematicAssumption;
  BOOST_TEST(make_model<NeoHookean>(K::plane_strain).has_symmetric_tangent());
  BOOST_TEST(
    !make_model<LinearElastic>(K::plane_strain).has_symmetric_tangent());
}
