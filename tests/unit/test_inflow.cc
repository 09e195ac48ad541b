// The inlet's layout (particles/inflow.h): in 2D and 3D, any direction,
// each layer carries exactly A s of volume; the particles lie in the
// inlet's plane (at the travelled distance), inside the segment or disk,
// with domains of their own volume whose half-vectors are s/2 along the
// flow and whose corners are the domain's; the layer count follows the
// crossing times tau_k = t0 + (k + 1/2) s / v, bounded by Volume and End
// time; ids interleave the inlets of a run.
#define BOOST_TEST_MODULE inflow
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <mpm/particles/inflow.h>

#include <cmath>

#include <boost/test/unit_test.hpp>

using namespace dealii;

namespace
{
  template <int dim>
  mpm::InflowParameters<dim>
  inlet(const Tensor<1, dim> &direction, const double radius)
  {
    mpm::InflowParameters<dim> p;
    p.enabled = true;
    for (unsigned int d = 0; d < dim; ++d)
      p.center[d] = 0.3 + 0.1 * d;
    p.direction  = direction / direction.norm();
    p.radius     = radius;
    p.speed      = 2;
    p.start_time = 0.1;
    p.spacing    = 0.01;
    return p;
  }

  template <int dim>
  void
  check_layer(const mpm::InflowParameters<dim> &p)
  {
    const mpm::Inflow<dim>              in(p, 0, 1.0, "Inflow");
    std::vector<mpm::ParticleSeed<dim>> seeds;
    std::vector<unsigned long long>     ids;
    const double                        t = 0.3;
    in.layer(3, t, seeds, ids);
    BOOST_TEST(seeds.size() == in.n_per_layer());
    // layer 3 crossed at tau = t0 + 3.5 s / v
    const double travelled = (t - p.start_time) * p.speed - 3.5 * p.spacing;
    double       volume    = 0;
    for (const auto &s : seeds)
      {
        volume += s.volume;
        const Tensor<1, dim> r = s.position - p.center;
        BOOST_TEST(std::abs(r * p.direction - travelled) < 1e-14);
        const Tensor<1, dim> across = r - (r * p.direction) * p.direction;
        BOOST_TEST(across.norm() < p.radius);
        BOOST_TEST(std::abs(determinant(s.domain) * (1 << dim) - s.volume) <
                   1e-15);
        Tensor<1, dim> along;
        for (unsigned int d = 0; d < dim; ++d)
          along[d] = s.domain[d][0];
        BOOST_TEST((along - p.spacing / 2 * p.direction).norm() < 1e-15);
        // the last corner is x + sum r_i, the first x - sum r_i
        for (unsigned int d = 0; d < dim; ++d)
          {
            double sum = 0;
            for (unsigned int i = 0; i < dim; ++i)
              sum += s.domain[d][i];
            BOOST_TEST(std::abs(s.corners[(1 << dim) - 1][d] - s.position[d] -
                                sum) < 1e-15);
            BOOST_TEST(std::abs(s.corners[0][d] - s.position[d] + sum) < 1e-15);
          }
      }
    BOOST_TEST(std::abs(volume / (p.area() * p.spacing) - 1) < 1e-14);
  }
} // namespace

BOOST_AUTO_TEST_CASE(layer_volume_and_placement_2d)
{
  check_layer(inlet<2>(Tensor<1, 2>({0, -1}), 0.05));
  check_layer(inlet<2>(Tensor<1, 2>({0.3, -1}), 0.043));
}

BOOST_AUTO_TEST_CASE(layer_volume_and_placement_3d)
{
  check_layer(inlet<3>(Tensor<1, 3>({0, 0, -1}), 0.05));
  check_layer(inlet<3>(Tensor<1, 3>({1, 2, -0.5}), 0.037));
  const mpm::Inflow<3> in(inlet<3>(Tensor<1, 3>({0, 0, 1}), 0.05), 0, 1, "");
  // the square lattice of spacing s through the centre, inside r < R:
  // 69 points for R = 5 s
  BOOST_TEST(in.n_per_layer() == 69u);
}

BOOST_AUTO_TEST_CASE(layer_count)
{
  auto p = inlet<2>(Tensor<1, 2>({1, 0}), 0.05);
  // layers with tau_k <= t: k + 1/2 <= (t - t0) v / s
  const mpm::Inflow<2> in(p, 0, 1.0, "");
  BOOST_TEST(in.layers_at(0.05) == 0u);
  BOOST_TEST(in.layers_at(0.1 + 0.5 * 0.01 / 2 - 1e-12) == 0u);
  BOOST_TEST(in.layers_at(0.1 + 0.5 * 0.01 / 2 + 1e-12) == 1u);
  BOOST_TEST(in.layers_at(0.3) == 40u);
  // until the run's end: (1 - 0.1) * 2 / 0.01 = 180 layers
  BOOST_TEST(in.n_layers() == 180u);
  BOOST_TEST(in.layers_at(1.0) == in.n_layers());
  p.end_time = 0.3;
  BOOST_TEST(mpm::Inflow<2>(p, 0, 1.0, "").n_layers() == 40u);
  p.volume = 0.1 * 0.01 * 25; // 25 layers of A s
  BOOST_TEST(mpm::Inflow<2>(p, 0, 1.0, "").n_layers() == 25u);
  BOOST_TEST(mpm::Inflow<2>::planned_particles(p, 1.0) ==
             25u * in.n_per_layer());
}

BOOST_AUTO_TEST_CASE(interleaved_ids)
{
  mpm::Inflow<2>           a(inlet<2>(Tensor<1, 2>({0, -1}), 0.05), 0, 1, "");
  mpm::Inflow<2>           b(inlet<2>(Tensor<1, 2>({0, -1}), 0.02), 1, 1, "");
  const unsigned long long stride = a.n_per_layer() + b.n_per_layer();
  a.set_ids(100, stride);
  b.set_ids(100 + a.n_per_layer(), stride);
  std::vector<mpm::ParticleSeed<2>> seeds;
  std::vector<unsigned long long>   ids;
  for (unsigned int k = 0; k < 3; ++k)
    {
      a.layer(k, 0.5, seeds, ids);
      b.layer(k, 0.5, seeds, ids);
    }
  // every id from 100 to 100 + 3 stride - 1 exactly once
  std::sort(ids.begin(), ids.end());
  BOOST_TEST(ids.size() == 3 * stride);
  for (std::size_t i = 0; i < ids.size(); ++i)
    BOOST_TEST(ids[i] == 100 + i);
}
