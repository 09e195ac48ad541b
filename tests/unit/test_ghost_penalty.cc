// The ghost penalty of the implicit step (GhostPenalty,
// doc/theory/implicit.md), on every face of real background grids in 1D,
// 2D and 3D, boxes of unequal sides and randomly distorted grids:
//
//  - a linear field u = a + B x has no jump of its normal derivative, so
//    g(u, u) = 0 on any Q1 grid;
//  - g is symmetric and positive for random fields;
//  - a kink of slope +-1 across the grid plane x = x_k, u_x = |x - x_k|,
//    jumps by 2 on every face of that plane: g = beta E h 4 |plane|
//    exactly, with h = |cell|^(1/d);
//  - the faces of a step: between cells whose nodes are all unknowns, one
//    of which has a node covered by less than a quarter of its support.
#define BOOST_TEST_MODULE ghost_penalty
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <mpm/grid/background_grid.h>
#include <mpm/integrators/ghost_penalty.h>
#include <mpm/parameters/parameters.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using namespace mpm;

// A BackgroundGrid needs MPI (p4est); the test runs on one rank.
struct MPIFixture
{
  MPIFixture()
  {
    auto &suite = boost::unit_test::framework::master_test_suite();
    mpi         = std::make_unique<Utilities::MPI::MPI_InitFinalize>(suite.argc,
                                                             suite.argv,
                                                             1);
  }
  std::unique_ptr<Utilities::MPI::MPI_InitFinalize> mpi;
};
BOOST_TEST_GLOBAL_FIXTURE(MPIFixture);

namespace
{
  constexpr double scale = 3.5; // beta E

  /// A box of 4 x 3 x 3 cells of sides 0.25 x 0.2 x 0.3 from (-0.3, 0.1,
  /// 0.2), its interior vertices moved at random by up to @p distortion
  /// of their shortest edge.
  template <int dim>
  std::unique_ptr<BackgroundGrid<dim>>
  make_grid(const double distortion)
  {
    const double          lo[3] = {-0.3, 0.1, 0.2}, h[3] = {0.25, 0.2, 0.3};
    const unsigned int    n[3] = {4, 3, 3};
    Parameters::Grid<dim> prm;
    for (unsigned int d = 0; d < dim; ++d)
      {
        prm.lower[d] = lo[d];
        prm.upper[d] = lo[d] + n[d] * h[d];
        prm.subdivisions.push_back(n[d]);
      }
    auto grid = std::make_unique<BackgroundGrid<dim>>(MPI_COMM_WORLD);
    grid->create(prm, "");
    if (distortion > 0)
      GridTools::distort_random(distortion, grid->triangulation(), true, 5);
    grid->setup(Parameters::BoundaryConditions());
    return grid;
  }

  /// The nodal vector of u(x) (dim components).
  template <int dim, typename Function>
  NodalVector
  interpolate(const BackgroundGrid<dim> &grid, const Function &u)
  {
    NodalVector v;
    grid.initialize_vector(v, dim);
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      {
        const Tensor<1, dim> value = u(grid.node_position(i));
        for (unsigned int c = 0; c < dim; ++c)
          v.local_element(i * dim + c) = value[c];
      }
    return v;
  }

  template <int dim>
  void
  check_linear_symmetric_positive(const double distortion)
  {
    const auto        grid = make_grid<dim>(distortion);
    GhostPenalty<dim> g(scale);
    g.reinit(*grid);
    g.select_all_faces(*grid);
    BOOST_REQUIRE(g.n_faces() > 0);
    Tensor<1, dim> a;
    Tensor<2, dim> B;
    for (unsigned int i = 0; i < dim; ++i)
      {
        a[i] = 0.3 - 0.1 * i;
        for (unsigned int j = 0; j < dim; ++j)
          B[i][j] = 0.7 * i - 0.4 * j + 0.2;
      }
    const auto   linear   = interpolate<dim>(*grid, [&](const Point<dim> &x) {
      return Tensor<1, dim>(a + B * x);
    });
    const double g_linear = g.form(linear, linear, MPI_COMM_WORLD);
    // (the scale of g for a unit field: scale h^(d-2) per face)
    BOOST_TEST(std::abs(g_linear) < 1e-10 * scale * g.n_faces(),
               dim << "D, distortion " << distortion
                   << ": g(u, u) of a linear u = " << g_linear);

    std::mt19937                           random(17 + dim);
    std::uniform_real_distribution<double> uniform(-1, 1);
    NodalVector                            u, w;
    grid->initialize_vector(u, dim);
    grid->initialize_vector(w, dim);
    for (unsigned int k = 0; k < u.locally_owned_size(); ++k)
      {
        u.local_element(k) = uniform(random);
        w.local_element(k) = uniform(random);
      }
    const double uw = g.form(u, w, MPI_COMM_WORLD);
    const double wu = g.form(w, u, MPI_COMM_WORLD);
    const double uu = g.form(u, u, MPI_COMM_WORLD);
    BOOST_TEST(std::abs(uw - wu) <= 1e-12 * uu);
    BOOST_TEST(uu > 0);
    // Cauchy-Schwarz of a positive semi-definite form
    BOOST_TEST(uw * uw <= uu * g.form(w, w, MPI_COMM_WORLD) * (1 + 1e-12));
  }

  template <int dim>
  void
  check_kink()
  {
    // the plane x = x_k through the second interior vertex line
    const auto        grid = make_grid<dim>(0);
    GhostPenalty<dim> g(scale);
    g.reinit(*grid);
    g.select_all_faces(*grid);
    const double x_k  = -0.3 + 2 * 0.25;
    const auto   kink = interpolate<dim>(*grid, [&](const Point<dim> &x) {
      Tensor<1, dim> u;
      u[0] = std::abs(x[0] - x_k);
      return u;
    });
    const double h[3] = {0.25, 0.2, 0.3}, n[3] = {4, 3, 3};
    double       cell = 1, plane = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        cell *= h[d];
        if (d > 0)
          plane *= n[d] * h[d];
      }
    const double expected = scale * std::pow(cell, 1. / dim) * 4 * plane;
    const double got      = g.form(kink, kink, MPI_COMM_WORLD);
    BOOST_TEST(std::abs(got - expected) <= 1e-12 * expected,
               dim << "D: g of the kink " << got << ", expected " << expected);
  }
} // namespace

BOOST_AUTO_TEST_CASE(linear_fields_symmetry_positivity)
{
  for (const double distortion : {0., 0.25})
    {
      check_linear_symmetric_positive<1>(distortion);
      check_linear_symmetric_positive<2>(distortion);
      check_linear_symmetric_positive<3>(distortion);
    }
}

BOOST_AUTO_TEST_CASE(kink_across_a_grid_plane)
{
  check_kink<1>();
  check_kink<2>();
  check_kink<3>();
}

BOOST_AUTO_TEST_CASE(faces_of_weakly_covered_cells)
{
  // 2D, 4 x 3 cells: a node covered by a fifth of its support, the others
  // fully, every node an unknown.
  const auto      grid = make_grid<2>(0);
  GhostPenalty<2> g(scale);
  g.reinit(*grid);
  NodalVector support, full;
  grid->initialize_vector(support, 1);
  grid->initialize_vector(full, 1);
  full    = 1.;
  support = 1.;
  std::vector<char> active(grid->n_local_nodes(), 1);
  g.select_faces(*grid, active, support, full);
  BOOST_TEST(g.n_faces() == 0u);

  // the interior node at (0.2, 0.3): its 4 cells (the lower two on the
  // bottom boundary) are weak, so the 4 faces between them and the 6
  // interior faces around them take part
  unsigned int weak_node = 0;
  for (unsigned int i = 0; i < grid->n_local_nodes(); ++i)
    if (grid->node_position(i).distance(Point<2>(0.2, 0.3)) < 1e-12)
      weak_node = i;
  support.local_element(weak_node) = 0.2;
  g.select_faces(*grid, active, support, full);
  BOOST_TEST(g.n_faces() == 10u);

  // a node that is not an unknown takes its cells' faces out: the corner
  // node at (0.2, 0.1) on the bottom boundary belongs to two of the weak
  // cells
  for (unsigned int i = 0; i < grid->n_local_nodes(); ++i)
    if (grid->node_position(i).distance(Point<2>(0.2, 0.1)) < 1e-12)
      active[i] = 0;
  g.select_faces(*grid, active, support, full);
  // left: the faces of the upper two weak cells but those to the lower
  // ones: 1 between them, 2 on their sides and 2 on top
  BOOST_TEST(g.n_faces() == 5u);
}
