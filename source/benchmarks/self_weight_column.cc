#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>

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
                                            const double rho,
                                            const double g,
                                            const double nu)
      : height(height)
      , rho(rho)
      , g(g)
      , nu(nu)
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
      // The cells of the particles: global indices, so that every rank
      // sees the sums of every cell.
      const Triangulation<dim> *tria =
        particles.n_locally_owned_particles() > 0 ?
          &particles.begin()->get_surrounding_cell()->get_triangulation() :
          nullptr;
      const unsigned int n_cells = Utilities::MPI::max(
        tria ? static_cast<unsigned int>(tria->n_global_active_cells()) : 0u,
        comm);
      // per cell: V, V * pressure error; then totals: V, |yy error| V,
      // |p error| V
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
          const auto c = p.get_surrounding_cell()->global_active_cell_index();
          local[2 * c] += V;
          local[2 * c + 1] += (p_mp - p_ex) * V;
        }
      std::vector<double> sum(local.size());
      Utilities::MPI::sum(local, comm, sum);

      const double scale = rho * g * height;
      auto         error = [&](const types::global_cell_index c) {
        const double V = sum[2 * c];
        return V > 0 ? sum[2 * c + 1] / V : std::nan("");
      };
      // each pair once: from the owned cell with the smaller index
      double jumps[2] = {};
      if (tria)
        for (const auto &cell : tria->active_cell_iterators())
          {
            if (!cell->is_locally_owned())
              continue;
            const auto   c = cell->global_active_cell_index();
            const double e = error(c);
            if (std::isnan(e))
              continue;
            for (const unsigned int f : cell->face_indices())
              {
                if (cell->at_boundary(f) || !cell->neighbor(f)->is_active())
                  continue;
                const auto n = cell->neighbor(f)->global_active_cell_index();
                const double en = error(n);
                if (n < c || std::isnan(en))
                  continue;
                jumps[0] += (e - en) * (e - en);
                jumps[1] += 1;
              }
          }
      double global_jumps[2];
      Utilities::MPI::sum(ArrayView<const double>(jumps, 2),
                          comm,
                          ArrayView<double>(global_jumps, 2));
      const double V = sum[2 * n_cells];
      return {sum[2 * n_cells + 1] / (V * scale),
              sum[2 * n_cells + 2] / (V * scale),
              global_jumps[1] > 0 ?
                std::sqrt(global_jumps[0] / global_jumps[1]) / scale :
                0.};
    }

    template class SelfWeightColumn<2>;
    template class SelfWeightColumn<3>;
  } // namespace benchmarks
} // namespace mpm
