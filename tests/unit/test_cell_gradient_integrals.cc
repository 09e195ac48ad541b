#define BOOST_TEST_MODULE cell_gradient_integrals
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
// The cell integrals behind a fluid's cell pressure over its cell
// (remedies::cell_gradient_integrals, cell_mean_velocity_gradient), on
// boxes (closed form) and distorted bilinear and trilinear cells (the
// 2^dim-point Gauss rule) against a 3^dim-point Gauss rule (both exact if the
// claim holds: the difference is round-off), the integrals sum to zero (a
// uniform pressure has no resultant), sum_v x_v (x) int grad N_v = |c| I, and
// the mean velocity gradient of a linear field is its gradient.
#include <deal.II/base/tensor.h>

#include <mpm/grid/nodal_layout.h>
#include <mpm/remedies/cell_pressure_force.h>

#include <array>
#include <cmath>
#include <vector>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using mpm::shape_functions::Q1Cell;

namespace
{
  /// The unit cube stretched and with each vertex moved by up to
  /// @p amplitude in each direction (deterministic in @p seed): a general
  /// bilinear (trilinear) cell, or with 0 a box (the closed form).
  template <int dim>
  Q1Cell<dim>
  distorted_cell(const unsigned int seed, const double amplitude)
  {
    std::array<Point<dim>, Q1Cell<dim>::n_vertices> corners;
    for (unsigned int i = 0; i < corners.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        corners[i][d] = (((i >> d) & 1) ? 1. + 0.2 * d : 0.) +
                        amplitude * std::sin(1.7 * seed + 2.3 * i + 0.9 * d);
    Q1Cell<dim> cell;
    cell.reinit(corners, 1e-12);
    return cell;
  }

  /// int_c grad N_v by the 3^dim-point Gauss rule.
  template <int dim>
  double
  three_point_integrals(const Q1Cell<dim> &geo, Tensor<1, dim> *integral)
  {
    constexpr unsigned int nv      = Q1Cell<dim>::n_vertices;
    const double           x[3]    = {0.5 - 0.5 * std::sqrt(0.6),
                                      0.5,
                                      0.5 + 0.5 * std::sqrt(0.6)};
    const double           w[3]    = {5. / 18, 8. / 18, 5. / 18};
    double                 measure = 0;
    unsigned int           n       = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= 3;
    for (unsigned int q = 0; q < n; ++q)
      {
        Point<dim>   xi;
        double       weight = 1;
        unsigned int k      = q;
        for (unsigned int d = 0; d < dim; ++d, k /= 3)
          {
            xi[d] = x[k % 3];
            weight *= w[k % 3];
          }
        Tensor<1, dim> grad[nv];
        geo.gradients(xi, grad);
        weight *= determinant(geo.jacobian(xi));
        measure += weight;
        for (unsigned int v = 0; v < nv; ++v)
          integral[v] += weight * grad[v];
      }
    return measure;
  }

  template <int dim>
  void
  check(const unsigned int seed, const double amplitude)
  {
    constexpr unsigned int nv  = Q1Cell<dim>::n_vertices;
    const Q1Cell<dim>      geo = distorted_cell<dim>(seed, amplitude);
    BOOST_TEST(geo.is_box == (amplitude == 0));
    Tensor<1, dim> two[nv], three[nv];
    const double   measure = mpm::remedies::cell_gradient_integrals(geo, two);
    BOOST_TEST(std::abs(measure - three_point_integrals(geo, three)) <=
               1e-14 * measure);
    Tensor<1, dim> resultant;
    Tensor<2, dim> moment;
    for (unsigned int v = 0; v < nv; ++v)
      {
        BOOST_TEST((two[v] - three[v]).norm() <= 1e-14 * measure);
        resultant += two[v];
        moment += outer_product(Tensor<1, dim>(geo.vertices[v]), two[v]);
      }
    BOOST_TEST(resultant.norm() <= 1e-14 * measure);
    BOOST_TEST((moment / measure - unit_symmetric_tensor<dim>()).norm() <=
               1e-13);

    // v = A x + b at the nodes, in the kinematics layout
    using K = mpm::KinematicsLayout<dim>;
    Tensor<2, dim> A;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        A[i][j] = 0.3 * i - 0.7 * j + 0.1 * (i + 1) * (j + 2);
    std::vector<double>       kinematics(nv * K::n_components);
    std::vector<unsigned int> nodes(nv);
    for (unsigned int v = 0; v < nv; ++v)
      {
        nodes[v]                 = nv - 1 - v; // any numbering
        const Tensor<1, dim> vel = A * geo.vertices[v];
        double *node = kinematics.data() + nodes[v] * K::n_components;
        for (unsigned int d = 0; d < dim; ++d)
          node[K::velocity + d] = vel[d] + 0.5;
      }
    const Tensor<2, dim> L =
      mpm::remedies::cell_mean_velocity_gradient(geo,
                                                 nodes.data(),
                                                 kinematics.data());
    BOOST_TEST((L - A).norm() <= 1e-13 * A.norm());
  }
} // namespace

BOOST_AUTO_TEST_CASE(boxes)
{
  check<2>(1, 0.);
  check<3>(1, 0.);
}

BOOST_AUTO_TEST_CASE(bilinear_cells)
{
  for (unsigned int seed = 1; seed <= 5; ++seed)
    check<2>(seed, 0.15);
}

BOOST_AUTO_TEST_CASE(trilinear_cells)
{
  for (unsigned int seed = 1; seed <= 5; ++seed)
    check<3>(seed, 0.15);
}
