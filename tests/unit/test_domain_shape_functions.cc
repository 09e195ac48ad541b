// The particle-domain shape functions (DomainShapeFunctions: uGIMP, cpGIMP,
// CPDI, CPDI2) evaluated on real background grids, for domains that span
// several cells:
//
//  - consistency: sum_i S_ip = 1, sum_i grad S_ip = 0, and linear fields
//    u = a + B x are reproduced: sum_i S_ip u_i = u(domain centroid) and
//    sum_i u_i (x) grad S_ip = B, in 1D, 2D and 3D, for box and distorted
//    domains (sheared/stretched F for cpGIMP and CPDI, a skewed R0 for
//    uGIMP, randomly perturbed corners for CPDI2), for particles anywhere
//    in the grid, near and on grid vertices and faces; a particle on a
//    face gets the same weights from every cell it lies in;
//  - the same for CPDI and CPDI2 on a background grid with randomly moved
//    interior vertices (GIMP is not defined there; the simulator refuses
//    it: tests/bad_input/gimp_on_distorted_grid.prm);
//  - CPDI2's corner weights against an independent quadrature, and CPDI2
//    of a parallelogram equals CPDI1;
//  - GIMP tends to standard MPM as the domain shrinks (rates below);
//  - CPDI1 of an undeformed axis-parallel box equals uGIMP exactly when
//    the box lies in one cell, and only partly when it spans cells;
//  - the failure statuses outside_grid (and clamp), collapsed, too_wide
//    and lost_corner.
#define BOOST_TEST_MODULE domain_shape_functions
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <mpm/grid/background_grid.h>
#include <mpm/parameters/parameters.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using namespace mpm;
using namespace mpm::shape_functions;

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
  template <int dim>
  using Status = typename DomainShapeFunctions<dim>::Status;

  constexpr Family families[] = {Family::ugimp,
                                 Family::cpgimp,
                                 Family::cpdi,
                                 Family::cpdi2};

  template <int dim>
  constexpr unsigned int n_corners = 1u << dim;

  template <int dim>
  using Corners = std::array<Point<dim>, n_corners<dim>>;

  const char *
  status_name(const int s)
  {
    static const char *names[] = {"ok",
                                  "outside_grid",
                                  "beyond_ghosts",
                                  "too_wide",
                                  "collapsed",
                                  "lost_corner"};
    return names[s];
  }

  template <int dim>
  std::string
  to_string(const Point<dim> &x)
  {
    std::ostringstream s;
    s.precision(17);
    s << "(" << x << ")";
    return s.str();
  }

  // ------------------------------------------------------------- the grid
  /**
   * The test grid: a box of n_d cells of size h_d per direction (the
   * sizes differ per direction), lower corner away from the origin. With
   * @p distortion > 0, interior vertices are moved at random by up to that
   * fraction of their shortest edge (deal.II's distort_random).
   */
  template <int dim>
  struct TestGrid
  {
    std::unique_ptr<BackgroundGrid<dim>> grid;
    Point<dim>                           lower, upper;
    Tensor<1, dim>                       h;
    std::vector<unsigned int>            n;

    TestGrid(const std::vector<unsigned int> &cells,
             const double                     distortion = 0)
      : n(cells.begin(), cells.begin() + dim)
    {
      const double lo[3] = {-0.3, 0.1, 0.2}, hs[3] = {0.25, 0.2, 0.3};
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = lo[d];
          h[d]     = hs[d];
          upper[d] = lo[d] + cells[d] * hs[d];
        }
      grid = std::make_unique<BackgroundGrid<dim>>(MPI_COMM_WORLD);
      Parameters::Grid<dim> prm;
      prm.lower        = lower;
      prm.upper        = upper;
      prm.subdivisions = n;
      grid->create(prm, "");
      if (distortion > 0)
        GridTools::distort_random(distortion, grid->triangulation(), true, 7);
      grid->setup(Parameters::BoundaryConditions());
      BOOST_REQUIRE_EQUAL(grid->is_cartesian(), distortion == 0);
    }

    /// Every cell containing x (several for x on a face), with xi there.
    std::vector<std::pair<unsigned int, Point<dim>>>
    hosts(const Point<dim> &x) const
    {
      std::vector<std::pair<unsigned int, Point<dim>>> r;
      Point<dim>                                       centre;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = 0.5;
      for (const auto &cell : grid->triangulation().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int i  = cell->active_cell_index();
            const Point<dim>   xi = grid->geometry(i).inverse_map(x, centre);
            if (Q1Cell<dim>::is_inside(xi))
              r.emplace_back(i, xi);
          }
      return r;
    }

    /// The (interior) grid vertex with indices idx (Cartesian grid).
    Point<dim>
    vertex(const unsigned int i,
           const unsigned int j,
           const unsigned int k) const
    {
      const unsigned int idx[3] = {i, j, k};
      Point<dim>         v;
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = lower[d] + idx[d] * h[d];
      return v;
    }

    double
    min_h() const
    {
      double m = h[0];
      for (unsigned int d = 1; d < dim; ++d)
        m = std::min(m, h[d]);
      return m;
    }
  };

  // ------------------------------------------------------------ particles
  /// A particle's property array (layout with CPDI2 corners, no history).
  template <int dim>
  struct TestParticle
  {
    using L = ParticleLayout<dim>;
    ParticleLayout<dim> layout;
    std::vector<double> prop;

    TestParticle()
    {
      layout.has_corners = true;
      prop.assign(layout.n_properties(), 0.);
      set_F(unit_symmetric_tensor<dim>());
    }
    void
    set_F(const Tensor<2, dim> &F)
    {
      store_matrix<dim>(F, prop.data() + L::F);
    }
    void
    set_R0(const Tensor<2, dim> &R0)
    {
      store_matrix<dim>(R0, prop.data() + L::domain);
    }
    void
    set_corners(const Corners<dim> &x)
    {
      for (unsigned int c = 0; c < n_corners<dim>; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          prop[layout.corners() + c * dim + d] = x[c][d];
    }
    Tensor<2, dim>
    F() const
    {
      return load_matrix<dim>(prop.data() + L::F);
    }
    Tensor<2, dim>
    R0() const
    {
      return load_matrix<dim>(prop.data() + L::domain);
    }
  };

  template <int dim>
  DomainShapeFunctions<dim>
  functions(const TestGrid<dim> &g, const Family f, const bool clamp = false)
  {
    return DomainShapeFunctions<dim>(*g.grid,
                                     f,
                                     clamp,
                                     TestParticle<dim>().layout.corners());
  }

  /// The stencil summed per node (entries may repeat a node).
  template <int dim>
  struct NodeWeight
  {
    double         value = 0;
    Tensor<1, dim> gradient;
  };

  template <int dim>
  std::map<unsigned int, NodeWeight<dim>>
  summed(const Stencil<dim> &s)
  {
    std::map<unsigned int, NodeWeight<dim>> m;
    for (unsigned int k = 0; k < s.n; ++k)
      {
        m[s.node[k]].value += s.value[k];
        m[s.node[k]].gradient += s.gradient[k];
      }
    return m;
  }

  /// max over nodes of |S - S'| and h |grad S - grad S'| (missing = 0).
  template <int dim>
  std::pair<double, double>
  difference(const std::map<unsigned int, NodeWeight<dim>> &a,
             const std::map<unsigned int, NodeWeight<dim>> &b,
             const double                                   h)
  {
    double dv = 0, dg = 0;
    auto   one_way = [&](const auto &x, const auto &y) {
      for (const auto &[node, w] : x)
        {
          const auto            it = y.find(node);
          const NodeWeight<dim> o =
            it == y.end() ? NodeWeight<dim>() : it->second;
          dv = std::max(dv, std::abs(w.value - o.value));
          dg = std::max(dg, h * (w.gradient - o.gradient).norm());
        }
    };
    one_way(a, b);
    one_way(b, a);
    return {dv, dg};
  }

  /// Random numbers of the tests (fixed seed per test).
  struct Random
  {
    std::mt19937 gen;
    explicit Random(const unsigned int seed)
      : gen(seed)
    {}
    double
    operator()(const double a, const double b)
    {
      return std::uniform_real_distribution<double>(a, b)(gen);
    }
    template <int dim>
    Tensor<2, dim>
    matrix(const double a)
    {
      Tensor<2, dim> m;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          m[i][j] = (*this)(-a, a);
      return m;
    }
  };

  // ---------------------------------------------------- consistency checks
  /// Worst errors over many particles, with the particle that gave them.
  struct Worst
  {
    double      value = 0;
    std::string where;
    void
    update(const double v, const std::string &w)
    {
      if (!(v <= value)) // NaN counts as worst
        {
          value = v;
          where = w;
        }
    }
  };

  struct Consistency
  {
    Worst    unity, gradient_sum, linear_value, linear_gradient, host;
    unsigned n_particles = 0, n_spanning = 0;

    void
    check(const std::string &what, const double tol) const
    {
      BOOST_TEST_MESSAGE(what << ": " << n_particles << " particles, "
                              << n_spanning << " spanning cells; worst "
                              << unity.value << " " << gradient_sum.value << " "
                              << linear_value.value << " "
                              << linear_gradient.value << " " << host.value);
      BOOST_TEST_INFO(what << ", at " << unity.where);
      BOOST_CHECK_SMALL(unity.value, tol);
      BOOST_TEST_INFO(what << ", at " << gradient_sum.where);
      BOOST_CHECK_SMALL(gradient_sum.value, tol);
      BOOST_TEST_INFO(what << ", at " << linear_value.where);
      BOOST_CHECK_SMALL(linear_value.value, tol);
      BOOST_TEST_INFO(what << ", at " << linear_gradient.where);
      BOOST_CHECK_SMALL(linear_gradient.value, tol);
      BOOST_TEST_INFO(what << ", at " << host.where);
      BOOST_CHECK_SMALL(host.value, tol);
      // the domains must really reach into other cells
      BOOST_TEST_INFO(what);
      BOOST_CHECK_GT(n_spanning, n_particles / 2);
    }
  };

  /**
   * Evaluate the particle @p prop at x from every cell that contains x
   * and record: partition of unity, zero gradient sum, reproduction of
   * u = a + B x (value at @p centroid, or at sum_c w_c x_c for CPDI2 when
   * @p centroid is null; gradient B), and that every host cell gives the
   * same weights. Errors are relative to the scale of the quantity.
   */
  template <int dim>
  void
  check_particle(const TestGrid<dim>             &g,
                 const DomainShapeFunctions<dim> &sf,
                 const Point<dim>                &x,
                 const TestParticle<dim>         &particle,
                 const Point<dim>                *centroid,
                 Random                          &random,
                 Consistency                     &result)
  {
    const auto hosts = g.hosts(x);
    BOOST_REQUIRE_MESSAGE(!hosts.empty(), "no cell holds " << to_string(x));
    Tensor<1, dim> a;
    for (unsigned int d = 0; d < dim; ++d)
      a[d] = random(-1, 1);
    const Tensor<2, dim> B     = random.matrix<dim>(1);
    const double         scale = std::max(1., g.upper.norm());
    const double         h     = g.min_h();

    std::map<unsigned int, NodeWeight<dim>> first;
    for (const auto &[cell, xi] : hosts)
      {
        std::ostringstream where;
        where << family_name(sf.family()) << " particle at " << to_string(x)
              << " in cell " << cell;
        Stencil<dim>       s;
        CornerWeights<dim> cw;
        const Status<dim>  status =
          sf.evaluate(cell, xi, particle.prop.data(), s, &cw);
        BOOST_REQUIRE_MESSAGE(status == Status<dim>::ok,
                              where.str()
                                << ": status " << status_name(int(status)));
        Point<dim> c = centroid ? *centroid : Point<dim>();
        if (!centroid)
          for (unsigned int k = 0; k < n_corners<dim>; ++k)
            c += cw.w[k] * cw.x[k];

        double         sum = 0;
        Tensor<1, dim> gsum, u;
        Tensor<2, dim> G;
        for (unsigned int k = 0; k < s.n; ++k)
          {
            const Tensor<1, dim> ui = a + B * g.grid->node_position(s.node[k]);
            sum += s.value[k];
            gsum += s.gradient[k];
            u += s.value[k] * ui;
            G += outer_product(ui, s.gradient[k]);
          }
        result.unity.update(std::abs(sum - 1), where.str());
        result.gradient_sum.update(h * gsum.norm(), where.str());
        result.linear_value.update((u - (a + B * c)).norm() / scale,
                                   where.str());
        result.linear_gradient.update((G - B).norm(), where.str());
        const auto m = summed(s);
        if (first.empty())
          {
            first = m;
            ++result.n_particles;
            result.n_spanning += m.size() > n_corners<dim>;
          }
        else
          {
            const auto [dv, dg] = difference(first, m, h);
            result.host.update(std::max(dv, dg),
                               where.str() + " against the first host");
          }
      }
  }

  /**
   * A particle of family @p f at x with a domain of half-widths @p l: a
   * box centred at x (distorted = false) or a distorted domain (centred
   * at x, except CPDI2's perturbed corners). Returns the largest reach of
   * the domain from x per direction.
   */
  template <int dim>
  Tensor<1, dim>
  make_domain(const Family          f,
              const bool            distorted,
              const Tensor<1, dim> &l,
              const Point<dim>     &x,
              Random               &random,
              TestParticle<dim>    &p)
  {
    Tensor<2, dim> R0, F = unit_symmetric_tensor<dim>();
    for (unsigned int d = 0; d < dim; ++d)
      R0[d][d] = l[d];
    Corners<dim> corners;
    for (unsigned int c = 0; c < n_corners<dim>; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        corners[c][d] = x[d] + (((c >> d) & 1) ? l[d] : -l[d]);
    if (distorted)
      switch (f)
        {
          case Family::ugimp:
            // a skewed reference domain (GIMP takes its bounding box,
            // scaled to its volume) and an F that uGIMP must ignore
            R0 = R0 + R0 * random.matrix<dim>(0.3);
            F  = F + random.matrix<dim>(0.4);
            break;
          case Family::cpgimp:
          case Family::cpdi:
            // stretch and shear
            F = F + random.matrix<dim>(0.35);
            if (f == Family::cpdi)
              R0 = R0 + R0 * random.matrix<dim>(0.2);
            break;
          case Family::cpdi2:
            for (auto &c : corners)
              for (unsigned int d = 0; d < dim; ++d)
                c[d] += random(-0.3, 0.3) * l[d];
            break;
          default:
            break;
        }
    p.set_F(F);
    p.set_R0(R0);
    p.set_corners(corners);

    Tensor<1, dim> reach;
    if (is_gimp(f))
      {
        reach = DomainShapeFunctions<dim>::gimp_half_widths(R0);
        if (f == Family::cpgimp)
          for (unsigned int d = 0; d < dim; ++d)
            {
              double n2 = 0;
              for (unsigned int i = 0; i < dim; ++i)
                n2 += F[i][d] * F[i][d];
              reach[d] *= std::sqrt(n2);
            }
      }
    else if (f == Family::cpdi)
      {
        const Tensor<2, dim> A = F * R0;
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int k = 0; k < dim; ++k)
            reach[d] += std::abs(A[d][k]);
      }
    else
      for (const auto &c : corners)
        for (unsigned int d = 0; d < dim; ++d)
          reach[d] = std::max(reach[d], std::abs(c[d] - x[d]));
    return reach;
  }

  /**
   * Consistency of one family on the Cartesian test grid: random
   * particles, particles near grid vertices and particles exactly on grid
   * vertices and faces, with domains of 0.2 to 0.5 cells half-width.
   */
  template <int dim>
  void
  check_family_on_box_grid(const Family f, const bool distorted)
  {
    TestGrid<dim> g(std::vector<unsigned int>{6, 5, 4});
    const auto    sf = functions(g, f);
    Random        random(11 + 3 * dim + 101 * int(f) + distorted);
    Consistency   result;
    const bool    with_centroid = f != Family::cpdi2 || !distorted;

    auto one = [&](const Point<dim> &x, const Tensor<1, dim> &l) {
      TestParticle<dim>    p;
      const Tensor<1, dim> reach = make_domain(f, distorted, l, x, random, p);
      for (unsigned int d = 0; d < dim; ++d)
        if (x[d] - reach[d] < g.lower[d] || x[d] + reach[d] > g.upper[d])
          return; // not for this test
      check_particle(g, sf, x, p, with_centroid ? &x : nullptr, random, result);
    };
    auto random_l = [&]() {
      Tensor<1, dim> l;
      for (unsigned int d = 0; d < dim; ++d)
        l[d] = random(0.2, 0.5) * g.h[d];
      return l;
    };
    // anywhere
    for (unsigned int i = 0; i < 150; ++i)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = random(g.lower[d] + 0.8 * g.h[d], g.upper[d] - 0.8 * g.h[d]);
        one(x, random_l());
      }
    // near, on, and on the faces through an interior vertex
    for (const unsigned int i : {1u, 2u})
      for (const unsigned int j : {1u, 2u})
        {
          const Point<dim> v = g.vertex(i + 1, j, 1 + (i + j) % 2);
          for (unsigned int k = 0; k < 8; ++k)
            {
              Point<dim> x = v;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] += random(-0.1, 0.1) * g.h[d];
              one(x, random_l());
            }
          one(v, random_l());
          for (unsigned int d = 0; d < dim; ++d)
            {
              Point<dim> x = v;
              for (unsigned int e = 0; e < dim; ++e)
                if (e != d)
                  x[e] += random(-0.4, 0.4) * g.h[e];
              one(x, random_l());
            }
        }
    // a domain ending exactly on a cell face
    {
      Point<dim>     x = g.vertex(2, 2, 2);
      Tensor<1, dim> l;
      for (unsigned int d = 0; d < dim; ++d)
        {
          l[d] = 0.25 * g.h[d];
          x[d] += 0.25 * g.h[d];
        }
      one(x, l);
    }
    BOOST_REQUIRE_GT(result.n_particles, 100u);
    std::ostringstream what;
    what << dim << "D " << family_name(f)
         << (distorted ? ", distorted domains" : ", box domains");
    result.check(what.str(), 1e-13);
  }

  /// The same on a grid with randomly moved interior vertices (CPDI, CPDI2).
  template <int dim>
  void
  check_family_on_distorted_grid(const Family f, const bool distorted)
  {
    TestGrid<dim> g(std::vector<unsigned int>{5, 4, 3}, 0.25);
    const auto    sf = functions(g, f);
    Random        random(5 + 7 * dim + 13 * int(f) + distorted);
    Consistency   result;
    // a particle on a face between cells: a mid-point of a face of an
    // interior cell (distorted faces are not flat in 3D, but their
    // bilinear centre lies on both cells)
    auto inside = [&](const Point<dim> &x, const Tensor<1, dim> &margin) {
      for (unsigned int d = 0; d < dim; ++d)
        if (x[d] - margin[d] < g.lower[d] || x[d] + margin[d] > g.upper[d])
          return false;
      return true;
    };
    std::vector<Point<dim>> on_faces;
    for (const auto &cell : g.grid->triangulation().active_cell_iterators())
      for (const unsigned int face : cell->face_indices())
        if (!cell->at_boundary(face) && on_faces.size() < 12 &&
            inside(cell->face(face)->center(), g.h))
          on_faces.push_back(cell->face(face)->center());
    BOOST_REQUIRE_GT(on_faces.size(), 3u);
    for (unsigned int i = 0; i < 150 + on_faces.size(); ++i)
      {
        Point<dim> x;
        if (i < on_faces.size())
          x = on_faces[i];
        else
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = random(g.lower[d] + 0.5 * g.h[d], g.upper[d] - 0.5 * g.h[d]);
        Tensor<1, dim> l;
        for (unsigned int d = 0; d < dim; ++d)
          l[d] = random(0.2, 0.4) * g.h[d];
        TestParticle<dim> p;
        if (!inside(x, make_domain(f, distorted, l, x, random, p)))
          continue;
        check_particle(
          g, sf, x, p, f == Family::cpdi ? &x : nullptr, random, result);
      }
    BOOST_REQUIRE_GT(result.n_particles, 60u);
    std::ostringstream what;
    what << dim << "D " << family_name(f) << " on a distorted grid"
         << (distorted ? ", distorted domains" : ", box domains");
    result.check(what.str(), 1e-12);
  }
} // namespace

// ------------------------------------------------------------------ tests
BOOST_AUTO_TEST_CASE(partition_of_unity_and_linear_fields_box_grid)
{
  for (const Family f : families)
    for (const bool distorted : {false, true})
      {
        check_family_on_box_grid<1>(f, distorted);
        check_family_on_box_grid<2>(f, distorted);
        check_family_on_box_grid<3>(f, distorted);
      }
}

BOOST_AUTO_TEST_CASE(partition_of_unity_and_linear_fields_distorted_grid)
{
  for (const Family f : {Family::cpdi, Family::cpdi2})
    for (const bool distorted : {false, true})
      {
        check_family_on_distorted_grid<2>(f, distorted);
        check_family_on_distorted_grid<3>(f, distorted);
      }
}

// ------------------------------------------------------- CPDI2's weights
namespace
{
  /// Corner functions and their reference gradients (written again here,
  /// independently of cpdi.h).
  template <int dim>
  void
  corner_functions(const Point<dim>                           &xi,
                   double                                     *M,
                   std::array<Tensor<1, dim>, n_corners<dim>> &dM)
  {
    for (unsigned int c = 0; c < n_corners<dim>; ++c)
      {
        M[c] = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const bool upper = (c >> d) & 1;
            M[c] *= upper ? xi[d] : 1 - xi[d];
            dM[c][d] = upper ? 1 : -1;
            for (unsigned int e = 0; e < dim; ++e)
              if (e != d)
                dM[c][d] *= ((c >> e) & 1) ? xi[e] : 1 - xi[e];
          }
      }
  }

  /// Volume, w_c and g_c of the multilinear domain of @p x by a 3-point
  /// Gauss rule per direction (more than the 2 points cpdi2_weights uses;
  /// both are exact for these polynomial integrands).
  template <int dim>
  void
  reference_weights(const Corners<dim>                         &x,
                    double                                     &volume,
                    std::array<double, n_corners<dim>>         &w,
                    std::array<Tensor<1, dim>, n_corners<dim>> &g)
  {
    const double q[3]  = {0.5 - 0.5 * std::sqrt(0.6),
                          0.5,
                          0.5 + 0.5 * std::sqrt(0.6)};
    const double wq[3] = {5. / 18, 8. / 18, 5. / 18};
    volume             = 0;
    w.fill(0.);
    g.fill(Tensor<1, dim>());
    for (unsigned int k = 0; k < Utilities::fixed_power<dim>(3u); ++k)
      {
        Point<dim> xi;
        double     weight = 1;
        for (unsigned int d = 0, r = k; d < dim; ++d, r /= 3)
          {
            xi[d] = q[r % 3];
            weight *= wq[r % 3];
          }
        double                                     M[n_corners<dim>];
        std::array<Tensor<1, dim>, n_corners<dim>> dM;
        corner_functions<dim>(xi, M, dM);
        Tensor<2, dim> J;
        for (unsigned int c = 0; c < n_corners<dim>; ++c)
          J += outer_product(x[c], dM[c]);
        const double         det   = determinant(J);
        const Tensor<2, dim> JinvT = transpose(invert(J));
        volume += weight * det;
        for (unsigned int c = 0; c < n_corners<dim>; ++c)
          {
            w[c] += weight * det * M[c];
            g[c] += weight * det * (JinvT * dM[c]);
          }
      }
    for (unsigned int c = 0; c < n_corners<dim>; ++c)
      {
        w[c] /= volume;
        g[c] /= volume;
      }
  }

  template <int dim>
  void
  check_cpdi2_weights()
  {
    Random random(3 + dim);
    double worst_v = 0, worst_w = 0, worst_g = 0, worst_sum = 0;
    for (unsigned int trial = 0; trial < 50; ++trial)
      {
        CornerWeights<dim> cw;
        Tensor<1, dim>     l;
        for (unsigned int d = 0; d < dim; ++d)
          l[d] = random(0.5, 2);
        for (unsigned int c = 0; c < n_corners<dim>; ++c)
          for (unsigned int d = 0; d < dim; ++d)
            cw.x[c][d] =
              3 + (((c >> d) & 1) ? l[d] : 0.) + random(-0.3, 0.3) * l[d];
        cpdi2_weights<dim>(cw);
        BOOST_REQUIRE_GT(cw.quality, min_domain_quality);
        double                                     V;
        std::array<double, n_corners<dim>>         w;
        std::array<Tensor<1, dim>, n_corners<dim>> g;
        reference_weights<dim>(cw.x, V, w, g);
        if constexpr (dim == 2)
          {
            // and the area by the shoelace formula (vertex order 0 1 3 2)
            const unsigned int ring[4] = {0, 1, 3, 2};
            double             area    = 0;
            for (unsigned int k = 0; k < 4; ++k)
              {
                const Point<2> &p = cw.x[ring[k]], &q = cw.x[ring[(k + 1) % 4]];
                area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
              }
            worst_v = std::max(worst_v, std::abs(area - V) / V);
          }
        worst_v            = std::max(worst_v, std::abs(cw.volume - V) / V);
        double         sum = 0;
        Tensor<1, dim> gsum;
        Tensor<2, dim> xg;
        const double   size = l.norm();
        for (unsigned int c = 0; c < n_corners<dim>; ++c)
          {
            worst_w = std::max(worst_w, std::abs(cw.w[c] - w[c]));
            worst_g = std::max(worst_g, size * (cw.g[c] - g[c]).norm());
            sum += cw.w[c];
            gsum += cw.g[c];
            xg += outer_product(cw.x[c], cw.g[c]);
          }
        worst_sum = std::max({worst_sum,
                              std::abs(sum - 1),
                              size * gsum.norm(),
                              (xg - unit_symmetric_tensor<dim>()).norm()});
      }
    BOOST_TEST_INFO(dim << "D");
    BOOST_CHECK_SMALL(worst_v, 1e-14);
    BOOST_TEST_INFO(dim << "D");
    BOOST_CHECK_SMALL(worst_w, 1e-14);
    BOOST_TEST_INFO(dim << "D");
    BOOST_CHECK_SMALL(worst_g, 1e-13);
    BOOST_TEST_INFO(dim << "D");
    BOOST_CHECK_SMALL(worst_sum, 1e-13);
  }

  /// CPDI2 of the corners of CPDI1's parallelogram is CPDI1.
  template <int dim>
  void
  check_cpdi2_of_parallelogram()
  {
    TestGrid<dim> g(std::vector<unsigned int>{6, 5, 4});
    const auto    cpdi  = functions(g, Family::cpdi);
    const auto    cpdi2 = functions(g, Family::cpdi2);
    Random        random(17 + dim);
    double        worst = 0, worst_corner = 0;
    for (unsigned int i = 0; i < 50; ++i)
      {
        Point<dim>     x;
        Tensor<2, dim> R0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d] = random(g.lower[d] + 1.2 * g.h[d], g.upper[d] - 1.2 * g.h[d]);
            R0[d][d] = random(0.2, 0.4) * g.h[d];
          }
        TestParticle<dim> p;
        p.set_F(unit_symmetric_tensor<dim>() + random.matrix<dim>(0.3));
        p.set_R0(R0);
        Corners<dim> corners;
        for (unsigned int c = 0; c < n_corners<dim>; ++c)
          {
            Tensor<1, dim> s;
            for (unsigned int d = 0; d < dim; ++d)
              s[d] = ((c >> d) & 1) ? 1 : -1;
            corners[c] = x + p.F() * (R0 * s);
          }
        p.set_corners(corners);
        const auto         host = g.hosts(x).front();
        Stencil<dim>       s1, s2;
        CornerWeights<dim> c1, c2;
        BOOST_REQUIRE(
          cpdi.evaluate(host.first, host.second, p.prop.data(), s1, &c1) ==
          Status<dim>::ok);
        BOOST_REQUIRE(
          cpdi2.evaluate(host.first, host.second, p.prop.data(), s2, &c2) ==
          Status<dim>::ok);
        const auto [dv, dg] = difference(summed(s1), summed(s2), g.min_h());
        worst               = std::max({worst, dv, dg});
        worst_corner =
          std::max(worst_corner, std::abs(c1.volume - c2.volume) / c1.volume);
        for (unsigned int c = 0; c < n_corners<dim>; ++c)
          worst_corner = std::max({worst_corner,
                                   c1.x[c].distance(c2.x[c]),
                                   std::abs(c1.w[c] - c2.w[c]),
                                   g.min_h() * (c1.g[c] - c2.g[c]).norm()});
      }
    BOOST_TEST_INFO(dim << "D");
    BOOST_CHECK_SMALL(worst, 1e-13);
    BOOST_TEST_INFO(dim << "D");
    BOOST_CHECK_SMALL(worst_corner, 1e-13);
  }
} // namespace

BOOST_AUTO_TEST_CASE(cpdi2_weights_against_quadrature)
{
  check_cpdi2_weights<1>();
  check_cpdi2_weights<2>();
  check_cpdi2_weights<3>();
}

BOOST_AUTO_TEST_CASE(cpdi2_of_a_parallelogram_is_cpdi)
{
  check_cpdi2_of_parallelogram<1>();
  check_cpdi2_of_parallelogram<2>();
  check_cpdi2_of_parallelogram<3>();
}

// ----------------------------------------------------- the GIMP variants
namespace
{
  /**
   * uGIMP ignores F; cpGIMP with F = I, or any rotation, is uGIMP;
   * cpGIMP with F = diag(lambda) is uGIMP with the half-widths times
   * lambda; gimp_half_widths keeps a diagonal R0 and the volume of any.
   */
  template <int dim>
  void
  check_gimp_variants()
  {
    TestGrid<dim> g(std::vector<unsigned int>{6, 5, 4});
    const auto    ugimp  = functions(g, Family::ugimp);
    const auto    cpgimp = functions(g, Family::cpgimp);
    Random        random(23 + dim);
    double        worst = 0, worst_widths = 0;
    auto          stencil = [&](const DomainShapeFunctions<dim>           &sf,
                       const std::pair<unsigned int, Point<dim>> &host,
                       const TestParticle<dim>                   &p) {
      Stencil<dim> s;
      BOOST_REQUIRE(sf.evaluate(host.first, host.second, p.prop.data(), s) ==
                    Status<dim>::ok);
      return summed(s);
    };
    auto compare = [&](const auto &a, const auto &b) {
      const auto [dv, dg] = difference(a, b, g.min_h());
      worst               = std::max({worst, dv, dg});
    };
    for (unsigned int i = 0; i < 50; ++i)
      {
        Point<dim>     x;
        Tensor<2, dim> R0;
        Tensor<1, dim> lambda;
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d] = random(g.lower[d] + 1.2 * g.h[d], g.upper[d] - 1.2 * g.h[d]);
            R0[d][d]  = random(0.2, 0.4) * g.h[d];
            lambda[d] = random(0.6, 1.5);
          }
        const auto host = g.hosts(x).front();

        TestParticle<dim> identity, deformed, rotated, stretched, scaled;
        for (auto *p : {&identity, &deformed, &rotated, &stretched, &scaled})
          p->set_R0(R0);
        deformed.set_F(unit_symmetric_tensor<dim>() + random.matrix<dim>(0.3));
        Tensor<2, dim> Q = unit_symmetric_tensor<dim>(), S;
        if constexpr (dim >= 2)
          {
            const double t = random(0, 2 * M_PI);
            Q[0][0] = Q[1][1] = std::cos(t);
            Q[0][1]           = -std::sin(t);
            Q[1][0]           = std::sin(t);
          }
        rotated.set_F(Q);
        Tensor<2, dim> R0_scaled;
        for (unsigned int d = 0; d < dim; ++d)
          {
            S[d][d]         = lambda[d];
            R0_scaled[d][d] = lambda[d] * R0[d][d];
          }
        stretched.set_F(S);
        scaled.set_R0(R0_scaled);

        const auto reference = stencil(ugimp, host, identity);
        compare(reference, stencil(ugimp, host, deformed));
        compare(reference, stencil(cpgimp, host, identity));
        compare(reference, stencil(cpgimp, host, rotated));
        compare(stencil(cpgimp, host, stretched), stencil(ugimp, host, scaled));

        // half-widths: diagonal R0 kept, volume of a general R0 kept
        const Tensor<1, dim> l =
          DomainShapeFunctions<dim>::gimp_half_widths(R0);
        const Tensor<2, dim> R0_skew = R0 + R0 * random.matrix<dim>(0.3);
        const Tensor<1, dim> l_skew =
          DomainShapeFunctions<dim>::gimp_half_widths(R0_skew);
        double product = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            worst_widths = std::max(worst_widths, std::abs(l[d] - R0[d][d]));
            product *= l_skew[d];
          }
        worst_widths =
          std::max(worst_widths,
                   std::abs(product - std::abs(determinant(R0_skew))) /
                     product);
      }
    BOOST_TEST_INFO(dim << "D");
    BOOST_CHECK_SMALL(worst, 1e-14);
    BOOST_TEST_INFO(dim << "D");
    BOOST_CHECK_SMALL(worst_widths, 1e-14);
  }
} // namespace

BOOST_AUTO_TEST_CASE(gimp_variants)
{
  check_gimp_variants<1>();
  check_gimp_variants<2>();
  check_gimp_variants<3>();
}

// ------------------------------------------------ GIMP -> standard MPM
namespace
{
  /**
   * uGIMP against the Q1 functions at the particle as the box shrinks,
   * l = h/4 ... h/2^k_max, for particles on a lattice of M^dim points of
   * one interior cell (cell-centred, so no particle is on a face). What
   * is true, and checked:
   *
   * - a box inside the particle's cell gives exactly N_i(x_p) and
   *   grad N_i(x_p): N_i is multilinear there, and the mean of a
   *   multilinear function (and of its derivatives) over a centred box
   *   is its value at the centre. So for a fixed particle the error is
   *   zero as soon as l is below its distance to the faces: faster than
   *   any power of l;
   * - a box crossing a face at distance delta < l averages across the
   *   kink of N_i: the value error is ~ (l - delta)^2 / (l h), largest
   *   for a particle on a vertex, where it is exactly 1 - (1 - l/2h)^dim
   *   for the vertex's own function (checked): O(l / h), first order;
   *   the mean over the cell is O((l / h)^2) (a strip of width 2l along
   *   the faces times O(l/h)): observed order 2;
   * - the gradient error there is O(1/h) (GIMP averages the jump of
   *   grad N across the face, standard MPM takes one side): the largest
   *   error does not decrease, the mean over the cell is O(l / h):
   *   observed order 1 (in 2D and 3D from below: where the strips of two
   *   faces overlap, near the edges, the errors do not add up, a
   *   correction of relative size O(l / h)).
   */
  template <int dim>
  void
  check_gimp_to_standard(const unsigned int M, const unsigned int k_max)
  {
    TestGrid<dim> g(std::vector<unsigned int>{6, 5, 4});
    const auto    sf     = functions(g, Family::ugimp);
    Point<dim>    centre = g.vertex(2, 2, 1);
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] += 0.5 * g.h[d];
    const unsigned int     cell  = g.hosts(centre).front().first;
    const auto            &geo   = g.grid->geometry(cell);
    const unsigned int    *nodes = g.grid->nodes(cell);
    constexpr unsigned int nv    = n_q1<dim>;

    std::vector<double> mean_v, mean_g, max_g;
    double              max_inside = 0, worst_vertex = 0;
    unsigned int        n_inside = 0;
    for (unsigned int k = 2; k <= k_max; ++k)
      {
        const double      ratio = std::ldexp(1., -int(k));
        TestParticle<dim> p;
        Tensor<2, dim>    R0;
        for (unsigned int d = 0; d < dim; ++d)
          R0[d][d] = ratio * g.h[d];
        p.set_R0(R0);
        {
          // the particle on vertex 0 of the cell
          Stencil<dim> s;
          BOOST_REQUIRE(sf.evaluate(cell, Point<dim>(), p.prop.data(), s) ==
                        Status<dim>::ok);
          const double exact = 1 - std::pow(1 - ratio / 2, dim);
          worst_vertex =
            std::max(worst_vertex,
                     std::abs(1 - summed(s)[nodes[0]].value - exact));
        }
        double       sum_v = 0, sum_g = 0, top_g = 0;
        unsigned int n = 0;
        for (unsigned int i = 0; i < Utilities::fixed_power<dim>(M); ++i)
          {
            Point<dim> xi;
            bool       inside = true;
            for (unsigned int d = 0, r = i; d < dim; ++d, r /= M)
              {
                xi[d] = (r % M + 0.5) / M;
                inside =
                  inside && std::min(xi[d], 1 - xi[d]) * g.h[d] > R0[d][d];
              }
            double         N[nv];
            Tensor<1, dim> G[nv];
            geo.values_and_gradients(xi, N, G);
            Stencil<dim> s;
            BOOST_REQUIRE(sf.evaluate(cell, xi, p.prop.data(), s) ==
                          Status<dim>::ok);
            auto m = summed(s);
            for (unsigned int v = 0; v < nv; ++v)
              {
                m[nodes[v]].value -= N[v];
                m[nodes[v]].gradient -= G[v];
              }
            double ev = 0, eg = 0;
            for (const auto &[node, w] : m)
              {
                ev = std::max(ev, std::abs(w.value));
                for (unsigned int d = 0; d < dim; ++d)
                  eg = std::max(eg, g.h[d] * std::abs(w.gradient[d]));
              }
            sum_v += ev;
            sum_g += eg;
            top_g = std::max(top_g, eg);
            ++n;
            if (inside)
              {
                max_inside = std::max({max_inside, ev, eg});
                ++n_inside;
              }
          }
        mean_v.push_back(sum_v / n);
        mean_g.push_back(sum_g / n);
        max_g.push_back(top_g);
      }
    BOOST_TEST_INFO(dim << "D: box inside the cell (" << n_inside << ")");
    BOOST_CHECK_SMALL(max_inside, 1e-14);
    BOOST_REQUIRE_GT(n_inside, 0u);
    BOOST_TEST_INFO(dim << "D: particle on a vertex");
    BOOST_CHECK_SMALL(worst_vertex, 1e-14);
    for (unsigned int k = 0; k + 1 < mean_v.size(); ++k)
      {
        const double order_mean_v = std::log2(mean_v[k] / mean_v[k + 1]);
        const double order_mean_g = std::log2(mean_g[k] / mean_g[k + 1]);
        BOOST_TEST_MESSAGE(
          dim << "D GIMP -> Q1, l = h/" << (4u << k) << ": mean value error "
              << mean_v[k] << ", mean gradient error " << mean_g[k]
              << ", max gradient error " << max_g[k] << "; orders "
              << order_mean_v << " " << order_mean_g);
        BOOST_TEST_INFO(dim << "D, l = h/" << (4u << k));
        BOOST_CHECK_CLOSE_FRACTION(order_mean_v, 2., 0.1);
        // first order, approached from below
        const bool last = k + 2 == mean_v.size();
        BOOST_TEST_INFO(dim << "D, l = h/" << (4u << k));
        BOOST_CHECK(order_mean_g > (last ? 0.9 : 0.65) && order_mean_g < 1.1);
        // the largest gradient error stays at about half the jump of h
        // grad N across a face
        BOOST_TEST_INFO(dim << "D, l = h/" << (4u << k));
        BOOST_CHECK_GT(max_g[k + 1], 0.4);
      }
  }
} // namespace

BOOST_AUTO_TEST_CASE(gimp_tends_to_standard_mpm)
{
  check_gimp_to_standard<1>(8192, 7);
  check_gimp_to_standard<2>(512, 6);
  check_gimp_to_standard<3>(64, 5);
}

// ------------------------------------------------------- CPDI1 vs uGIMP
namespace
{
  /**
   * CPDI1 of an undeformed axis-parallel box (F = I, R0 diagonal) against
   * uGIMP of the same box. CPDI1 averages the corner values; uGIMP
   * integrates N_i exactly over the box. They are equal (values and
   * gradients, node by node) when the box lies in ONE cell: N_i is
   * multilinear there and its mean over a box is the mean of its corner
   * values. Across cells N_i has kinks inside the box and the values
   * differ (checked: by more than 1e-3 for many particles). What stays
   * true across cells: gradient component d is the difference of the
   * means of N_i over the two faces normal to d, divided by 2 l_d, in
   * both families; so it agrees whenever those faces lie in one cell in
   * every other direction (always in 1D).
   */
  template <int dim>
  void
  check_cpdi_against_ugimp()
  {
    TestGrid<dim> g(std::vector<unsigned int>{6, 5, 4});
    const auto    cpdi  = functions(g, Family::cpdi);
    const auto    ugimp = functions(g, Family::ugimp);
    Random        random(31 + dim);
    Worst         one_cell, spanning_gradient;
    double        largest_value_difference = 0;
    unsigned int  n_different = 0, n_spanning = 0, n_gradient_checks = 0;

    auto compare = [&](const Point<dim> &x, const Tensor<1, dim> &l) {
      TestParticle<dim> p;
      Tensor<2, dim>    R0;
      for (unsigned int d = 0; d < dim; ++d)
        R0[d][d] = l[d];
      p.set_R0(R0);
      const auto   host = g.hosts(x).front();
      Stencil<dim> sc, sg;
      BOOST_REQUIRE(cpdi.evaluate(host.first, host.second, p.prop.data(), sc) ==
                    Status<dim>::ok);
      BOOST_REQUIRE(
        ugimp.evaluate(host.first, host.second, p.prop.data(), sg) ==
        Status<dim>::ok);
      const auto a = summed(sc), b = summed(sg);
      // which cell (per direction) each end of the box is in
      bool one[dim];
      bool in_one_cell = true;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double lo = (x[d] - l[d] - g.lower[d]) / g.h[d];
          const double hi = (x[d] + l[d] - g.lower[d]) / g.h[d];
          one[d]          = std::floor(lo) == std::ceil(hi) - 1 ||
                   std::floor(lo) == std::floor(hi);
          in_one_cell = in_one_cell && one[d];
        }
      std::ostringstream where;
      where << "particle at " << to_string(x) << ", l = " << l;
      if (in_one_cell)
        {
          // gradients relative to their round-off, which grows like 1/l
          // in both (differences of N across the box)
          double l_min = l[0];
          for (unsigned int d = 1; d < dim; ++d)
            l_min = std::min(l_min, l[d]);
          const auto [dv, dg] = difference(a, b, l_min);
          one_cell.update(std::max(dv, dg), where.str());
          return;
        }
      ++n_spanning;
      const auto [dv, dg] = difference(a, b, g.min_h());
      (void)dg;
      largest_value_difference = std::max(largest_value_difference, dv);
      n_different += dv > 1e-3;
      for (unsigned int d = 0; d < dim; ++d)
        {
          bool faces_in_one_cell = true;
          for (unsigned int e = 0; e < dim; ++e)
            if (e != d)
              faces_in_one_cell = faces_in_one_cell && one[e];
          if (!faces_in_one_cell)
            continue;
          ++n_gradient_checks;
          double worst = 0;
          for (const auto &[node, w] : a)
            {
              const auto   it = b.find(node);
              const double o  = it == b.end() ? 0. : it->second.gradient[d];
              worst = std::max(worst, g.h[d] * std::abs(w.gradient[d] - o));
            }
          for (const auto &[node, w] : b)
            if (a.find(node) == a.end())
              worst = std::max(worst, g.h[d] * std::abs(w.gradient[d]));
          spanning_gradient.update(worst,
                                   where.str() + ", component " +
                                     std::to_string(d));
        }
    };
    for (unsigned int i = 0; i < 400; ++i)
      {
        Point<dim>     x;
        Tensor<1, dim> l;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = random(g.lower[d] + 0.6 * g.h[d], g.upper[d] - 0.6 * g.h[d]);
        if (i % 2 == 0)
          {
            // in one cell: up to the distance to its faces
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double s = (x[d] - g.lower[d]) / g.h[d];
                const double t = s - std::floor(s);
                l[d]           = random(0.05, 1) * std::min(t, 1 - t) * g.h[d];
              }
          }
        else
          for (unsigned int d = 0; d < dim; ++d)
            l[d] = random(0.2, 0.5) * g.h[d];
        compare(x, l);
      }
    // the box that is a whole cell
    {
      Point<dim>     x = g.vertex(2, 2, 1);
      Tensor<1, dim> l;
      for (unsigned int d = 0; d < dim; ++d)
        {
          x[d] += 0.5 * g.h[d];
          l[d] = 0.5 * g.h[d];
        }
      compare(x, l);
    }
    BOOST_TEST_MESSAGE(dim << "D CPDI1 vs uGIMP: largest difference in one "
                           << "cell " << one_cell.value << "; spanning "
                           << n_spanning << ", values differ by up to "
                           << largest_value_difference << " (" << n_different
                           << " by more than 1e-3), gradient components "
                           << "checked " << n_gradient_checks << ", worst "
                           << spanning_gradient.value);
    BOOST_TEST_INFO(dim << "D, at " << one_cell.where);
    BOOST_CHECK_SMALL(one_cell.value, 1e-13);
    BOOST_TEST_INFO(dim << "D, at " << spanning_gradient.where);
    BOOST_CHECK_SMALL(spanning_gradient.value, 1e-13);
    BOOST_CHECK_GT(n_spanning, 100u);
    BOOST_CHECK_GT(n_different, n_spanning / 2);
    BOOST_CHECK_GT(n_gradient_checks, 20u);
  }
} // namespace

BOOST_AUTO_TEST_CASE(cpdi_equals_ugimp_on_boxes_in_one_cell)
{
  check_cpdi_against_ugimp<1>();
  check_cpdi_against_ugimp<2>();
  check_cpdi_against_ugimp<3>();
}

// ----------------------------------------------------- failure statuses
namespace
{
  template <int dim>
  Status<dim>
  evaluate_at(const TestGrid<dim>             &g,
              const DomainShapeFunctions<dim> &sf,
              const Point<dim>                &x,
              const TestParticle<dim>         &p,
              Stencil<dim>                    &s,
              CornerWeights<dim>              *cw = nullptr)
  {
    const auto hosts = g.hosts(x);
    BOOST_REQUIRE(!hosts.empty());
    return sf.evaluate(
      hosts.front().first, hosts.front().second, p.prop.data(), s, cw);
  }

  /// sum S - 1, h |sum grad S| and the error of reproducing u = a + B x
  /// at @p centroid (value) and B (gradient; only if @p gradient).
  template <int dim>
  double
  consistency_error(const TestGrid<dim> &g,
                    const Stencil<dim>  &s,
                    const Point<dim>    &centroid,
                    const bool           gradient)
  {
    Tensor<1, dim> a;
    Tensor<2, dim> B;
    for (unsigned int d = 0; d < dim; ++d)
      {
        a[d] = 0.3 + d;
        for (unsigned int e = 0; e < dim; ++e)
          B[d][e] = 1. / (1 + d + 2 * e);
      }
    double         sum = 0;
    Tensor<1, dim> gsum, u;
    Tensor<2, dim> G;
    for (unsigned int k = 0; k < s.n; ++k)
      {
        const Tensor<1, dim> ui = a + B * g.grid->node_position(s.node[k]);
        sum += s.value[k];
        gsum += s.gradient[k];
        u += s.value[k] * ui;
        G += outer_product(ui, s.gradient[k]);
      }
    return std::max({std::abs(sum - 1),
                     g.min_h() * gsum.norm(),
                     (u - (a + B * centroid)).norm(),
                     gradient ? (G - B).norm() : 0.});
  }

  template <int dim>
  unsigned int
  n_distinct_nodes(const Stencil<dim> &s)
  {
    return summed(s).size();
  }

  /**
   * outside_grid: a domain reaching over the grid boundary is refused
   * with clamp = false. With clamp = true GIMP cuts the box at the
   * boundary (still a box: u is reproduced at its centre, grad u
   * exactly), CPDI and CPDI2 move the corners outside onto the boundary
   * (on an axis-parallel grid: each coordinate clipped to the grid), and
   * the stencil is still a partition of unity that reproduces u at the
   * centroid of the moved corners with the original weights (not the
   * gradient: the corner weights g_c belong to the unmoved domain).
   */
  template <int dim>
  void
  check_outside_grid()
  {
    TestGrid<dim> g(std::vector<unsigned int>{6, 5, 4});
    Random        random(41 + dim);
    // near the lower corner of the grid, and near the upper x face with a
    // domain sheared into the next cell above (the clamped corner is then
    // found by walking along the boundary)
    Point<dim> near_corner, near_face;
    for (unsigned int d = 0; d < dim; ++d)
      {
        near_corner[d] = g.lower[d] + 0.2 * g.h[d];
        near_face[d]   = g.lower[d] + 2.7 * g.h[d];
      }
    near_face[0] = g.upper[0] - 0.05 * g.h[0];
    for (const Family f : families)
      for (const bool sheared : {false, true})
        {
          const Point<dim> x = sheared ? near_face : near_corner;
          Tensor<1, dim>   l;
          for (unsigned int d = 0; d < dim; ++d)
            l[d] = 0.4 * g.h[d];
          TestParticle<dim> p;
          make_domain(f, false, l, x, random, p);
          if (sheared && dim > 1)
            {
              Tensor<2, dim> F = unit_symmetric_tensor<dim>();
              // a corner 0.35 h beyond the x face and 0.3 h into the
              // cell above: the walk meets the boundary first
              F[1][0] = 0.5 * g.h[1] / g.h[0];
              p.set_F(F);
              if (f == Family::cpdi2)
                {
                  Corners<dim> c;
                  for (unsigned int k = 0; k < n_corners<dim>; ++k)
                    {
                      Tensor<1, dim> s;
                      for (unsigned int d = 0; d < dim; ++d)
                        s[d] = (((k >> d) & 1) ? 1 : -1) * l[d];
                      c[k] = x + F * s;
                    }
                  p.set_corners(c);
                }
            }
          std::ostringstream what;
          what << dim << "D " << family_name(f)
               << (sheared ? ", sheared over the x face" : ", grid corner");
          Stencil<dim>       s;
          CornerWeights<dim> cw;
          const auto refused = evaluate_at(g, functions(g, f, false), x, p, s);
          BOOST_TEST_INFO(what.str());
          BOOST_CHECK(refused == Status<dim>::outside_grid);
          const auto clamped =
            evaluate_at(g, functions(g, f, true), x, p, s, &cw);
          BOOST_TEST_INFO(what.str());
          BOOST_REQUIRE(clamped == Status<dim>::ok);
          Point<dim> centroid;
          if (is_gimp(f))
            {
              Tensor<1, dim> half = l;
              if (f == Family::cpgimp)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const Tensor<2, dim> F  = p.F();
                    double               n2 = 0;
                    for (unsigned int i = 0; i < dim; ++i)
                      n2 += F[i][d] * F[i][d];
                    half[d] *= std::sqrt(n2);
                  }
              for (unsigned int d = 0; d < dim; ++d)
                centroid[d] = 0.5 * (std::max(x[d] - half[d], g.lower[d]) +
                                     std::min(x[d] + half[d], g.upper[d]));
            }
          else
            for (unsigned int k = 0; k < n_corners<dim>; ++k)
              {
                // the corners the family computed, clipped to the grid
                Point<dim> clipped = cw.x[k];
                for (unsigned int d = 0; d < dim; ++d)
                  clipped[d] =
                    std::min(g.upper[d], std::max(g.lower[d], clipped[d]));
                centroid += cw.w[k] * clipped;
              }
          BOOST_TEST_INFO(what.str() << ", clamped");
          BOOST_CHECK_SMALL(consistency_error(g, s, centroid, is_gimp(f)),
                            1e-13);
          if (sheared && dim > 1) // the domain spans two cells
            {
              BOOST_TEST_INFO(what.str() << ", clamped");
              BOOST_CHECK_GT(n_distinct_nodes(s), n_q1<dim>);
            }
        }
  }

  /// collapsed: CPDI with a nearly singular or an inverted F, CPDI2 with
  /// flat or crossed corners.
  template <int dim>
  void
  check_collapsed()
  {
    TestGrid<dim>  g(std::vector<unsigned int>{6, 5, 4});
    Point<dim>     x = g.vertex(2, 2, 2);
    Tensor<1, dim> l;
    for (unsigned int d = 0; d < dim; ++d)
      {
        x[d] += 0.1 * g.h[d];
        l[d] = 0.3 * g.h[d];
      }
    Random            random(43);
    const auto        cpdi  = functions(g, Family::cpdi);
    const auto        cpdi2 = functions(g, Family::cpdi2);
    Stencil<dim>      s;
    TestParticle<dim> p;
    make_domain(Family::cpdi, false, l, x, random, p);

    // nearly singular (2D, 3D): two columns of F almost parallel; 1D has
    // no angle, only the sign of F
    std::vector<std::pair<std::string, Tensor<2, dim>>> bad;
    Tensor<2, dim> F = unit_symmetric_tensor<dim>();
    if constexpr (dim > 1)
      {
        F[0][1] = 1;
        F[1][0] = 1;
        F[1][1] = 1 + 1e-6;
        bad.emplace_back("nearly singular F", F);
      }
    F       = unit_symmetric_tensor<dim>();
    F[0][0] = -1;
    bad.emplace_back("inverted F", F);
    for (const auto &[what, F] : bad)
      {
        p.set_F(F);
        const auto status = evaluate_at(g, cpdi, x, p, s);
        BOOST_TEST_INFO(dim << "D CPDI, " << what);
        BOOST_CHECK(status == Status<dim>::collapsed);
      }
    // a sheared but valid F is fine
    if constexpr (dim > 1)
      {
        F       = unit_symmetric_tensor<dim>();
        F[0][1] = 0.8;
        p.set_F(F);
        const auto status = evaluate_at(g, cpdi, x, p, s);
        BOOST_TEST_INFO(dim << "D CPDI, sheared F");
        BOOST_CHECK(status == Status<dim>::ok);
      }

    // CPDI2: two corners swapped (a bow tie); the last corner moved into
    // the plane of its neighbours (a corner angle of 180 degrees); the
    // corners of the nearly singular parallelogram. (A thin box is not
    // collapsed: the quality measures corner angles, not aspect ratio.)
    Corners<dim> box;
    for (unsigned int c = 0; c < n_corners<dim>; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        box[c][d] = x[d] + (((c >> d) & 1) ? l[d] : -l[d]);
    Corners<dim> crossed = box, flat = box, thin = box, squashed;
    std::swap(crossed[0], crossed[1]);
    const unsigned int last = n_corners<dim> - 1;
    flat[last]              = Point<dim>();
    for (unsigned int d = 0; d < dim; ++d)
      flat[last] += box[last ^ (1u << d)] / double(dim);
    for (unsigned int c = 0; c < n_corners<dim>; ++c)
      thin[c][0] = x[0] + 1e-7 * (((c >> 0) & 1) ? l[0] : -l[0]);
    std::vector<std::pair<std::string, Corners<dim>>> bad_corners = {
      {"crossed", crossed}};
    if (dim > 1) // a 1D domain has no angle
      {
        bad_corners.emplace_back("flat", flat);
        for (unsigned int c = 0; c < n_corners<dim>; ++c)
          squashed[c] = x + bad[0].second * (box[c] - x);
        bad_corners.emplace_back("squashed", squashed);
      }
    for (const auto &[what, corners] : bad_corners)
      {
        p.set_corners(corners);
        const auto status = evaluate_at(g, cpdi2, x, p, s);
        BOOST_TEST_INFO(dim << "D CPDI2, " << what << " corners");
        BOOST_CHECK(status == Status<dim>::collapsed);
      }
    for (const auto &[what, corners] :
         {std::make_pair("box", box), std::make_pair("thin box", thin)})
      {
        p.set_corners(corners);
        const auto status = evaluate_at(g, cpdi2, x, p, s);
        BOOST_TEST_INFO(dim << "D CPDI2, " << what);
        BOOST_CHECK(status == Status<dim>::ok);
      }
  }

  /**
   * too_wide: a GIMP box may overlap at most the neighbouring cell in
   * each direction. A box 2.8 cells wide at the centre of a cell ends in
   * the neighbours (fine: 3^dim cells, still consistent); 3.2 cells wide
   * it reaches beyond them. cpGIMP gets there by stretching.
   */
  template <int dim>
  void
  check_too_wide()
  {
    TestGrid<dim> g(std::vector<unsigned int>{6, 5, 4});
    Point<dim>    x = g.vertex(2, 2, 1);
    for (unsigned int d = 0; d < dim; ++d)
      x[d] += 0.5 * g.h[d];
    Random random(47);
    for (const Family f : {Family::ugimp, Family::cpgimp})
      {
        const auto sf = functions(g, f);
        for (const double width : {1.4, 1.6})
          {
            Tensor<1, dim> l;
            for (unsigned int d = 0; d < dim; ++d)
              l[d] = width * g.h[d];
            TestParticle<dim> p;
            make_domain(f, false, l, x, random, p);
            Stencil<dim> s;
            const auto   status = evaluate_at(g, sf, x, p, s);
            BOOST_TEST_INFO(dim << "D " << family_name(f) << ", half-width "
                                << width << " h");
            if (width < 1.5)
              {
                BOOST_REQUIRE(status == Status<dim>::ok);
                BOOST_CHECK_SMALL(consistency_error(g, s, x, true), 1e-13);
                BOOST_CHECK_EQUAL(n_distinct_nodes(s),
                                  Utilities::fixed_power<dim>(4u));
              }
            else
              BOOST_CHECK(status == Status<dim>::too_wide);
          }
        if (f == Family::cpgimp)
          {
            // a box of half a cell, stretched 3.5 times in direction 0
            Tensor<1, dim> l;
            for (unsigned int d = 0; d < dim; ++d)
              l[d] = 0.5 * g.h[d];
            TestParticle<dim> p;
            make_domain(f, false, l, x, random, p);
            Tensor<2, dim> F = unit_symmetric_tensor<dim>();
            F[0][0]          = 3.5;
            p.set_F(F);
            Stencil<dim> s;
            const auto   status = evaluate_at(g, sf, x, p, s);
            BOOST_TEST_INFO(dim << "D cpGIMP stretched");
            BOOST_CHECK(status == Status<dim>::too_wide);
          }
      }
  }

  /**
   * lost_corner: the corner walk gives up after 4 dim cells; a CPDI
   * domain reaching 5.5 cells in every direction is lost, one reaching
   * 2.2 cells is found (and consistent).
   */
  template <int dim>
  void
  check_lost_corner()
  {
    TestGrid<dim> g(std::vector<unsigned int>(3, 14));
    const auto    sf = functions(g, Family::cpdi);
    Point<dim>    x  = g.vertex(7, 7, 7);
    Random        random(53);
    for (unsigned int d = 0; d < dim; ++d)
      x[d] += 0.3 * g.h[d];
    for (const double reach : {2.2, 5.5})
      {
        Tensor<1, dim> l;
        for (unsigned int d = 0; d < dim; ++d)
          l[d] = reach * g.h[d];
        TestParticle<dim> p;
        make_domain(Family::cpdi, false, l, x, random, p);
        Stencil<dim> s;
        const auto   status = evaluate_at(g, sf, x, p, s);
        BOOST_TEST_INFO(dim << "D CPDI reaching " << reach << " cells");
        if (reach < 3)
          {
            BOOST_REQUIRE(status == Status<dim>::ok);
            BOOST_CHECK_SMALL(consistency_error(g, s, x, true), 1e-13);
          }
        else
          BOOST_CHECK(status == Status<dim>::lost_corner);
      }
  }
} // namespace

BOOST_AUTO_TEST_CASE(status_outside_grid_and_clamp)
{
  check_outside_grid<1>();
  check_outside_grid<2>();
  check_outside_grid<3>();
}

BOOST_AUTO_TEST_CASE(status_collapsed)
{
  check_collapsed<1>();
  check_collapsed<2>();
  check_collapsed<3>();
}

BOOST_AUTO_TEST_CASE(status_too_wide)
{
  check_too_wide<1>();
  check_too_wide<2>();
  check_too_wide<3>();
}

BOOST_AUTO_TEST_CASE(status_lost_corner)
{
  check_lost_corner<1>();
  check_lost_corner<2>();
  check_lost_corner<3>();
}
