#include <mpm/grid/grid_update.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/transfer/grid_to_particle.h>

#include <cmath>
#include <sstream>

namespace mpm
{
  namespace transfer
  {
    using namespace dealii;

    template <int dim>
    std::string
    grid_to_particle(const BackgroundGrid<dim>       &grid,
                     Particles::ParticleHandler<dim> &particles,
                     const NodalVector               &kinematics,
                     const double                     dt,
                     const double                     flip,
                     NodalVector                     *remap)
    {
      using L                         = ParticleLayout<dim>;
      using K                         = KinematicsLayout<dim>;
      constexpr unsigned int nv       = shape_functions::n_q1<dim>;
      const double          *in       = kinematics.begin();
      double                *momentum = nullptr;
      if (remap)
        {
          *remap   = 0.;
          momentum = remap->begin();
        }
      std::string error;
      double      N[nv];
      for_each_cell_with_particles(
        grid, particles, [&](const auto &cell, const auto &pic) {
          const unsigned int *nodes          = grid.nodes(cell);
          double              local[nv][dim] = {}; // re-mapped momentum
          for (auto &p : pic)
            {
              shape_functions::Q1Cell<dim>::values(p.get_reference_location(),
                                                   N);
              double v_grid[dim] = {}, dv[dim] = {};
              for (unsigned int v = 0; v < nv; ++v)
                {
                  const double *k = in + nodes[v] * K::n_components;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      v_grid[d] += N[v] * k[K::velocity + d];
                      dv[d] += N[v] * k[K::increment + d];
                    }
                }
              move_particle<dim>(p, v_grid, dv, flip, false, dt, error);
              if (momentum)
                {
                  const double *prop = p.get_properties().data();
                  for (unsigned int v = 0; v < nv; ++v)
                    {
                      const double w = N[v] * prop[L::mass];
                      for (unsigned int d = 0; d < dim; ++d)
                        local[v][d] += w * prop[L::velocity + d];
                    }
                }
            }
          if (momentum)
            for (unsigned int v = 0; v < nv; ++v)
              for (unsigned int d = 0; d < dim; ++d)
                momentum[nodes[v] * dim + d] += local[v][d];
        });
      if (remap)
        remap->compress(VectorOperation::add);
      return error;
    }

    template std::string
    grid_to_particle<1>(const BackgroundGrid<1> &,
                        Particles::ParticleHandler<1> &,
                        const NodalVector &,
                        double,
                        double,
                        NodalVector *);
    template std::string
    grid_to_particle<2>(const BackgroundGrid<2> &,
                        Particles::ParticleHandler<2> &,
                        const NodalVector &,
                        double,
                        double,
                        NodalVector *);
    template std::string
    grid_to_particle<3>(const BackgroundGrid<3> &,
                        Particles::ParticleHandler<3> &,
                        const NodalVector &,
                        double,
                        double,
                        NodalVector *);
  } // namespace transfer
} // namespace mpm
