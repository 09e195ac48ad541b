// The manufactured solution u_i = G sin(pi X_i) sin(c pi t + phi_i)
// (doc/benchmarks/manufactured_solution.md,
// doc/benchmarks/manufactured_solution.md): its body force is rho0 d2u/dt2 -
// Div P over rho0 with P the first Piola-Kirchhoff stress of the project's
// neo-Hookean model (plane strain in 2D), both derivatives taken by finite
// differences of the displacement, so the hand derivation is checked against
// the code's material law; its velocity is du/dt; it satisfies the slip walls
// of the unit square/cube.
#define BOOST_TEST_MODULE manufactured_solution
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <mpm/benchmarks/manufactured_solution.h>
#include <mpm/materials/neo_hookean.h>

#include <cmath>
#include <random>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using mpm::benchmarks::ManufacturedSolution;

namespace
{
  constexpr double E = 1e7, nu = 0.3, rho = 1000;

  mpm::materials::NeoHookean
  neo_hookean(const mpm::KinematicAssumption k)
  {
    ParameterHandler prm;
    mpm::materials::NeoHookean::declare_parameters(prm);
    prm.set("Young's modulus", std::to_string(E));
    prm.set("Poisson's ratio", std::to_string(nu));
    mpm::materials::NeoHookean model;
    model.set_common(rho, k);
    model.parse_parameters(prm);
    return model;
  }

  /// F = I + Grad u by central differences, embedded in 3D (plane strain).
  template <int dim>
  Tensor<2, 3>
  deformation_gradient(const ManufacturedSolution<dim> &exact,
                       const Point<dim>                &X,
                       const double                     t)
  {
    const double eps = 1e-6;
    Tensor<2, 3> F   = unit_symmetric_tensor<3>();
    for (unsigned int j = 0; j < dim; ++j)
      {
        Point<dim> a = X, b = X;
        a[j] += eps;
        b[j] -= eps;
        const Tensor<1, dim> du =
          (exact.displacement(a, t) - exact.displacement(b, t)) / (2 * eps);
        for (unsigned int i = 0; i < dim; ++i)
          F[i][j] += du[i];
      }
    return F;
  }

  template <int dim>
  void
  check_body_force(const double G)
  {
    const ManufacturedSolution<dim> exact(G, E, nu, rho);
    const auto                      model =
      neo_hookean(dim == 2 ? mpm::KinematicAssumption::plane_strain :
                             mpm::KinematicAssumption::three_dimensional);
    const double c = exact.wave_speed();
    BOOST_TEST(std::abs(c - 100.) < 1e-12);
    auto piola = [&](const Point<dim> &X, const double t) {
      const Tensor<2, 3> F = deformation_gradient(exact, X, t);
      return determinant(F) *
             Tensor<2, 3>(model.cauchy_stress(F) * transpose(invert(F)));
    };
    // the scale of every term: rho0 |d2u/dt2| = rho0 G (c pi)^2
    const double scale = G * c * c * M_PI * M_PI;

    std::mt19937                           gen(11);
    std::uniform_real_distribution<double> unit(0., 1.);
    double                                 worst = 0;
    for (unsigned int q = 0; q < 20; ++q)
      {
        Point<dim> X;
        for (unsigned int d = 0; d < dim; ++d)
          X[d] = 0.02 + 0.96 * unit(gen);
        const double t = 2 / c * unit(gen);

        const double         dt = 1e-7;
        const Tensor<1, dim> acceleration =
          (exact.displacement(X, t + dt) - 2 * exact.displacement(X, t) +
           exact.displacement(X, t - dt)) /
          (dt * dt);
        const double   h = 1e-4;
        Tensor<1, dim> div_P;
        for (unsigned int j = 0; j < dim; ++j)
          {
            Point<dim> a = X, b = X;
            a[j] += h;
            b[j] -= h;
            const Tensor<2, 3> dP = (piola(a, t) - piola(b, t)) / (2 * h);
            for (unsigned int i = 0; i < dim; ++i)
              div_P[i] += dP[i][j];
          }
        const Tensor<1, dim> error =
          exact.body_force(X, t) - (acceleration - div_P / rho);
        worst = std::max(worst, error.norm() / scale);
      }
    BOOST_TEST_MESSAGE("dim " << dim << " G " << G << ": body force error "
                              << worst);
    // finite-difference truncation and round-off are about 1e-7 of the scale
    BOOST_TEST(worst < 1e-5);
  }

  template <int dim>
  void
  check_kinematics(const double G)
  {
    const ManufacturedSolution<dim>        exact(G, E, nu, rho);
    const double                           c = exact.wave_speed();
    std::mt19937                           gen(5);
    std::uniform_real_distribution<double> unit(0., 1.);
    for (unsigned int q = 0; q < 10; ++q)
      {
        Point<dim> X;
        for (unsigned int d = 0; d < dim; ++d)
          X[d] = unit(gen);
        const double         t = 2 / c * unit(gen), dt = 1e-8;
        const Tensor<1, dim> dudt =
          (exact.displacement(X, t + dt) - exact.displacement(X, t - dt)) /
          (2 * dt);
        BOOST_TEST((exact.velocity(X, t) - dudt).norm() < 1e-6 * G * c);
        BOOST_TEST(exact.displacement(X, 0).norm() < 1e-15 * G);
        // the normal displacement vanishes on the faces X_d = 0 and 1
        for (unsigned int d = 0; d < dim; ++d)
          for (const double face : {0., 1.})
            {
              Point<dim> Y = X;
              Y[d]         = face;
              BOOST_TEST(std::abs(exact.displacement(Y, t)[d]) < 1e-15 * G);
            }
      }
    // phi = (0, pi, pi): the first component leads, the others are opposite
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5;
    const Tensor<1, dim> v0 = exact.velocity(centre, 0);
    BOOST_TEST(std::abs(v0[0] - G * c * M_PI) < 1e-12 * G * c);
    for (unsigned int d = 1; d < dim; ++d)
      BOOST_TEST(std::abs(v0[d] + G * c * M_PI) < 1e-12 * G * c);
  }
} // namespace

BOOST_AUTO_TEST_CASE(body_force_2d_plane_strain)
{
  check_body_force<2>(1e-4);
  check_body_force<2>(0.05);
}

BOOST_AUTO_TEST_CASE(body_force_3d)
{
  check_body_force<3>(1e-4);
  check_body_force<3>(0.05);
}

BOOST_AUTO_TEST_CASE(velocity_and_boundaries)
{
  check_kinematics<2>(1e-4);
  check_kinematics<2>(0.05);
  check_kinematics<3>(0.05);
}
