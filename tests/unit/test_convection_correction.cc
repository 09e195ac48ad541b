// The 1D convection correction of one cell
// (doc/theory/convection_correction.md): the corrected quadrature sum_p V_p
// (sigma_p + Delta) is the exact integral of the particles' least-squares line
// over the occupied part of the cell; no shift for particles centred in a full
// cell or for a constant stress; the seed's two-particle cell; one particle
// borrowing a neighbour.
#define BOOST_TEST_MODULE convection_correction
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <mpm/remedies/convection_correction.h>

#include <random>

#include <boost/test/unit_test.hpp>

using namespace mpm::remedies;

namespace
{
  double
  corrected_sum(const std::vector<AxialSample> &s, const double delta)
  {
    double sum = 0;
    for (const auto &p : s)
      sum += p.volume * (p.value + delta);
    return sum;
  }

  // n particles at random positions in [lo, hi] (natural coordinates)
  // with the linear stress c + g r.
  std::vector<AxialSample>
  linear_samples(const unsigned int n,
                 const double       lo,
                 const double       hi,
                 const double       c,
                 const double       g,
                 const unsigned int seed)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> u(lo, hi), w(0.02, 0.1);
    std::vector<AxialSample>               out(n);
    for (auto &p : out)
      {
        p.r      = u(gen);
        p.volume = w(gen);
        p.value  = c + g * p.r;
      }
    return out;
  }
} // namespace

BOOST_AUTO_TEST_CASE(exact_for_a_linear_stress)
{
  const double h = 0.2, c = -3.0, g = 1.7;
  for (unsigned int seed = 0; seed < 20; ++seed)
    for (const unsigned int n : {2u, 3u, 4u, 7u})
      {
        // full cell
        auto s = linear_samples(n, -1, 1, c, g, seed);
        BOOST_TEST(corrected_sum(s, convection_shift(s, nullptr, -1, 1, h)) ==
                     h * c,
                   boost::test_tools::tolerance(1e-12));
        // a free end: the body occupies [a, 1]
        const double a     = -0.4;
        s                  = linear_samples(n, a, 1, c, g, seed);
        const double exact = 0.5 * h * (c * (1 - a) + 0.5 * g * (1 - a * a));
        BOOST_TEST(corrected_sum(s, convection_shift(s, nullptr, a, 1, h)) ==
                     exact,
                   boost::test_tools::tolerance(1e-12));
      }
}

BOOST_AUTO_TEST_CASE(no_shift_when_the_quadrature_is_exact)
{
  const double h = 0.2;
  // the seed's cell: two equal particles at xi = 1/4, 3/4, any stresses
  std::vector<AxialSample> s = {{-0.5, 0.1, 2.0}, {0.5, 0.1, -5.0}};
  BOOST_TEST(std::abs(convection_shift(s, nullptr, -1, 1, h)) < 1e-14);
  // a constant stress whose particles fill the cell, at any positions
  s        = linear_samples(5, -1, 1, 4.0, 0.0, 3);
  double V = 0;
  for (const auto &p : s)
    V += p.volume;
  for (auto &p : s)
    p.volume *= h / V;
  BOOST_TEST(std::abs(convection_shift(s, nullptr, -1, 1, h)) < 1e-13);
}

BOOST_AUTO_TEST_CASE(seed_cell_convected)
{
  // Two equal particles shifted by r0 from the symmetric places: the
  // particle sum takes the line at r0 instead of the centre, and the shift
  // is -b2 r0 (b2 the slope, here the stress difference).
  const double h = 0.2, s1 = 1.0, s2 = 3.0;
  for (const double r0 : {-0.4, -0.1, 0.2, 0.45})
    {
      const std::vector<AxialSample> s = {{r0 - 0.5, 0.5 * h, s1},
                                          {r0 + 0.5, 0.5 * h, s2}};
      BOOST_TEST(convection_shift(s, nullptr, -1, 1, h) == -(s2 - s1) * r0,
                 boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(one_particle)
{
  const double                   h = 0.2;
  const std::vector<AxialSample> s = {{0.6, 0.05, 2.0}};
  // alone: its constant stress over the occupied part [0.1, 1]
  BOOST_TEST(corrected_sum(s, convection_shift(s, nullptr, 0.1, 1, h)) ==
               0.5 * h * 0.9 * 2.0,
             boost::test_tools::tolerance(1e-12));
  // with the nearest particle of the neighbour (r = 1.4, stress 3): the
  // line through both, 2 + 1.25 (r - 0.6), integrated over [0.1, 1]
  const AxialSample extra{1.4, 0.05, 3.0};
  BOOST_TEST(corrected_sum(s, convection_shift(s, &extra, 0.1, 1, h)) ==
               0.5 * h * 0.9 * (2.0 + 1.25 * (0.55 - 0.6)),
             boost::test_tools::tolerance(1e-12));
  // the neighbour is ignored when the cell's particles determine a line
  const std::vector<AxialSample> two = {{-0.5, 0.1, 1.0}, {0.5, 0.1, 2.0}};
  BOOST_TEST(convection_shift(two, &extra, -1, 1, h) ==
               convection_shift(two, nullptr, -1, 1, h),
             boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(line_moments)
{
  // The body-force part integrates the line against N = (1 -+ r)/2: the
  // moments of 2 + 3 r over [-0.5, 1] are 4.125 and 1.875.
  const std::vector<AxialSample> s    = {{-0.3, 0.1, 2 - 0.9},
                                         {0.7, 0.3, 2 + 2.1}};
  const CellLine                 line = CellLine::fit(s, nullptr);
  BOOST_TEST(line.moment(-0.5, 1, 0) == 4.125,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(line.moment(-0.5, 1, 1) == 1.875,
             boost::test_tools::tolerance(1e-12));
}
