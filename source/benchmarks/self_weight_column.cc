#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/self_weight_column.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    template <int dim>
    SelfWeightColumn<dim>::SelfWeightColumn(const double height,
                                            const double width,
                                            const double rho,
                                            const double g,
                                            const double nu,
                                            const double h)
      : height(height)
      , width(width)
      , rho(rho)
      , g(g)
      , nu(nu)
      , h(h)
      // cells of the column and one row above it for the settled top
      , nx(static_cast<unsigned int>(std::ceil(width / h - 1e-9)))
      , ny(static_cast<unsigned int>(std::ceil(height / h - 1e-9)) + 1)
    {}

    template <int dim>
    std::vector<std::string>
    SelfWeightColumn<dim>::columns() const
    {
      return {"sigma_yy_error", "pressure_error", "checkerboard"};
    }

    template <int dim>
    std::vector<double>
    SelfWeightColumn<dim>::measure(Particles::ParticleHandler<dim> &particles,
                                   const double,
                                   const MPI_Comm comm) const
    {
      using L = ParticleLayout<dim>;
      // per cell: V, V * pressure error; then totals: V, |yy error| V,
      // |p error| V
      const unsigned int  n_cells = nx * ny;
      std::vector<double> local(2 * n_cells + 3, 0.);
      for (const auto &p : particles)
        {
          const double *prop = p.get_properties().data();
          const double  V    = prop[L::volume];
          const double  Y    = prop[L::X + 1];
          const double *s    = prop + L::stress;
          const double  yy   = -rho * g * (height - Y);
          const double  xx   = nu / (1 - nu) * yy;
          const double  zz   = dim == 2 ? nu * (xx + yy) : xx;
          const double  p_ex = -(xx + yy + zz) / 3;
          const double  p_mp = -(s[0] + s[1] + s[2]) / 3;
          local[2 * n_cells] += V;
          local[2 * n_cells + 1] += std::abs(s[1] - yy) * V;
          local[2 * n_cells + 2] += std::abs(p_mp - p_ex) * V;
          const int i = static_cast<int>(std::floor(p.get_location()[0] / h));
          const int j = static_cast<int>(std::floor(p.get_location()[1] / h));
          if (i >= 0 && j >= 0 && i < int(nx) && j < int(ny))
            {
              local[2 * (i + nx * j)] += V;
              local[2 * (i + nx * j) + 1] += (p_mp - p_ex) * V;
            }
        }
      std::vector<double> sum(local.size());
      Utilities::MPI::sum(local, comm, sum);

      const double scale = rho * g * height;
      auto         error = [&](const unsigned int i, const unsigned int j) {
        const double V = sum[2 * (i + nx * j)];
        return V > 0 ? sum[2 * (i + nx * j) + 1] / V : std::nan("");
      };
      double       jumps2  = 0;
      unsigned int n_pairs = 0;
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const double e = error(i, j);
            if (std::isnan(e))
              continue;
            const double right = i + 1 < nx ? error(i + 1, j) : std::nan("");
            const double up    = j + 1 < ny ? error(i, j + 1) : std::nan("");
            for (const double n : {right, up})
              if (!std::isnan(n))
                {
                  jumps2 += (e - n) * (e - n);
                  ++n_pairs;
                }
          }
      const double V = sum[2 * n_cells];
      return {sum[2 * n_cells + 1] / (V * scale),
              sum[2 * n_cells + 2] / (V * scale),
              n_pairs > 0 ? std::sqrt(jumps2 / n_pairs) / scale : 0.};
    }

    template class SelfWeightColumn<2>;
    template class SelfWeightColumn<3>;
  } // namespace benchmarks
} // namespace mpm
