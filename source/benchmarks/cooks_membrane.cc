#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/benchmarks/cooks_membrane.h>
#include <mpm/benchmarks/global_sums.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>
#include <limits>
#include <utility>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    namespace
    {
      const BenchmarkDeclaration declaration{
        "cooks membrane",
        "Cook's membrane, the tapered panel (0,0), (48,44), (48,60), "
        "(0,44) clamped at x = 0 under a vertical shear load F on its right "
        "edge; u_y against the FE reference",
        {nonzero_constant("F",
                          "total load on the right edge [N]",
                          "the ratios are divided by it"),
         required_constant("uy_ref",
                           "FE reference of u_y at (48,60) for F = 1"),
         required_constant("uy_ref_mid",
                           "FE reference of u_y at (48,52) for F = 1"),
         positive_constant("r_fit",
                           "radius of the plane fitted around a point",
                           "the particles within it make the fit")},
        {"uy_corner",
         "uy_mid",
         "corner_ratio",
         "mid_ratio",
         "corner_nearest_ratio"}};
    } // namespace

    template <int dim>
    CooksMembrane<dim>::CooksMembrane(const double F,
                                      const double uy_ref,
                                      const double uy_ref_mid,
                                      const double r_fit)
      : Benchmark<dim>(declaration.columns)
      , F(F)
      , uy_ref(uy_ref)
      , uy_ref_mid(uy_ref_mid)
      , r_fit(r_fit)
    {}

    template <int dim>
    CooksMembrane<dim>::CooksMembrane(const BenchmarkConstants &c)
      : CooksMembrane(c["F"], c["uy_ref"], c["uy_ref_mid"], c["r_fit"])
    {}

    template <int dim>
    double
    CooksMembrane<dim>::fitted_uy(Particles::ParticleHandler<dim> &particles,
                                  const Point<dim>                &X0,
                                  const MPI_Comm                   comm) const
    {
      using L = ParticleLayout<dim>;
      // normal equations of the plane a + b.(X - X0): the upper triangle of
      // sum phi phi^T and sum phi u_y, phi = (1, X - X0)
      constexpr unsigned int n                = dim + 1;
      double                 local[n * n + n] = {};
      for (const auto &particle : particles)
        {
          const double *prop = particle.get_properties().data();
          Point<dim>    X;
          for (unsigned int d = 0; d < dim; ++d)
            X[d] = prop[L::X + d];
          if (X.distance(X0) > r_fit)
            continue;
          double phi[n] = {1.};
          for (unsigned int d = 0; d < dim; ++d)
            phi[d + 1] = X[d] - X0[d];
          const double uy = particle.get_location()[1] - X[1];
          for (unsigned int i = 0; i < n; ++i)
            {
              for (unsigned int j = 0; j < n; ++j)
                local[i * n + j] += phi[i] * phi[j];
              local[n * n + i] += phi[i] * uy;
            }
        }
      const auto   sum = global_sums(local, comm);
      Tensor<2, n> A;
      Tensor<1, n> b;
      for (unsigned int i = 0; i < n; ++i)
        {
          for (unsigned int j = 0; j < n; ++j)
            A[i][j] = sum[i * n + j];
          b[i] = sum[n * n + i];
        }
      // fewer than n particles, or all on a line: the plane is undetermined
      // (the scale of A is the particle count times r_fit^2 per direction)
      const double scale = std::pow(A[0][0] * r_fit * r_fit, dim);
      if (A[0][0] < n || !(std::abs(determinant(A)) > 1e-10 * scale))
        return std::nan("");
      return (invert(A) * b)[0];
    }

    template <int dim>
    std::vector<double>
    CooksMembrane<dim>::measure(Particles::ParticleHandler<dim> &particles,
                                const double,
                                const MPI_Comm comm) const
    {
      using L = ParticleLayout<dim>;
      Point<dim> corner, mid;
      corner[0] = mid[0]     = 48;
      corner[1]              = 60;
      mid[1]                 = 52;
      const double uy_corner = fitted_uy(particles, corner, comm);
      const double uy_mid    = fitted_uy(particles, mid, comm);

      // the particle nearest the corner (ties: the lowest distance, then
      // the lowest rank's value)
      std::pair<double, double> nearest(std::numeric_limits<double>::max(),
                                        std::nan(""));
      for (const auto &particle : particles)
        {
          const double *prop = particle.get_properties().data();
          Point<dim>    X;
          for (unsigned int d = 0; d < dim; ++d)
            X[d] = prop[L::X + d];
          const double r = X.distance(corner);
          if (r < nearest.first)
            nearest = {r, particle.get_location()[1] - X[1]};
        }
      // every rank picks the same: the first of the smallest distance in
      // rank order
      const auto all = Utilities::MPI::all_gather(comm, nearest);
      nearest        = all[0];
      for (const auto &candidate : all)
        if (candidate.first < nearest.first)
          nearest = candidate;
      return {uy_corner,
              uy_mid,
              uy_corner / (F * uy_ref),
              uy_mid / (F * uy_ref_mid),
              nearest.second / (F * uy_ref)};
    }

    template class CooksMembrane<2>;

    MPM_REGISTER_BENCHMARK(CooksMembrane, declaration, 2)
  } // namespace benchmarks
} // namespace mpm
