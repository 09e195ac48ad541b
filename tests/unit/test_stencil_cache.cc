// The stencil cache (shape_functions/stencil_cache.h): a filled stencil
// comes back merged by node with its sums unchanged; a wrong particle id,
// an unfilled cell or a fill out of order is never served; a failed pass
// leaves the cache empty; forget() empties it; a ready cache is not
// refilled by the next pass.
#define BOOST_TEST_MODULE stencil_cache
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <mpm/shape_functions/stencil_cache.h>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using mpm::shape_functions::Stencil;
using mpm::shape_functions::StencilCache;

namespace
{
  /// A stencil naming nodes 7, 3, 7, 5 (node 7 twice, as GIMP appends).
  Stencil<2>
  sample(const double scale)
  {
    Stencil<2> s;
    s.n                          = 4;
    const unsigned int nodes[4]  = {7, 3, 7, 5};
    const double       values[4] = {0.1, 0.2, 0.3, 0.4};
    for (unsigned int k = 0; k < 4; ++k)
      {
        s.node[k]        = nodes[k];
        s.value[k]       = scale * values[k];
        s.gradient[k][0] = scale * (k + 1);
        s.gradient[k][1] = -scale * k;
      }
    return s;
  }
} // namespace

BOOST_AUTO_TEST_CASE(stored_stencils_come_back_merged)
{
  StencilCache<2> cache;
  cache.begin_pass(10, 4);
  cache.store(4, 0, 100, sample(1));
  cache.store(4, 1, 101, sample(2));
  cache.store(2, 0, 200, sample(3));
  cache.end_pass(true);
  BOOST_TEST(cache.ready());

  Stencil<2> s;
  BOOST_TEST(cache.load(4, 1, 101, s));
  BOOST_TEST(s.n == 3u); // 7, 3, 5
  BOOST_TEST(s.node[0] == 7u);
  BOOST_TEST(s.value[0] == 2 * (0.1 + 0.3),
             boost::test_tools::tolerance(1e-15));
  BOOST_TEST(s.gradient[0][0] == 2 * (1. + 3.));
  BOOST_TEST(s.gradient[0][1] == -2 * (0. + 2.));
  double sum = 0;
  for (unsigned int k = 0; k < s.n; ++k)
    sum += s.value[k];
  BOOST_TEST(sum == 2., boost::test_tools::tolerance(1e-15));
  BOOST_TEST(cache.load(2, 0, 200, s));
  BOOST_TEST(s.value[1] == 3 * 0.2, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(never_serves_another_particle)
{
  StencilCache<2> cache;
  cache.begin_pass(10, 4);
  cache.store(4, 0, 100, sample(1));
  cache.store(4, 1, 101, sample(2));
  cache.end_pass(true);
  Stencil<2> s;
  BOOST_TEST(!cache.load(4, 0, 101, s)); // wrong id at that place
  BOOST_TEST(!cache.load(4, 2, 102, s)); // beyond the cell's particles
  BOOST_TEST(!cache.load(5, 0, 100, s)); // a cell not filled
}

BOOST_AUTO_TEST_CASE(out_of_order_fill_is_not_used)
{
  StencilCache<2> cache;
  cache.begin_pass(10, 4);
  cache.store(4, 0, 100, sample(1));
  cache.store(4, 2, 102, sample(1)); // the second particle was skipped
  cache.end_pass(true);
  Stencil<2> s;
  BOOST_TEST(!cache.ready());
  BOOST_TEST(!cache.load(4, 0, 100, s));
  // not refilled before forget()
  cache.begin_pass(10, 4);
  cache.store(4, 0, 100, sample(1));
  cache.end_pass(true);
  BOOST_TEST(!cache.ready());
  cache.forget();
  cache.begin_pass(10, 4);
  cache.store(4, 0, 100, sample(1));
  cache.end_pass(true);
  BOOST_TEST(cache.load(4, 0, 100, s));
}

BOOST_AUTO_TEST_CASE(failed_pass_and_forget_empty_it)
{
  StencilCache<2> cache;
  Stencil<2>      s;
  cache.begin_pass(10, 4);
  cache.store(1, 0, 1, sample(1));
  cache.end_pass(false);
  BOOST_TEST(!cache.ready());
  BOOST_TEST(!cache.load(1, 0, 1, s));

  cache.begin_pass(10, 4);
  cache.store(1, 0, 1, sample(1));
  cache.end_pass(true);
  BOOST_TEST(cache.load(1, 0, 1, s));
  // a ready cache ignores the next pass's stores
  cache.begin_pass(10, 4);
  cache.store(1, 0, 1, sample(5));
  cache.end_pass(true);
  BOOST_TEST(cache.load(1, 0, 1, s));
  BOOST_TEST(s.value[1] == 0.2, boost::test_tools::tolerance(1e-15));
  cache.forget();
  BOOST_TEST(!cache.ready());
  BOOST_TEST(!cache.load(1, 0, 1, s));
}

BOOST_AUTO_TEST_CASE(merged_stencils_are_stored_as_given)
{
  StencilCache<2> cache;
  Stencil<2>      s = sample(1), back;
  s.n               = 3; // nodes 7, 3, 7: stored as given when merged
  cache.begin_pass(10, 4);
  cache.store(0, 0, 9, s, true);
  cache.end_pass(true);
  BOOST_TEST(cache.load(0, 0, 9, back));
  BOOST_TEST(back.n == 3u);
  for (unsigned int k = 0; k < 3; ++k)
    {
      BOOST_TEST(back.node[k] == s.node[k]);
      BOOST_TEST(back.value[k] == s.value[k]);
    }
}
