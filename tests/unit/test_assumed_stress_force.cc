// The internal force of a cell's assumed-stress field (AssumedStressForce):
// on an axis-parallel box that its particles fill (at least 2^dim of
// them, covering 3/4 of the cell) it equals the exact integral of
// -sigma(xi) grad N_v over the particle domains, for any particle layout
// and any field coefficients (checked against a 6-point Gauss rule per
// direction in every domain, which is exact for the polynomial
// integrand), and the particle midpoint rule it replaces is not (the
// check can fail); in a sparse cell it is that particle sum; the forces
// sum to zero (linear momentum).
#define BOOST_TEST_MODULE assumed_stress_force
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <deal.II/base/quadrature_lib.h>

#include <mpm/remedies/assumed_stress.h>
#include <mpm/remedies/assumed_stress_force.h>
#include <mpm/shape_functions/q1_cell.h>

#include <random>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using namespace mpm::remedies;

namespace
{
  /// n_particles random particles with domain half-widths (reference
  /// coordinates) in [a_min, a_max]. A filled cell (at least 2^dim
  /// particles covering 3/4 of it) must get the exact integral; a sparse
  /// one the particle sum. @p enriched: the enriched field.
  template <int dim>
  void
  check_box(const unsigned int seed,
            const unsigned int n_particles,
            const double       a_min,
            const double       a_max,
            const bool         enriched = false)
  {
    constexpr unsigned int                 nv = mpm::shape_functions::n_q1<dim>;
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> u(0, 1);

    std::array<Point<dim>, nv> vertices;
    Tensor<1, dim>             extent;
    for (unsigned int d = 0; d < dim; ++d)
      extent[d] = 0.5 + u(gen);
    for (unsigned int v = 0; v < nv; ++v)
      for (unsigned int d = 0; d < dim; ++d)
        vertices[v][d] = 1.0 + (((v >> d) & 1) ? extent[d] : 0.);
    mpm::shape_functions::Q1Cell<dim> cell;
    cell.reinit(vertices, 1e-12);
    BOOST_REQUIRE(cell.is_box);

    Tensor<2, dim> J0;
    for (unsigned int d = 0; d < dim; ++d)
      J0[d][d] = extent[d];
    const AssumedStressProjection<dim> field(J0,
                                             Metric::mass,
                                             SymmetricTensor<4, dim>(),
                                             enriched);
    double beta[AssumedStressProjection<dim>::n_beta];
    for (double &b : beta)
      b = 2 * u(gen) - 1;

    // particles: random centres, axis-parallel domains of random size
    AssumedStressForce<dim> force;
    force.clear();
    const QGauss<dim>   gauss(6);
    std::vector<double> exact(nv * dim, 0.), midpoint(nv * dim, 0.);
    double              N[nv];
    Tensor<1, dim>      G[nv];
    double              cell_volume = 1, total_volume = 0;
    for (unsigned int d = 0; d < dim; ++d)
      cell_volume *= extent[d];
    std::vector<Point<dim>>     centres(n_particles);
    std::vector<Tensor<2, dim>> half(n_particles);
    std::vector<double>         volumes(n_particles, 1.);
    for (unsigned int p = 0; p < n_particles; ++p)
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            half[p][d][d] = a_min + (a_max - a_min) * u(gen);
            centres[p][d] = half[p][d][d] + (1 - 2 * half[p][d][d]) * u(gen);
            volumes[p] *= 2 * half[p][d][d] * extent[d];
          }
        total_volume += volumes[p];
      }
    // as the caller does: domains only in a cell they fill
    const bool filled =
      AssumedStressForce<dim>::fills(n_particles, total_volume, cell_volume);
    for (unsigned int p = 0; p < n_particles; ++p)
      {
        const Point<dim>     &xi = centres[p];
        const Tensor<2, dim> &q  = half[p];
        const double          V  = volumes[p];
        force.add_particle(xi, filled ? q : Tensor<2, dim>(), V);
        for (unsigned int k = 0; k < gauss.size(); ++k)
          {
            Point<dim> x = xi;
            for (unsigned int d = 0; d < dim; ++d)
              x[d] += q[d][d] * (2 * gauss.point(k)[d] - 1);
            cell.values_and_gradients(x, N, G);
            const auto sigma = field.field(x, beta);
            for (unsigned int v = 0; v < nv; ++v)
              {
                const Tensor<1, dim> f = -V * gauss.weight(k) * (sigma * G[v]);
                for (unsigned int d = 0; d < dim; ++d)
                  exact[v * dim + d] += f[d];
              }
          }
        cell.values_and_gradients(xi, N, G);
        const auto sigma = field.field(xi, beta);
        for (unsigned int v = 0; v < nv; ++v)
          {
            const Tensor<1, dim> f = -V * (sigma * G[v]);
            for (unsigned int d = 0; d < dim; ++d)
              midpoint[v * dim + d] += f[d];
          }
      }
    std::vector<double> f(nv * dim, 0.);
    force.add_internal_force(cell, field, beta, f.data());

    double scale = 0, error = 0, midpoint_error = 0;
    double sum[dim] = {};
    for (unsigned int i = 0; i < nv * dim; ++i)
      {
        scale = std::max(scale, std::abs(exact[i]));
        error = std::max(error, std::abs(f[i] - exact[i]));
        midpoint_error =
          std::max(midpoint_error, std::abs(midpoint[i] - exact[i]));
        sum[i % dim] += f[i];
      }
    BOOST_TEST(filled == (n_particles >= (1u << dim)));
    if (filled)
      {
        BOOST_TEST(error <= 1e-13 * scale);
        BOOST_TEST(midpoint_error > 1e-4 * scale);
      }
    else
      {
        double from_midpoint = 0;
        for (unsigned int i = 0; i < nv * dim; ++i)
          from_midpoint = std::max(from_midpoint, std::abs(f[i] - midpoint[i]));
        BOOST_TEST(from_midpoint <= 1e-13 * scale);
      }
    for (unsigned int d = 0; d < dim; ++d)
      BOOST_TEST(std::abs(sum[d]) <= 1e-13 * scale);
  }
} // namespace

BOOST_AUTO_TEST_CASE(exact_on_filled_boxes_2d)
{
  for (unsigned int seed = 1; seed <= 20; ++seed)
    check_box<2>(seed, 8, 0.2, 0.3);
}

BOOST_AUTO_TEST_CASE(exact_on_filled_boxes_3d)
{
  for (unsigned int seed = 1; seed <= 20; ++seed)
    check_box<3>(seed, 12, 0.25, 0.35);
}

BOOST_AUTO_TEST_CASE(exact_on_filled_boxes_enriched_field)
{
  for (unsigned int seed = 1; seed <= 20; ++seed)
    {
      check_box<2>(seed, 8, 0.2, 0.3, true);
      check_box<3>(seed, 12, 0.25, 0.35, true);
    }
}

BOOST_AUTO_TEST_CASE(particle_sum_in_sparse_cells)
{
  for (unsigned int seed = 1; seed <= 20; ++seed)
    {
      check_box<2>(seed, 3, 0.05, 0.25);
      check_box<3>(seed, 7, 0.05, 0.25);
    }
}
