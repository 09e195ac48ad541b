#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>

#include <mpm/benchmarks/checkerboard.h>
#include <mpm/benchmarks/global_sums.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    template <int dim>
    double
    checkerboard(Particles::ParticleHandler<dim>             &particles,
                 const std::function<double(const double *)> &error,
                 const MPI_Comm                               comm)
    {
      return checkerboard_with_position<dim>(
        particles,
        [&](const double *prop, const Point<dim> &) { return error(prop); },
        comm);
    }

    template <int dim>
    double
    checkerboard_with_position(
      Particles::ParticleHandler<dim> &particles,
      const std::function<double(const double *, const Point<dim> &)> &error,
      const MPI_Comm                                                   comm)
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
      // per cell: V, V * error
      std::vector<double> local(2 * n_cells, 0.);
      for (const auto &p : particles)
        {
          const double *prop = p.get_properties().data();
          const double  V    = prop[L::volume];
          const auto c = p.get_surrounding_cell()->global_active_cell_index();
          local[2 * c] += V;
          local[2 * c + 1] += error(prop, p.get_location()) * V;
        }
      std::vector<double> sum(local.size());
      Utilities::MPI::sum(local, comm, sum);

      auto cell_error = [&](const types::global_cell_index c) {
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
            const double e = cell_error(c);
            if (std::isnan(e))
              continue;
            for (const unsigned int f : cell->face_indices())
              {
                if (cell->at_boundary(f) || !cell->neighbor(f)->is_active())
                  continue;
                const auto   n  = cell->neighbor(f)->global_active_cell_index();
                const double en = cell_error(n);
                if (n < c || std::isnan(en))
                  continue;
                jumps[0] += (e - en) * (e - en);
                jumps[1] += 1;
              }
          }
      const auto global_jumps = global_sums(jumps, comm);
      return global_jumps[1] > 0 ?
               std::sqrt(global_jumps[0] / global_jumps[1]) :
               0.;
    }

    template double
    checkerboard<2>(Particles::ParticleHandler<2> &,
                    const std::function<double(const double *)> &,
                    const MPI_Comm);
    template double
    checkerboard<3>(Particles::ParticleHandler<3> &,
                    const std::function<double(const double *)> &,
                    const MPI_Comm);
    template double
    checkerboard_with_position<2>(
      Particles::ParticleHandler<2> &,
      const std::function<double(const double *, const Point<2> &)> &,
      const MPI_Comm);
    template double
    checkerboard_with_position<3>(
      Particles::ParticleHandler<3> &,
      const std::function<double(const double *, const Point<3> &)> &,
      const MPI_Comm);
  } // namespace benchmarks
} // namespace mpm
