#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/shape_functions/family_registry.h>
#include <mpm/transfer/grid_to_particle.h>
#include <mpm/transfer/nodal_sum.h>
#include <mpm/transfer/velocity_gradient.h>

namespace mpm
{
  namespace transfer
  {
    using namespace dealii;

    namespace
    {
      /// The G2P pass of family @p Family: per cell, the family's weights
      /// of each particle; the re-mapped momenta summed as the family
      /// asks (NodalSum). Compiled per family: no family branch in the
      /// loop.
      template <typename Family, int dim>
      std::string
      g2p_pass(const G2PContext<dim> &c)
      {
        using L          = ParticleLayout<dim>;
        using K          = KinematicsLayout<dim>;
        using Weights    = typename Family::template Weights<dim>;
        using Sum        = NodalSum<Family, dim, dim>;
        double *momentum = nullptr;
        if (c.remap)
          {
            if (c.active)
              c.active->zero(*c.remap, dim);
            else
              *c.remap = 0.;
            momentum = c.remap->begin();
          }
        const double *in   = c.kinematics.begin();
        bool          apic = false;
        if constexpr (Family::allows_apic)
          apic = c.affine != 0;
        std::string error;
        Weights     weights(c.grid, c.domains);

        weights.begin_pass(c.particles.n_locally_owned_particles());
        for_each_cell_with_particles(
          c.grid, c.particles, [&](const auto &cell, const auto &pic) {
            weights.begin_cell(cell);
            Sum sum(momentum, dim);
            for (auto &p : pic)
              {
                double *prop = p.get_properties().data();
                if (c.only.template skips<dim>(prop) ||
                    !weights.evaluate(p, false, error))
                  continue;
                double v_grid[dim] = {}, dv[dim] = {};
                for (unsigned int k = 0; k < weights.size(); ++k)
                  {
                    const double *node = in + weights.node(k) * K::n_components;
                    const double  S    = weights.value(k);
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        v_grid[d] += S * node[K::velocity + d];
                        dv[d] += S * node[K::increment + d];
                      }
                  }
                Tensor<2, dim> C; // APIC: sum_i v_i (x) grad S_ip
                if constexpr (Family::allows_apic)
                  if (apic)
                    {
                      C = velocity_gradient<dim>(in, weights.stencil());
                      store_matrix<dim>(C, prop + c.affine);
                    }
                move_particle<dim>(
                  p, v_grid, dv, c.flip_fraction, apic, c.dt, error);
                // MUSL: the new particle momentum back to the nodes, with
                // the same weights
                if (momentum)
                  {
                    Point<dim> x_c;
                    if constexpr (Family::allows_apic)
                      if (apic)
                        x_c = stencil_centroid(weights.stencil(), c.grid);
                    for (unsigned int k = 0; k < weights.size(); ++k)
                      {
                        Tensor<1, dim> v;
                        for (unsigned int d = 0; d < dim; ++d)
                          v[d] = prop[L::velocity + d];
                        if constexpr (Family::allows_apic)
                          if (apic)
                            v +=
                              C * (c.grid.node_position(weights.node(k)) - x_c);
                        double *node = sum.slot(weights, k);
                        for (unsigned int d = 0; d < dim; ++d)
                          node[d] += weights.value(k) * prop[L::mass] * v[d];
                      }
                  }
              }
            if (momentum)
              sum.finish(weights, 0, dim);
          });
        weights.end_pass(error.empty());
        if (c.remap)
          {
            c.remap->compress(VectorOperation::add);
            if (c.active)
              c.active->record(*c.remap);
          }
        return error;
      }
    } // namespace

    template <int dim>
    std::string
    grid_to_particle(const G2PContext<dim> &c)
    {
      return shape_functions::with_family(shape_functions::family_of(c.domains),
                                          [&](const auto f) {
                                            return g2p_pass<decltype(f)>(c);
                                          });
    }

    template <int dim>
    std::string
    move_domain_corners(
      const BackgroundGrid<dim>                        &grid,
      Particles::ParticleHandler<dim>                  &particles,
      const NodalVector                                &kinematics,
      const double                                      dt,
      const shape_functions::DomainShapeFunctions<dim> &domains,
      const FieldSelection                             &only)
    {
      using K = KinematicsLayout<dim>;
      using Status =
        typename shape_functions::DomainShapeFunctions<dim>::Status;
      std::string error;
      for_each_cell_with_particles(
        grid, particles, [&](const auto &cell, const auto &pic) {
          for (auto &p : pic)
            {
              if (only.template skips<dim>(p.get_properties().data()))
                continue;
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

#define MPM_INSTANTIATE(d)                                         \
  template std::string grid_to_particle<d>(const G2PContext<d> &); \
  template std::string move_domain_corners<d>(                     \
    const BackgroundGrid<d> &,                                     \
    Particles::ParticleHandler<d> &,                               \
    const NodalVector &,                                           \
    double,                                                        \
    const shape_functions::DomainShapeFunctions<d> &,              \
    const FieldSelection &);
    MPM_INSTANTIATE(1)
    MPM_INSTANTIATE(2)
    MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
  } // namespace transfer
} // namespace mpm
