// Q1 shape functions evaluated without FEValues: on boxes (fast path) and
// on distorted cells they form a partition of unity, their gradients sum to
// zero, linear fields are reproduced exactly, and they agree with a
// finite-difference derivative of the mapped values.
#define BOOST_TEST_MODULE q1_cell
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <mpm/shape_functions/q1_cell.h>

#include <random>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using mpm::shape_functions::Q1Cell;

namespace
{
  template <int dim>
  Q1Cell<dim>
  make_cell(const bool distorted, const unsigned int seed)
  {
    std::mt19937                                    gen(seed);
    std::uniform_real_distribution<double>          u(-0.2, 0.2);
    std::array<Point<dim>, Q1Cell<dim>::n_vertices> v;
    for (unsigned int i = 0; i < Q1Cell<dim>::n_vertices; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        v[i][d] = 1.0 + 0.5 * d + (((i >> d) & 1) ? 0.3 + 0.1 * d : 0.) +
                  (distorted ? 0.1 * u(gen) : 0.);
    Q1Cell<dim> c;
    c.reinit(v, 1e-12);
    return c;
  }

  template <int dim>
  void
  check_cell(const Q1Cell<dim> &cell)
  {
    constexpr unsigned int nv = Q1Cell<dim>::n_vertices;
    // a linear field u(x) = a + B x
    Tensor<1, dim> a;
    Tensor<2, dim> B;
    for (unsigned int i = 0; i < dim; ++i)
      {
        a[i] = 0.3 + i;
        for (unsigned int j = 0; j < dim; ++j)
          B[i][j] = 0.7 * i - 1.1 * j + 0.2;
      }
    std::mt19937                           gen(7);
    std::uniform_real_distribution<double> u(0., 1.);
    for (unsigned int q = 0; q < 20; ++q)
      {
        Point<dim> xi;
        for (unsigned int d = 0; d < dim; ++d)
          xi[d] = u(gen);
        double         N[nv];
        Tensor<1, dim> G[nv];
        cell.values_and_gradients(xi, N, G);
        double         sum = 0;
        Tensor<1, dim> gsum, value;
        Tensor<2, dim> grad;
        for (unsigned int v = 0; v < nv; ++v)
          {
            sum += N[v];
            gsum += G[v];
            const Tensor<1, dim> uv = a + B * cell.vertices[v];
            value += N[v] * uv;
            grad += outer_product(uv, G[v]);
          }
        BOOST_TEST(std::abs(sum - 1) < 1e-14);
        BOOST_TEST(gsum.norm() < 1e-12);
        const Point<dim> x = cell.map(xi);
        BOOST_TEST((value - (a + B * x)).norm() < 1e-13);
        BOOST_TEST((grad - B).norm() < 1e-12);

        // gradients against central differences in physical space
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double   eps = 1e-6;
            const auto     J   = cell.jacobian(xi);
            Tensor<1, dim> e;
            e[d]                     = eps;
            const Tensor<1, dim> dxi = invert(J) * e;
            double               Np[nv], Nm[nv];
            Q1Cell<dim>::values(xi + dxi, Np);
            Q1Cell<dim>::values(xi - dxi, Nm);
            for (unsigned int v = 0; v < nv; ++v)
              BOOST_TEST(std::abs((Np[v] - Nm[v]) / (2 * eps) - G[v][d]) <
                         1e-6);
          }
      }
  }
} // namespace

BOOST_AUTO_TEST_CASE(box_fast_path_is_detected)
{
  BOOST_TEST(make_cell<1>(false, 1).is_box);
  BOOST_TEST(make_cell<2>(false, 1).is_box);
  BOOST_TEST(make_cell<3>(false, 1).is_box);
  BOOST_TEST(!make_cell<2>(true, 1).is_box);
  BOOST_TEST(!make_cell<3>(true, 1).is_box);
}

BOOST_AUTO_TEST_CASE(boxes)
{
  check_cell(make_cell<1>(false, 1));
  check_cell(make_cell<2>(false, 1));
  check_cell(make_cell<3>(false, 1));
}

BOOST_AUTO_TEST_CASE(distorted_cells)
{
  for (unsigned int s = 0; s < 5; ++s)
    {
      check_cell(make_cell<2>(true, s));
      check_cell(make_cell<3>(true, s));
    }
}

BOOST_AUTO_TEST_CASE(parallelogram)
{
  std::array<Point<2>, 4> v = {{Point<2>(0, 0),
                                Point<2>(1, 0.2),
                                Point<2>(0.5, 1),
                                Point<2>(1.5, 1.2)}};
  Q1Cell<2>               c;
  c.reinit(v, 1e-12);
  BOOST_TEST(!c.is_box);
  check_cell(c);
}
