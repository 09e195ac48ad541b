#define BOOST_TEST_MODULE materials
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <mpm/materials/elasticity.h>
#include <mpm/materials/linear_elastic.h>
#include <mpm/materials/material.h>
#include <mpm/materials/neo_hookean.h>
#include <mpm/materials/newtonian_fluid.h>
#include <mpm/materials/von_mises_plasticity.h>
#include <mpm/utilities/input_error.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

using namespace mpm;
using namespace mpm::materials;
using dealii::ArrayView;
using dealii::SymmetricTensor;
using dealii::Tensor;

namespace
{
  using Parameters = std::map<std::string, std::string>;

  /// A model of type T with the given parameters (others at defaults).
  template <typename T>
  T
  make_model(
    const Parameters         &parameters,
    const KinematicAssumption k       = KinematicAssumption::three_dimensional,
    const double              density = 1000)
  {
    dealii::ParameterHandler prm;
    T::declare_parameters(prm);
    for (const auto &p : parameters)
      prm.set(p.first, p.second);
    T model;
    model.set_common(density, k);
    model.parse_parameters(prm);
    return model;
  }

  const Parameters steel = {{"Young's modulus", "200e9"},
                            {"Poisson's ratio", "0.3"}};

  Tensor<2, 3>
  identity()
  {
    return Tensor<2, 3>(dealii::unit_symmetric_tensor<3>());
  }

  /// Unit skew tensor K with K v = axis x v.
  Tensor<2, 3>
  skew_of(const Tensor<1, 3> &axis)
  {
    Tensor<2, 3> K;
    K[0][1] = -axis[2];
    K[0][2] = axis[1];
    K[1][0] = axis[2];
    K[1][2] = -axis[0];
    K[2][0] = -axis[1];
    K[2][1] = axis[0];
    return K;
  }

  /// Rotation by @p angle about the unit vector @p axis (Rodrigues).
  Tensor<2, 3>
  rotation(const Tensor<1, 3> &axis, const double angle)
  {
    const Tensor<2, 3> K = skew_of(axis);
    return identity() + std::sin(angle) * K + (1 - std::cos(angle)) * K * K;
  }

  /// The unit vector along (x, y, z): an axis of no symmetry.
  Tensor<1, 3>
  unit_axis(const double x, const double y, const double z)
  {
    Tensor<1, 3> axis;
    axis[0] = x;
    axis[1] = y;
    axis[2] = z;
    return axis / axis.norm();
  }

  SymmetricTensor<2, 3>
  rotate(const SymmetricTensor<2, 3> &s, const Tensor<2, 3> &Q)
  {
    return dealii::symmetrize(Q * Tensor<2, 3>(s) * dealii::transpose(Q));
  }

  double
  relative_difference(const SymmetricTensor<2, 3> &a,
                      const SymmetricTensor<2, 3> &b)
  {
    return (a - b).norm() / std::max(b.norm(), 1e-300);
  }

  double
  relative_difference(const double a, const double b)
  {
    return std::abs(a - b) / std::max(std::abs(b), 1e-300);
  }

  /// Invariants I1, I2 (= (I1^2 - s:s)/2), I3.
  std::array<double, 3>
  invariants(const SymmetricTensor<2, 3> &s)
  {
    const double I1 = dealii::trace(s);
    return {{I1, 0.5 * (I1 * I1 - s * s), dealii::determinant(s)}};
  }

  /**
   * Spin a stress state rigidly: L = omega K for n_steps steps, F the exact
   * rotation. Checks that the result is the initial stress rotated by the
   * accumulated Hughes-Winget angle and that the invariants are unchanged.
   */
  void
  check_rigid_spin(const Material              &material,
                   const SymmetricTensor<2, 3> &initial_stress,
                   const Tensor<1, 3>          &axis,
                   std::vector<double>          history = {})
  {
    const double       omega   = 2.0;
    const double       dt      = 1e-3;
    const unsigned int n_steps = 5000;

    const std::vector<double> initial_history = history;
    SymmetricTensor<2, 3>     stress          = initial_stress;
    PointKinematics           point;
    point.velocity_gradient = omega * skew_of(axis);
    point.dt                = dt;
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        point.F = rotation(axis, omega * n * dt);
        material.update_stress(
          point, stress, ArrayView<double>(history.data(), history.size()));
      }

    // The Cayley transform rotates by 2 atan(omega dt / 2) per step.
    const double discrete_angle = n_steps * 2 * std::atan(0.5 * omega * dt);
    const Tensor<2, 3> Q        = rotation(axis, discrete_angle);
    BOOST_TEST(relative_difference(rotate(stress, dealii::transpose(Q)),
                                   initial_stress) < 1e-10);

    const auto   i0    = invariants(initial_stress);
    const auto   i1    = invariants(stress);
    const double scale = initial_stress.norm();
    BOOST_TEST(std::abs(i1[0] - i0[0]) < 1e-10 * scale);
    BOOST_TEST(std::abs(i1[1] - i0[1]) < 1e-10 * scale * scale);
    BOOST_TEST(std::abs(i1[2] - i0[2]) < 1e-10 * scale * scale * scale);

    // Against the exact rotation F only up to the O(dt^2) angle error.
    const Tensor<2, 3> R = point.F;
    BOOST_TEST(relative_difference(rotate(stress, dealii::transpose(R)),
                                   initial_stress) < 1e-4);

    for (unsigned int i = 0; i < history.size(); ++i)
      BOOST_TEST(std::abs(history[i] - initial_history[i]) < 1e-14);
  }

  SymmetricTensor<2, 3>
  general_stress(const double scale)
  {
    SymmetricTensor<2, 3> s;
    s[0][0] = 1.0;
    s[1][1] = -0.4;
    s[2][2] = 0.3;
    s[0][1] = 0.25;
    s[0][2] = -0.6;
    s[1][2] = 0.15;
    return scale * s;
  }

  /// Constant velocity gradient for n_steps steps, F integrated with
  /// F <- (I + dt L) F. Returns the accumulated strain sum dt sym(L).
  SymmetricTensor<2, 3>
  drive(const Material        &material,
        const Tensor<2, 3>    &L,
        const double           dt,
        const unsigned int     n_steps,
        SymmetricTensor<2, 3> &stress,
        Tensor<2, 3>          &F,
        std::vector<double>   &history)
  {
    PointKinematics point;
    point.velocity_gradient = L;
    point.dt                = dt;
    for (unsigned int n = 0; n < n_steps; ++n)
      {
        F       = (identity() + dt * L) * F;
        point.F = F;
        material.update_stress(
          point, stress, ArrayView<double>(history.data(), history.size()));
      }
    return n_steps * dt * dealii::symmetrize(L);
  }
} // namespace



BOOST_AUTO_TEST_SUITE(objectivity)

BOOST_AUTO_TEST_CASE(linear_elastic_rigid_spin)
{
  const Tensor<1, 3> axis = unit_axis(1, 2, 3);
  Tensor<1, 3>       z;
  z[2] = 1;

  const auto model3d = make_model<LinearElastic>(steel);
  check_rigid_spin(model3d, general_stress(1e8), axis);

  const auto plane_strain =
    make_model<LinearElastic>(steel, KinematicAssumption::plane_strain);
  SymmetricTensor<2, 3> s = general_stress(1e8);
  s[0][2] = s[1][2] = 0;
  check_rigid_spin(plane_strain, s, z);

  const auto plane_stress =
    make_model<LinearElastic>(steel, KinematicAssumption::plane_stress);
  s[2][2] = 0;
  check_rigid_spin(plane_stress, s, z);
}

BOOST_AUTO_TEST_CASE(plasticity_rigid_spin)
{
  Parameters p           = steel;
  p["Yield stress"]      = "250e6";
  p["Hardening modulus"] = "1e9";
  const auto model       = make_model<VonMisesPlasticity>(p);

  const Tensor<1, 3> axis = unit_axis(-0.5, 1, 2);

  // Inside the elastic domain.
  check_rigid_spin(model, general_stress(1e8), axis, {0.0});

  // On the yield surface after plastic loading: the spin must not cause
  // further plastic flow.
  SymmetricTensor<2, 3> stress;
  Tensor<2, 3>          F       = identity();
  std::vector<double>   history = {0.0};
  Tensor<2, 3>          L;
  L[0][0] = 1;
  L[1][1] = -0.2;
  L[0][1] = 0.3;
  L[1][0] = 0.3;
  drive(model, L, 1e-5, 300, stress, F, history);
  BOOST_TEST(history[0] > 0);
  BOOST_TEST(std::abs(model.yield_function(stress, history[0])) <
             1e-10 * model.yield_stress());
  check_rigid_spin(model, stress, axis, history);
}

BOOST_AUTO_TEST_CASE(midpoint_increment_of_a_finite_rotation_step)
{
  // A step that moves every point by a rigid rotation of 0.4 rad
  // (h = R - I, as positions move on the grid): with the midpoint gradient
  // the stress turns by exactly R and is not strained; the start-of-step
  // gradient strains it by about theta^2 / 2 of the elastic modulus.
  const Tensor<1, 3> axis  = unit_axis(0.3, -1, 2);
  const double       theta = 0.4;
  const Tensor<2, 3> R     = rotation(axis, theta);
  PointKinematics    point;
  point.dt                            = 0.5;
  point.velocity_gradient             = (R - identity()) / point.dt;
  point.F                             = R;
  const SymmetricTensor<2, 3> initial = general_stress(1e8);
  const SymmetricTensor<2, 3> exact   = rotate(initial, R);

  Parameters p              = steel;
  p["Strain increment"]     = "midpoint";
  const auto            mid = make_model<LinearElastic>(p);
  SymmetricTensor<2, 3> s   = initial;
  mid.update_stress(point, s, ArrayView<double>());
  BOOST_TEST(relative_difference(s, exact) < 1e-12);

  const auto start = make_model<LinearElastic>(steel);
  s                = initial;
  start.update_stress(point, s, ArrayView<double>());
  // 200 GPa times a strain of about theta^2 / 2 = 0.08 against 1e8
  BOOST_TEST(relative_difference(s, exact) > 10);

  // Many small steps of a rigid rotation: the midpoint update follows the
  // rotation to round-off (2000 steps of about 1e-13 each; the
  // start-of-step update would be off by 2000 (2e-3)^2 / 2 of the modulus).
  const unsigned int n_steps = 2000;
  const Tensor<2, 3> r       = rotation(axis, 2e-3);
  point.velocity_gradient    = (r - identity()) / point.dt;
  s                          = initial;
  for (unsigned int n = 0; n < n_steps; ++n)
    mid.update_stress(point, s, ArrayView<double>());
  BOOST_TEST(relative_difference(s, rotate(initial, rotation(axis, 4.))) <
             2e-9);
}

BOOST_AUTO_TEST_CASE(neo_hookean_frame_indifference)
{
  const auto   model = make_model<NeoHookean>(steel);
  Tensor<2, 3> F;
  F[0][0]              = 1.2;
  F[0][1]              = 0.3;
  F[0][2]              = -0.1;
  F[1][0]              = 0.05;
  F[1][1]              = 0.9;
  F[1][2]              = 0.2;
  F[2][0]              = 0.1;
  F[2][1]              = -0.15;
  F[2][2]              = 1.1;
  const Tensor<2, 3> Q = rotation(unit_axis(0.3, -1, 0.5), 1.234);

  BOOST_TEST(relative_difference(model.cauchy_stress(Q * F),
                                 rotate(model.cauchy_stress(F), Q)) < 1e-12);
  BOOST_TEST(relative_difference(model.wave_speed(Q * F), model.wave_speed(F)) <
             1e-12);

  // update_stress ignores the previous stress.
  PointKinematics point;
  point.F                      = Q * F;
  point.dt                     = 1e-3;
  SymmetricTensor<2, 3> stress = general_stress(1e9);
  model.update_stress(point, stress, ArrayView<double>());
  BOOST_TEST(relative_difference(stress, model.cauchy_stress(Q * F)) < 1e-15);
}

// The wave speed of a plane-strain F (b_xz = b_yz = 0: the largest
// eigenvalue of b in closed form) equals that of the same F turned about a
// general axis (deal.II's 3x3 eigenvalues), whether the largest
// eigenvalue is in-plane or b_zz.
BOOST_AUTO_TEST_CASE(neo_hookean_plane_strain_wave_speed)
{
  const auto         model = make_model<NeoHookean>(steel);
  const Tensor<2, 3> Q     = rotation(unit_axis(0.3, -1, 0.5), 0.7);
  for (const double F_zz : {1.0, 1.6})
    {
      Tensor<2, 3> F;
      F[0][0] = 1.2;
      F[0][1] = 0.3;
      F[1][0] = -0.1;
      F[1][1] = 0.9;
      F[2][2] = F_zz;
      BOOST_TEST(relative_difference(model.wave_speed(F),
                                     model.wave_speed(Q * F)) < 1e-13);
    }
}

BOOST_AUTO_TEST_SUITE_END()



BOOST_AUTO_TEST_SUITE(linear_elasticity)

BOOST_AUTO_TEST_CASE(energy_after_small_strain_path)
{
  const double E = 200e9, nu = 0.3;
  for (const auto k : {KinematicAssumption::three_dimensional,
                       KinematicAssumption::plane_strain,
                       KinematicAssumption::uniaxial_strain,
                       KinematicAssumption::uniaxial_stress})
    {
      BOOST_TEST_CONTEXT("assumption " << to_string(k))
      {
        const auto   model = make_model<LinearElastic>(steel, k);
        Tensor<2, 3> L;
        L[0][0] = 1;
        if (k == KinematicAssumption::three_dimensional ||
            k == KinematicAssumption::plane_strain)
          {
            L[1][1] = -0.5;
            L[0][1] = L[1][0] = 0.4;
          }
        if (k == KinematicAssumption::three_dimensional)
          {
            L[2][2] = 0.2;
            L[0][2] = L[2][0] = -0.3;
          }

        SymmetricTensor<2, 3>       stress;
        Tensor<2, 3>                F = identity();
        std::vector<double>         history;
        const SymmetricTensor<2, 3> eps =
          drive(model, L, 1e-6, 100, stress, F, history);

        // Symmetric L: no rotation, so the stress is exactly C : eps.
        const double          lambda = model.elastic_constants().lambda();
        const double          mu     = model.elastic_constants().mu();
        SymmetricTensor<2, 3> expected =
          lambda * dealii::trace(eps) * dealii::unit_symmetric_tensor<3>() +
          2 * mu * eps;
        if (k == KinematicAssumption::uniaxial_stress)
          {
            expected       = 0;
            expected[0][0] = E * eps[0][0];
          }
        BOOST_TEST(relative_difference(stress, expected) < 1e-12);

        const double J = dealii::determinant(F);
        const double energy =
          model.strain_energy_density(stress, F, ArrayView<const double>());
        BOOST_TEST(relative_difference(energy, J * 0.5 * (stress * eps)) <
                   1e-12);
        if (k == KinematicAssumption::uniaxial_stress)
          BOOST_TEST(relative_difference(energy,
                                         J * stress[0][0] * stress[0][0] /
                                           (2 * E)) < 1e-12);
      }
    }

  // The p-wave speed of every assumption at rest.
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu     = E / (2 * (1 + nu));
  const std::map<KinematicAssumption, double> modulus = {
    {KinematicAssumption::three_dimensional, lambda + 2 * mu},
    {KinematicAssumption::plane_strain, lambda + 2 * mu},
    {KinematicAssumption::uniaxial_strain, lambda + 2 * mu},
    {KinematicAssumption::plane_stress, E / (1 - nu * nu)},
    {KinematicAssumption::uniaxial_stress, E}};
  for (const auto &km : modulus)
    {
      const auto model = make_model<LinearElastic>(steel, km.first, 7800);
      BOOST_TEST(relative_difference(model.wave_speed(identity()),
                                     std::sqrt(km.second / 7800)) < 1e-14);
    }
}

BOOST_AUTO_TEST_CASE(plane_stress)
{
  const double E = 200e9, nu = 0.3;
  const auto   model =
    make_model<LinearElastic>(steel, KinematicAssumption::plane_stress);

  // A general in-plane motion with spin: sigma_zz stays exactly zero.
  {
    Tensor<2, 3> L;
    L[0][0] = 0.7;
    L[1][1] = -0.3;
    L[0][1] = 1.5;
    L[1][0] = -0.8;
    SymmetricTensor<2, 3> stress;
    Tensor<2, 3>          F = identity();
    std::vector<double>   history;
    drive(model, L, 1e-4, 1000, stress, F, history);
    BOOST_TEST(stress[2][2] == 0.0);
    BOOST_TEST(stress[0][2] == 0.0);
    BOOST_TEST(stress[1][2] == 0.0);
    BOOST_TEST(std::abs(stress[0][1]) > 0);
  }

  // In-plane uniaxial stress: D = diag(d, -nu d).
  {
    Tensor<2, 3> L;
    L[0][0] = 1;
    L[1][1] = -nu;
    SymmetricTensor<2, 3>       stress;
    Tensor<2, 3>                F = identity();
    std::vector<double>         history;
    const SymmetricTensor<2, 3> eps =
      drive(model, L, 1e-6, 200, stress, F, history);
    BOOST_TEST(relative_difference(stress[0][0], E * eps[0][0]) < 1e-12);
    BOOST_TEST(std::abs(stress[1][1]) < 1e-12 * std::abs(stress[0][0]));
    BOOST_TEST(stress[2][2] == 0.0);
    const double energy =
      model.strain_energy_density(stress, F, ArrayView<const double>());
    BOOST_TEST(relative_difference(energy,
                                   dealii::determinant(F) * stress[0][0] *
                                     stress[0][0] / (2 * E)) < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(hughes_winget_rotation_is_orthogonal)
{
  Tensor<2, 3> L;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      L[i][j] = std::sin(1.0 + 3 * i + j);
  const Tensor<2, 3> R = elasticity::hughes_winget_rotation(L, 0.7);
  BOOST_TEST((R * dealii::transpose(R) - identity()).norm() < 1e-14);
  BOOST_TEST(std::abs(dealii::determinant(R) - 1) < 1e-14);
}

BOOST_AUTO_TEST_CASE(rotation_about_z_equals_the_general_rotation)
{
  // An in-plane velocity gradient with a large spin (w = 0.6) and a full
  // stress: the closed form must give R sigma R^T of the general path.
  Tensor<2, 3> L;
  L[0][0] = 0.3, L[0][1] = 1.9, L[1][0] = -1.3, L[1][1] = -0.2, L[2][2] = 0.4;
  SymmetricTensor<2, 3> sigma;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = i; j < 3; ++j)
      sigma[i][j] = std::cos(1.0 + 2 * i + 5 * j);
  const double dt = 0.75;
  const auto   general =
    elasticity::rotate(sigma, elasticity::hughes_winget_rotation(L, dt));
  const auto fast =
    elasticity::rotate_about_z(sigma, 0.25 * dt * (L[0][1] - L[1][0]));
  BOOST_TEST((fast - general).norm() < 1e-15 * sigma.norm());
  BOOST_TEST(std::abs(fast.norm() - sigma.norm()) < 1e-15);
}

BOOST_AUTO_TEST_SUITE_END()



BOOST_AUTO_TEST_SUITE(neo_hookean)

BOOST_AUTO_TEST_CASE(energy_derivative_is_stress_power)
{
  Tensor<2, 3> A;
  A[0][0] = 0.4;
  A[0][1] = 0.2;
  A[1][0] = -0.1;
  A[1][1] = -0.3;
  A[0][2] = 0.15;
  A[2][1] = 0.25;
  A[2][2] = 0.1;

  for (const auto k : {KinematicAssumption::three_dimensional,
                       KinematicAssumption::plane_strain,
                       KinematicAssumption::uniaxial_strain})
    {
      BOOST_TEST_CONTEXT("assumption " << to_string(k))
      {
        const auto model = make_model<NeoHookean>(steel, k);
        // Embed: no out-of-plane rows/columns of the rate.
        Tensor<2, 3>       Fdot = A;
        const unsigned int dim  = k == KinematicAssumption::three_dimensional ?
                                    3 :
                                  k == KinematicAssumption::plane_strain ? 2 :
                                                                           1;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            if (i >= dim || j >= dim)
              Fdot[i][j] = 0;

        const auto psi = [&](const double t) {
          return model.strain_energy_density(SymmetricTensor<2, 3>(),
                                             identity() + t * Fdot,
                                             ArrayView<const double>());
        };
        for (const double t : {0.1, 0.5, 1.0})
          {
            const Tensor<2, 3> F       = identity() + t * Fdot;
            const double       h       = 1e-5;
            const double       dpsi_dt = (psi(t + h) - psi(t - h)) / (2 * h);
            const SymmetricTensor<2, 3> D =
              dealii::symmetrize(Fdot * dealii::invert(F));
            const double power =
              dealii::determinant(F) * (model.cauchy_stress(F) * D);
            BOOST_TEST(relative_difference(dpsi_dt, power) < 1e-6);
          }
      }
    }
}

BOOST_AUTO_TEST_CASE(stress_and_wave_speed)
{
  const auto model =
    make_model<NeoHookean>(steel, KinematicAssumption::three_dimensional, 7800);
  const double lambda = model.elastic_constants().lambda();
  const double mu     = model.elastic_constants().mu();

  // Stress free and small-strain p-wave speed in the reference state.
  BOOST_TEST(model.cauchy_stress(identity()).norm() == 0.0);
  BOOST_TEST(relative_difference(model.wave_speed(identity()),
                                 std::sqrt((lambda + 2 * mu) / 7800)) < 1e-14);

  // Uniaxial stretch: sigma_xx = (mu (s^2 - 1) + lambda ln s) / s.
  Tensor<2, 3> F                = identity();
  F[0][0]                       = 1.3;
  const SymmetricTensor<2, 3> s = model.cauchy_stress(F);
  BOOST_TEST(relative_difference(s[0][0],
                                 (mu * (1.69 - 1) + lambda * std::log(1.3)) /
                                   1.3) < 1e-14);
  BOOST_TEST(relative_difference(s[1][1], lambda * std::log(1.3) / 1.3) <
             1e-14);

  // Isochoric deformation: at least the small-strain speed.
  Tensor<2, 3> G = identity();
  G[0][0]        = 1.5;
  G[1][1]        = 1 / 1.5;
  BOOST_TEST(model.wave_speed(G) >= model.wave_speed(identity()));
}

BOOST_AUTO_TEST_SUITE_END()



BOOST_AUTO_TEST_SUITE(newtonian_fluid)

BOOST_AUTO_TEST_CASE(equation_of_state_and_energy)
{
  const double K = 2.2e9, gamma = 7, mu = 1e-3, rho0 = 1000;
  for (const std::string eos : {"linear", "Tait"})
    {
      BOOST_TEST_CONTEXT("equation of state " << eos)
      {
        const auto model =
          make_model<NewtonianFluid>({{"Equation of state", eos},
                                      {"Bulk modulus", "2.2e9"},
                                      {"Tait exponent", "7"},
                                      {"Viscosity", "1e-3"}},
                                     KinematicAssumption::three_dimensional,
                                     rho0);
        const auto psi = [&](const double J) {
          Tensor<2, 3> F = identity();
          F[0][0]        = J;
          return model.strain_energy_density(SymmetricTensor<2, 3>(),
                                             F,
                                             ArrayView<const double>());
        };
        BOOST_TEST(psi(1.0) == 0.0);

        for (const double J : {0.8, 0.95, 1.05, 1.3})
          {
            const double p_expected = eos == "linear" ?
                                        K * (1 / J - 1) :
                                        K / gamma * (std::pow(J, -gamma) - 1);
            BOOST_TEST(relative_difference(model.pressure(J), p_expected) <
                       1e-12);

            // The stress of a motion with this J.
            Tensor<2, 3> F = identity();
            F[1][1]        = J;
            PointKinematics point;
            point.F  = F;
            point.dt = 1e-3;
            SymmetricTensor<2, 3> stress;
            model.update_stress(point, stress, ArrayView<double>());
            BOOST_TEST(
              relative_difference(stress,
                                  -p_expected *
                                    dealii::unit_symmetric_tensor<3>()) <
              1e-12);

            // p = -dpsi/dJ.
            const double h    = 1e-6;
            const double dpsi = (psi(J + h) - psi(J - h)) / (2 * h);
            BOOST_TEST(relative_difference(-dpsi, p_expected) < 1e-6);

            // Sound speed sqrt(dp/drho), rho = rho0/J.
            const double c2 =
              eos == "linear" ? K / rho0 : K / rho0 * std::pow(J, 1 - gamma);
            BOOST_TEST(relative_difference(model.wave_speed(F), std::sqrt(c2)) <
                       1e-12);
          }
      }
    }

  // Viscous part: 2 mu dev(sym L), J = 1.
  const auto model = make_model<NewtonianFluid>(
    {{"Viscosity", "1e-3"}, {"Bulk modulus", "2.2e9"}});
  PointKinematics point;
  point.F  = identity();
  point.dt = 1e-3;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      point.velocity_gradient[i][j] = std::cos(1.0 + 2 * i + j);
  SymmetricTensor<2, 3> stress;
  model.update_stress(point, stress, ArrayView<double>());
  BOOST_TEST(relative_difference(stress,
                                 2 * mu *
                                   dealii::deviator(dealii::symmetrize(
                                     point.velocity_gradient))) < 1e-12);
}

BOOST_AUTO_TEST_CASE(initial_jacobian_inverts_the_equation_of_state)
{
  // The J with p(J) = -tr(sigma0)/3, so that an initial pressure persists;
  // NaN below the law's limit (-K, -K/gamma).
  for (const std::string eos : {"linear", "Tait"})
    {
      BOOST_TEST_CONTEXT("equation of state " << eos)
      {
        const auto model = make_model<NewtonianFluid>(
          {{"Equation of state", eos}, {"Bulk modulus", "6.25e5"}});
        for (const double p0 : {-5e4, -1.0, 0.0, 1121.0, 3e5})
          {
            SymmetricTensor<2, 3> sigma =
              -p0 * dealii::unit_symmetric_tensor<3>();
            sigma[0][1]    = 7.0; // deviatoric part: ignored
            const double J = model.initial_jacobian(sigma);
            BOOST_TEST(J > 0);
            BOOST_TEST(std::abs(model.pressure(J) - p0) <=
                       1e-9 * (1 + std::abs(p0)));
          }
        const double limit = eos == "linear" ? -6.25e5 : -6.25e5 / 7;
        BOOST_TEST(std::isnan(model.initial_jacobian(
          -1.01 * limit * dealii::unit_symmetric_tensor<3>())));
      }
    }
  // Models that keep their stress start at J = 1.
  const auto elastic = make_model<LinearElastic>({});
  BOOST_TEST(
    elastic.initial_jacobian(-1e5 * dealii::unit_symmetric_tensor<3>()) == 1.0);
}

BOOST_AUTO_TEST_CASE(tait_with_unit_exponent_is_linear)
{
  const auto linear =
    make_model<NewtonianFluid>({{"Equation of state", "linear"}});
  const auto tait = make_model<NewtonianFluid>(
    {{"Equation of state", "Tait"}, {"Tait exponent", "1"}});
  for (const double J : {0.7, 1.0, 1.4})
    {
      Tensor<2, 3> F = identity();
      F[2][2]        = J;
      BOOST_TEST(relative_difference(tait.pressure(J), linear.pressure(J)) <
                 1e-14);
      BOOST_TEST(std::abs(tait.strain_energy_density({}, F, {}) -
                          linear.strain_energy_density({}, F, {})) <=
                 1e-14 * linear.bulk_modulus());
      BOOST_TEST(relative_difference(tait.wave_speed(F), linear.wave_speed(F)) <
                 1e-14);
    }
}

BOOST_AUTO_TEST_SUITE_END()



BOOST_AUTO_TEST_SUITE(plasticity)

BOOST_AUTO_TEST_CASE(radial_return_consistency)
{
  Parameters p           = steel;
  p["Yield stress"]      = "250e6";
  p["Hardening modulus"] = "2e9";
  const auto   model     = make_model<VonMisesPlasticity>(p);
  const double mu        = model.elastic_constants().mu();
  const double H         = 2e9;
  const double sigma_y   = 250e6;

  Tensor<2, 3> L;
  L[0][0] = 1;
  L[1][1] = -0.3;
  L[2][2] = 0.1;
  L[0][1] = L[1][0] = 0.5;
  L[1][2] = L[2][1] = -0.2;
  const double dt   = 2e-3; // beyond yield in one step

  // One plastic step from the natural state.
  SymmetricTensor<2, 3> stress;
  std::vector<double>   history = {0.0};
  PointKinematics       point;
  point.velocity_gradient = L;
  point.dt                = dt;
  point.F                 = identity() + dt * L;
  model.update_stress(point, stress, ArrayView<double>(history.data(), 1));

  const SymmetricTensor<2, 3> trial =
    elasticity::stress_increment(model.elastic_constants(),
                                 dt * dealii::symmetrize(L),
                                 KinematicAssumption::three_dimensional);
  const double f_trial = model.yield_function(trial, 0.0);
  BOOST_TEST(f_trial > 0);
  const double d_gamma = f_trial / (2 * mu + 2. / 3. * H);

  BOOST_TEST(std::abs(model.yield_function(stress, history[0])) <
             1e-12 * sigma_y);
  BOOST_TEST(relative_difference(history[0], std::sqrt(2. / 3.) * d_gamma) <
             1e-12);
  // Pressure unchanged, deviator scaled along the trial direction.
  BOOST_TEST(std::abs(dealii::trace(stress) - dealii::trace(trial)) <
             1e-12 * trial.norm());
  const SymmetricTensor<2, 3> s  = dealii::deviator(stress);
  const SymmetricTensor<2, 3> st = dealii::deviator(trial);
  BOOST_TEST(relative_difference(s / s.norm(), st / st.norm()) < 1e-12);
  BOOST_TEST(relative_difference(s.norm(),
                                 std::sqrt(2. / 3.) *
                                   (sigma_y + H * history[0])) < 1e-12);

  // Continued loading with rotation: every step stays on the surface and
  // alpha grows.
  Tensor<2, 3> L2 = L;
  L2[0][1] += 0.7;
  L2[1][0] -= 0.7;
  point.velocity_gradient = L2;
  point.dt                = 1e-5;
  for (unsigned int n = 0; n < 50; ++n)
    {
      const double alpha_old = history[0];
      point.F                = (identity() + point.dt * L2) * point.F;
      model.update_stress(point, stress, ArrayView<double>(history.data(), 1));
      BOOST_TEST(history[0] > alpha_old);
      BOOST_TEST(std::abs(model.yield_function(stress, history[0])) <
                 1e-10 * sigma_y);
    }

  // Elastic unloading leaves alpha alone.
  const double alpha      = history[0];
  point.velocity_gradient = -1 * L;
  point.dt                = 1e-5;
  model.update_stress(point, stress, ArrayView<double>(history.data(), 1));
  BOOST_TEST(history[0] == alpha);
  BOOST_TEST(model.yield_function(stress, history[0]) < 0);
}

BOOST_AUTO_TEST_CASE(uniaxial_strain_curve)
{
  Parameters p           = steel;
  p["Yield stress"]      = "250e6";
  p["Hardening modulus"] = "5e9";
  const auto model =
    make_model<VonMisesPlasticity>(p, KinematicAssumption::uniaxial_strain);
  const double lambda  = model.elastic_constants().lambda();
  const double mu      = model.elastic_constants().mu();
  const double K       = model.elastic_constants().bulk_modulus();
  const double H       = 5e9;
  const double sigma_y = 250e6;

  // Analytic response to eps_xx = eps: elastic up to eps_y = sigma_y/(2 mu),
  // then q = sigma_xx - sigma_yy = sigma_y + H alpha with
  // alpha = (2 mu eps - sigma_y)/(3 mu + H).
  const auto alpha_exact = [&](const double eps) {
    return std::max(0.0, (2 * mu * eps - sigma_y) / (3 * mu + H));
  };
  const auto sigma_xx_exact = [&](const double eps) {
    if (2 * mu * eps <= sigma_y)
      return (lambda + 2 * mu) * eps;
    return K * eps + 2. / 3. * (sigma_y + H * alpha_exact(eps));
  };
  const double tangent = K + 4. / 3. * mu * H / (3 * mu + H);

  Tensor<2, 3> L;
  L[0][0]                     = 1;
  const double          d_eps = 1e-5;
  SymmetricTensor<2, 3> stress;
  std::vector<double>   history = {0.0};
  PointKinematics       point;
  point.velocity_gradient = L;
  point.dt                = d_eps;
  point.F                 = identity();
  double       eps        = 0;
  double       previous   = 0;
  unsigned int n_plastic  = 0;
  for (unsigned int n = 1; n <= 600; ++n)
    {
      eps           = n * d_eps;
      point.F[0][0] = 1 + eps;
      model.update_stress(point, stress, ArrayView<double>(history.data(), 1));
      BOOST_TEST(relative_difference(stress[0][0], sigma_xx_exact(eps)) <
                 1e-10);
      BOOST_TEST(std::abs(stress[1][1] - stress[2][2]) < 1e-6);
      BOOST_TEST(std::abs(history[0] - alpha_exact(eps)) < 1e-12);
      if (2 * mu * (eps - d_eps) > sigma_y)
        {
          ++n_plastic;
          BOOST_TEST(relative_difference((stress[0][0] - previous) / d_eps,
                                         tangent) < 1e-6);
        }
      previous = stress[0][0];
    }
  BOOST_TEST(n_plastic > 100);
}

BOOST_AUTO_TEST_SUITE_END()



BOOST_AUTO_TEST_SUITE(registry)

BOOST_AUTO_TEST_CASE(registered_models)
{
  std::vector<std::string> names;
  for (const auto &entry : registered_materials())
    {
      names.push_back(entry.name);
      BOOST_TEST(!entry.description.empty());
    }
  const std::vector<std::string> expected = {"Newtonian fluid",
                                             "linear elastic",
                                             "neo-Hookean",
                                             "rigid",
                                             "von Mises plasticity"};
  BOOST_TEST(names == expected, boost::test_tools::per_element());

  BOOST_TEST(subsection_name("linear elastic") == "Linear elastic");
  BOOST_TEST(subsection_name("neo-Hookean") == "Neo-Hookean");
  BOOST_TEST(subsection_name("Newtonian fluid") == "Newtonian fluid");
  BOOST_TEST(subsection_name("von Mises plasticity") == "Von Mises plasticity");
  BOOST_TEST(to_string(KinematicAssumption::plane_stress) == "plane stress");
}

BOOST_AUTO_TEST_CASE(create_every_model)
{
  dealii::ParameterHandler prm;
  prm.enter_subsection("Material");
  declare_material_parameters(prm);
  BOOST_TEST(prm.get("Model") == "linear elastic");
  prm.leave_subsection();

  // Every entry has documentation (printed as comments).
  std::ostringstream out;
  prm.print_parameters(out, dealii::ParameterHandler::PRM);
  BOOST_TEST(out.str().find("Young's modulus E [Pa]") != std::string::npos);

  for (const auto &entry : registered_materials())
    {
      BOOST_TEST_CONTEXT("model " << entry.name)
      {
        prm.enter_subsection("Material");
        prm.set("Model", entry.name);
        prm.set("Density", "2500");
        const auto material =
          create_material(prm, KinematicAssumption::plane_strain, "Material");
        prm.leave_subsection();
        BOOST_TEST(material->name() == entry.name);
        BOOST_TEST(material->reference_density() == 2500.0);
        BOOST_TEST((material->kinematic_assumption() ==
                    KinematicAssumption::plane_strain));
        BOOST_TEST(material->history_names().size() == material->n_history());
        // a rigid body carries no waves (its motion is prescribed)
        BOOST_TEST((material->wave_speed(identity()) > 0) ==
                   (entry.name != "rigid"));
      }
    }

  // Parameters from a file-like string reach the model.
  prm.parse_input_from_string("subsection Material\n"
                              "  set Model = von Mises plasticity\n"
                              "  subsection Von Mises plasticity\n"
                              "    set Yield stress = 3e8\n"
                              "    set Hardening modulus = 1e9\n"
                              "  end\n"
                              "end\n");
  prm.enter_subsection("Material");
  const auto material =
    create_material(prm, KinematicAssumption::three_dimensional, "Material");
  prm.leave_subsection();
  const auto &plastic = dynamic_cast<const VonMisesPlasticity &>(*material);
  BOOST_TEST(plastic.yield_stress() == 3e8);
  BOOST_TEST(plastic.hardening_modulus() == 1e9);
  BOOST_TEST(plastic.history_names().at(0) == "equivalent plastic strain");
}

BOOST_AUTO_TEST_CASE(input_errors)
{
  dealii::ParameterHandler prm;
  declare_material_parameters(prm);

  const auto message_of = [&](const KinematicAssumption k) -> std::string {
    try
      {
        create_material(prm, k, "Material 2");
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  };

  // Unsupported combinations.
  for (const std::string name :
       {"neo-Hookean", "Newtonian fluid", "von Mises plasticity"})
    {
      prm.set("Model", name);
      for (const auto k : {KinematicAssumption::plane_stress,
                           KinematicAssumption::uniaxial_stress})
        {
          const std::string message = message_of(k);
          BOOST_TEST(message ==
                     "Material 2: material model '" + name +
                       "' does not support the kinematic assumption '" +
                       to_string(k) + "'");
        }
    }
  prm.set("Model", "linear elastic");
  BOOST_TEST(message_of(KinematicAssumption::uniaxial_stress).empty());

  // Bad Poisson's ratio.
  prm.enter_subsection("Linear elastic");
  prm.set("Poisson's ratio", "0.5");
  prm.leave_subsection();
  std::string message = message_of(KinematicAssumption::three_dimensional);
  BOOST_TEST(message.find("Material 2") != std::string::npos);
  BOOST_TEST(message.find("Poisson's ratio = 0.5 is out of range [0, 0.5)") !=
             std::string::npos);
  prm.enter_subsection("Linear elastic");
  prm.set("Poisson's ratio", "-0.1");
  prm.leave_subsection();
  BOOST_CHECK_THROW(create_material(prm,
                                    KinematicAssumption::three_dimensional,
                                    "Material"),
                    InputError);
  prm.enter_subsection("Linear elastic");
  prm.set("Poisson's ratio", "0.25");
  prm.leave_subsection();

  // Density.
  prm.set("Density", "0");
  message = message_of(KinematicAssumption::three_dimensional);
  BOOST_TEST(message.find("Material 2") != std::string::npos);
  BOOST_TEST(message.find("Density") != std::string::npos);
  prm.set("Density", "1000");

  // Other model parameters.
  const std::vector<std::array<std::string, 4>> bad = {
    {{"Newtonian fluid", "Newtonian fluid", "Viscosity", "-1"}},
    {{"Newtonian fluid", "Newtonian fluid", "Bulk modulus", "0"}},
    {{"Newtonian fluid", "Newtonian fluid", "Tait exponent", "0.5"}},
    {{"von Mises plasticity", "Von Mises plasticity", "Yield stress", "0"}},
    {{"von Mises plasticity",
      "Von Mises plasticity",
      "Hardening modulus",
      "-1"}},
    {{"neo-Hookean", "Neo-Hookean", "Young's modulus", "0"}}};
  for (const auto &b : bad)
    {
      BOOST_TEST_CONTEXT(b[2] << " = " << b[3])
      {
        prm.set("Model", b[0]);
        prm.enter_subsection(b[1]);
        const std::string good = prm.get(b[2]);
        prm.set(b[2], b[3]);
        prm.leave_subsection();
        message = message_of(KinematicAssumption::three_dimensional);
        BOOST_TEST(message.find(b[2] + " = " + b[3]) != std::string::npos);
        prm.enter_subsection(b[1]);
        prm.set(b[2], good);
        prm.leave_subsection();
        BOOST_TEST(message_of(KinematicAssumption::three_dimensional).empty());
      }
    }
}

BOOST_AUTO_TEST_SUITE_END()
