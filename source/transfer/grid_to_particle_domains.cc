#include <mpm/grid/grid_update.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/transfer/grid_to_particle.h>
#include <mpm/transfer/velocity_gradient.h>

#include <cmath>
#include <sstream>

namespace mpm
{
  namespace transfer
  {
    using namespace dealii;

    template <int dim>
    std::string
    grid_to_particle_domains(
      const BackgroundGrid<dim>                        &grid,
      Particles::ParticleHandler<dim>                  &particles,
      const NodalVector                                &kinematics,
      const double                                      dt,
      const double                                      flip,
      const shape_functions::DomainShapeFunctions<dim> &domains,
      NodalVector                                      *remap,
      const unsigned int                                affine)
    {
      double *momentum = nullptr;
      if (remap)
        {
          *remap   = 0.;
          momentum = remap->begin();
        }
      using L                          = ParticleLayout<dim>;
      using K                          = KinematicsLayout<dim>;
      const double                 *in = kinematics.begin();
      std::string                   error;
      shape_functions::Stencil<dim> st;
      domains.begin_pass(particles.n_locally_owned_particles());
      for_each_cell_with_particles(
        grid, particles, [&](const auto &cell, const auto &pic) {
          const unsigned int index   = cell->active_cell_index();
          unsigned int       ordinal = 0;
          for (auto &p : pic)
            {
              double *prop = p.get_properties().data();
              if (!domains.evaluate(index, ordinal++, p, st, error))
                continue;
              double v_grid[dim] = {}, dv[dim] = {};
              for (unsigned int k = 0; k < st.n; ++k)
                {
                  const double *node = in + st.node[k] * K::n_components;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      v_grid[d] += st.value[k] * node[K::velocity + d];
                      dv[d] += st.value[k] * node[K::increment + d];
                    }
                }
              Tensor<2, dim> C; // APIC: sum_i v_i (x) grad S_ip
              if (affine)
                {
                  C = velocity_gradient<dim>(in, st);
                  store_matrix<dim>(C, prop + affine);
                }
              move_particle<dim>(p, v_grid, dv, flip, affine != 0, dt, error);
              // MUSL: the new particle momentum back to the nodes, with
              // the same weights
              if (momentum)
                {
                  const Point<dim> x_c =
                    affine ? stencil_centroid(st, grid) : Point<dim>();
                  for (unsigned int k = 0; k < st.n; ++k)
                    {
                      Tensor<1, dim> v;
                      for (unsigned int d = 0; d < dim; ++d)
                        v[d] = prop[L::velocity + d];
                      if (affine)
                        v += C * (grid.node_position(st.node[k]) - x_c);
                      for (unsigned int d = 0; d < dim; ++d)
                        momentum[st.node[k] * dim + d] +=
                          st.value[k] * prop[L::mass] * v[d];
                    }
                }
            }
        });
      domains.end_pass(error.empty());
      if (remap)
        remap->compress(VectorOperation::add);
      return error;
    }

    template <int dim>
    std::string
    move_domain_corners(
      const BackgroundGrid<dim>                        &grid,
      Particles::ParticleHandler<dim>                  &particles,
      const NodalVector                                &kinematics,
      const double                                      dt,
      const shape_functions::DomainShapeFunctions<dim> &domains)
    {
      using K = KinematicsLayout<dim>;
      using Status =
        typename shape_functions::DomainShapeFunctions<dim>::Status;
      std::string error;
      for_each_cell_with_particles(
        grid, particles, [&](const auto &cell, const auto &pic) {
          for (auto &p : pic)
            {
              const Status status =
                domains.move_corners(cell->active_cell_index(),
                                     p.get_reference_location(),
                                     p.get_properties().data(),
                                     kinematics.begin() + K::velocity,
                                     K::n_components,
                                     dt);
              if (status != Status::ok && error.empty())
                error = domains.message(status, p.get_id(), p.get_location());
            }
        });
      return error;
    }

#define MPM_INSTANTIATE(d)                            \
  template std::string grid_to_particle_domains<d>(   \
    const BackgroundGrid<d> &,                        \
    Particles::ParticleHandler<d> &,                  \
    const NodalVector &,                              \
    double,                                           \
    double,                                           \
    const shape_functions::DomainShapeFunctions<d> &, \
    NodalVector *,                                    \
    unsigned int);                                    \
  template std::string move_domain_corners<d>(        \
    const BackgroundGrid<d> &,                        \
    Particles::ParticleHandler<d> &,                  \
    const NodalVector &,                              \
    double,                                           \
    const shape_functions::DomainShapeFunctions<d> &);
    MPM_INSTANTIATE(1)
    MPM_INSTANTIATE(2)
    MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
  } // namespace transfer
} // namespace mpm
