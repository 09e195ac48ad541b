// The assumed-stress filter as a projection:
// idempotent, exact on its span (also on distorted cells), commutes with
// rigid rotations, removes the parasitic shear of one bending cell, and
// falls back to constant stress on degenerate particle layouts.
#define BOOST_TEST_MODULE assumed_stress
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <mpm/remedies/assumed_stress.h>
#include <mpm/shape_functions/q1_cell.h>

#include <random>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using namespace mpm::remedies;

namespace
{
  template <int dim>
  mpm::shape_functions::Q1Cell<dim>
  distorted_cell(const unsigned int seed)
  {
    std::mt19937                                            gen(seed);
    std::uniform_real_distribution<double>                  u(-0.15, 0.15);
    std::array<Point<dim>, mpm::shape_functions::n_q1<dim>> v;
    for (unsigned int i = 0; i < v.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        v[i][d] = 2.0 + (((i >> d) & 1) ? 0.5 : 0.) + 0.5 * u(gen);
    mpm::shape_functions::Q1Cell<dim> c;
    c.reinit(v, 1e-12);
    return c;
  }

  template <int dim>
  std::vector<StressSample<dim>>
  samples(const unsigned int n, const unsigned int seed)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> u(0.05, 0.95), w(0.5, 2.0),
      s(-100, 100);
    std::vector<StressSample<dim>> out(n);
    for (auto &p : out)
      {
        for (unsigned int d = 0; d < dim; ++d)
          p.xi[d] = u(gen);
        p.weight = w(gen);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            p.stress[i][j] = s(gen);
      }
    return out;
  }

  template <int dim>
  Tensor<2, dim>
  centre_jacobian(const mpm::shape_functions::Q1Cell<dim> &c)
  {
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5;
    return c.jacobian(centre);
  }

  template <int dim>
  double
  max_difference(const std::vector<StressSample<dim>> &a,
                 const std::vector<StressSample<dim>> &b)
  {
    double m = 0;
    for (unsigned int p = 0; p < a.size(); ++p)
      m = std::max(m, (a[p].stress - b[p].stress).norm());
    return m;
  }

  template <int dim>
  void
  check_projection(const Metric metric, const bool enriched = false)
  {
    const auto compliance = isotropic_compliance<dim>(1e6, 0.3, false);
    for (unsigned int seed = 0; seed < 5; ++seed)
      {
        const auto                         cell = distorted_cell<dim>(seed);
        const AssumedStressProjection<dim> P(centre_jacobian(cell),
                                             metric,
                                             compliance,
                                             enriched);
        const unsigned int                 n = dim == 2 ? 9 : 27;

        // idempotent
        auto once = samples<dim>(n, seed);
        BOOST_TEST(
          (P.project(once) == AssumedStressProjection<dim>::Result::full));
        auto twice = once;
        P.project(twice);
        BOOST_TEST(max_difference(once, twice) < 1e-10 * 100);

        // exact on the span of S
        std::mt19937                           gen(seed + 10);
        std::uniform_real_distribution<double> u(-50, 50);
        double beta[AssumedStressProjection<dim>::n_beta];
        for (auto &b : beta)
          b = u(gen);
        auto in_span = samples<dim>(n, seed + 20);
        for (auto &p : in_span)
          p.stress = P.field(p.xi, beta);
        auto projected = in_span;
        P.project(projected);
        BOOST_TEST(max_difference(in_span, projected) < 1e-9 * 100);
      }
  }

  template <int dim>
  void
  check_rotation(const Metric metric, const bool enriched = false)
  {
    const auto compliance = isotropic_compliance<dim>(1e6, 0.3, false);
    const auto cell       = distorted_cell<dim>(3);
    const auto J0         = centre_jacobian(cell);
    // a rotation Q
    Tensor<2, dim> Q;
    const double   a = 0.7, c = std::cos(a), s = std::sin(a);
    Q[0][0] = c, Q[0][1] = -s, Q[1][0] = s, Q[1][1] = c;
    if (dim == 3)
      Q[2][2] = 1;
    const AssumedStressProjection<dim> P(J0, metric, compliance, enriched);
    const AssumedStressProjection<dim> PQ(Q * J0, metric, compliance, enriched);
    auto original = samples<dim>(dim == 2 ? 9 : 27, 4);
    auto rotated  = original;
    for (auto &p : rotated)
      p.stress =
        symmetrize(Tensor<2, dim>(Q * Tensor<2, dim>(p.stress) * transpose(Q)));
    P.project(original);
    PQ.project(rotated);
    double m = 0;
    for (unsigned int p = 0; p < original.size(); ++p)
      {
        const auto expected = symmetrize(Tensor<2, dim>(
          Q * Tensor<2, dim>(original[p].stress) * transpose(Q)));
        m = std::max(m, (expected - rotated[p].stress).norm());
      }
    BOOST_TEST(m < 1e-9 * 100);
  }
} // namespace

BOOST_AUTO_TEST_CASE(projection_2d)
{
  check_projection<2>(Metric::mass);
  check_projection<2>(Metric::compliance);
}

BOOST_AUTO_TEST_CASE(projection_3d)
{
  check_projection<3>(Metric::mass);
  check_projection<3>(Metric::compliance);
}

// The enriched field (Filter field = enriched): the same projection
// properties, and it keeps a normal stress varying along its own direction,
// which the Pian-Sumihara field cannot.
BOOST_AUTO_TEST_CASE(enriched_projection)
{
  check_projection<2>(Metric::mass, true);
  check_projection<2>(Metric::compliance, true);
  check_projection<3>(Metric::mass, true);
  check_projection<3>(Metric::compliance, true);
  check_rotation<2>(Metric::mass, true);
  check_rotation<3>(Metric::compliance, true);

  // sigma_xx = 10 + 3 x on a unit box cell (x = xi): kept by the enriched
  // field, flattened to its mean by Pian-Sumihara
  const Tensor<2, 2>           J = unit_symmetric_tensor<2>();
  std::vector<StressSample<2>> s;
  for (const double x : {0.2, 0.4, 0.6, 0.8})
    for (const double y : {0.25, 0.75})
      {
        StressSample<2> p;
        p.xi           = Point<2>(x, y);
        p.weight       = 1;
        p.stress[0][0] = 10 + 3 * x;
        s.push_back(p);
      }
  auto enriched = s, plain = s;
  AssumedStressProjection<2>(J, Metric::mass, {}, true).project(enriched);
  AssumedStressProjection<2>(J, Metric::mass).project(plain);
  BOOST_TEST(max_difference(enriched, s) < 1e-12);
  BOOST_TEST(max_difference(plain, s) > 0.5);
  BOOST_TEST(AssumedStressProjection<2>(J, Metric::mass, {}, true).size() ==
             7u);
  BOOST_TEST(
    AssumedStressProjection<3>(unit_symmetric_tensor<3>(), Metric::mass)
      .size() == 18u);
}

BOOST_AUTO_TEST_CASE(commutes_with_rotation)
{
  check_rotation<2>(Metric::mass);
  check_rotation<2>(Metric::compliance);
  check_rotation<3>(Metric::mass);
  check_rotation<3>(Metric::compliance);
}

// One square cell in pure bending u = (kappa x y, -kappa x^2/2) seen by Q1:
// the particles get sigma_xx linear in y (kept by beta_4 t) and a
// parasitic shear linear in x (removed: the shear field is constant and
// the particles lie symmetric about the centre).
BOOST_AUTO_TEST_CASE(bending_cell_loses_parasitic_shear)
{
  const double                 G = 1e3;
  std::vector<StressSample<2>> p;
  for (const double x : {0.25, 0.75})
    for (const double y : {0.25, 0.75})
      {
        StressSample<2> s;
        s.xi           = Point<2>(x, y);
        s.weight       = 1;
        s.stress[0][0] = 100 * (y - 0.5);
        s.stress[0][1] = G * (x - 0.5); // parasitic
        p.push_back(s);
      }
  Tensor<2, 2> J;
  J[0][0] = J[1][1] = 1;
  const AssumedStressProjection<2> P(J, Metric::mass);
  P.project(p);
  for (const auto &s : p)
    {
      BOOST_TEST(std::abs(s.stress[0][1]) < 1e-12);
      BOOST_TEST(std::abs(s.stress[0][0] - 100 * (s.xi[1] - 0.5)) < 1e-12);
    }
}

BOOST_AUTO_TEST_CASE(degenerate_layouts_fall_back)
{
  Tensor<2, 2> J;
  J[0][0] = J[1][1] = 1;
  const AssumedStressProjection<2> P(J, Metric::mass);
  using R = AssumedStressProjection<2>::Result;

  // one particle: its own (constant) stress
  auto       one    = samples<2>(1, 7);
  const auto before = one[0].stress;
  BOOST_TEST((P.project(one) == R::constant));
  BOOST_TEST((one[0].stress - before).norm() < 1e-12 * before.norm());

  // collinear particles (all at the same eta): the t-linear term is
  // undetermined, the mean stress is kept
  auto                  line = samples<2>(4, 8);
  SymmetricTensor<2, 2> mean;
  double                total = 0;
  for (auto &s : line)
    {
      s.xi[1] = 0.3;
      mean += s.weight * s.stress;
      total += s.weight;
    }
  mean /= total;
  BOOST_TEST((P.project(line) == R::constant));
  for (const auto &s : line)
    {
      BOOST_TEST(std::isfinite(s.stress.norm()));
      BOOST_TEST((s.stress - mean).norm() < 1e-9 * mean.norm());
    }

  // no weight: nothing changes
  auto none = samples<2>(3, 9);
  for (auto &s : none)
    s.weight = 0;
  const auto copy = none;
  BOOST_TEST((P.project(none) == R::unchanged));
  BOOST_TEST(max_difference(copy, none) == 0.);

  // empty cell
  std::vector<StressSample<2>> empty;
  BOOST_TEST((P.project(empty) == R::unchanged));
}
