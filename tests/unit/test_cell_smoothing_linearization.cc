#define BOOST_TEST_MODULE cell_smoothing_linearization
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
// The linearization of `Volumetric smoothing = cell` in the implicit step
// (remedies::LinearizedCellSmoothing): the derivative of a particle's
// material increment by a nodal increment against central differences of
// material_increment(), for the rate form (B-bar) and the total form
// (F-bar), in 1D, 2D and 3D, with four particles of one body and one of
// another body (which must not enter the first body's average). Largest
// difference relative to the largest entry at most 1e-6.
#include <deal.II/base/tensor.h>

#include <mpm/remedies/linearized_cell_smoothing.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/test/unit_test.hpp>

using dealii::Tensor;

namespace
{
  /// A deterministic sequence in [-1, 1].
  double
  next(unsigned int &seed)
  {
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 8) % 20001) / 10000. - 1.;
  }

  template <int dim>
  struct Cell
  {
    static constexpr unsigned int nv = mpm::shape_functions::n_q1<dim>;
    using Smoothing = mpm::remedies::LinearizedCellSmoothing<dim>;

    std::vector<unsigned int>                body;
    std::vector<std::vector<Tensor<1, dim>>> G;
    std::vector<Tensor<2, dim>>              F_n;
    std::vector<double>                      V0;
    std::vector<typename Smoothing::Point>   points;

    explicit Cell(unsigned int seed)
    {
      for (unsigned int q = 0; q < 5; ++q)
        {
          body.push_back(q == 4 ? 1 : 0);
          G.emplace_back(nv);
          for (auto &g : G.back())
            for (unsigned int d = 0; d < dim; ++d)
              g[d] = next(seed);
          Tensor<2, dim> F;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              F[i][j] = (i == j) + 0.2 * next(seed);
          F_n.push_back(F);
          V0.push_back(1 + 0.5 * next(seed));
        }
    }

    /// The points of the nodal increment @p u, added to @p s.
    void
    evaluate(const std::vector<Tensor<1, dim>> &u, Smoothing &s)
    {
      points.assign(body.size(), {});
      s.reset();
      for (unsigned int q = 0; q < body.size(); ++q)
        {
          auto &p = points[q];
          p.body  = body[q];
          for (unsigned int a = 0; a < nv; ++a)
            for (unsigned int i = 0; i < dim; ++i)
              p.h[i] += u[a][i] * G[q][a];
          p.f = dealii::unit_symmetric_tensor<dim>();
          p.f += p.h;
          p.j     = dealii::determinant(p.f);
          p.f_inv = dealii::invert(p.f);
          p.F     = p.f * F_n[q];
          p.V0    = V0[q];
          p.V_n   = dealii::determinant(F_n[q]) * V0[q];
          p.G     = G[q].data();
          if (s.smooths(p.body))
            s.add(p);
        }
    }
  };

  template <int dim>
  double
  largest_error(const bool total)
  {
    constexpr unsigned int        nv = Cell<dim>::nv;
    Cell<dim>                     cell(7 + dim + 10 * total);
    typename Cell<dim>::Smoothing smoothing(std::vector<char>{1, 1});
    unsigned int                  seed = 99;
    std::vector<Tensor<1, dim>>   u(nv);
    for (auto &ua : u)
      for (unsigned int d = 0; d < dim; ++d)
        ua[d] = 0.05 * next(seed);
    const auto h_eff = [&](const std::vector<Tensor<1, dim>> &v,
                           const unsigned int                 q) {
      cell.evaluate(v, smoothing);
      Tensor<2, dim> h_rate, F_bar, h;
      smoothing.material_increment(cell.points[q], total, h_rate, F_bar, h);
      return h;
    };
    double       error = 0, largest = 0;
    const double eps = 1e-6;
    for (unsigned int q = 0; q < cell.body.size(); ++q)
      for (unsigned int b = 0; b < nv; ++b)
        for (unsigned int k = 0; k < dim; ++k)
          {
            auto plus = u, minus = u;
            plus[b][k] += eps;
            minus[b][k] -= eps;
            const Tensor<2, dim> fd =
              (h_eff(plus, q) - h_eff(minus, q)) / (2 * eps);
            cell.evaluate(u, smoothing);
            Tensor<2, dim> h_rate, F_bar, h;
            smoothing.material_increment(
              cell.points[q], total, h_rate, F_bar, h);
            const Tensor<2, dim> exact =
              smoothing.derivative(cell.points[q], total, b, k);
            error   = std::max(error, (fd - exact).norm());
            largest = std::max(largest, exact.norm());
          }
    return error / largest;
  }
} // namespace

namespace
{
  void
  check(const double error)
  {
    BOOST_TEST_MESSAGE("relative difference " << error);
    BOOST_TEST(error <= 1e-6);
  }
} // namespace

BOOST_AUTO_TEST_CASE(rate_form_b_bar)
{
  check(largest_error<1>(false));
  check(largest_error<2>(false));
  check(largest_error<3>(false));
}

BOOST_AUTO_TEST_CASE(total_form_f_bar)
{
  check(largest_error<1>(true));
  check(largest_error<2>(true));
  check(largest_error<3>(true));
}
