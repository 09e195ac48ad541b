#include <mpm/remedies/stress_filter.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/transfer/particle_to_grid.h>
#include <mpm/transfer/velocity_gradient.h>

namespace mpm
{
  namespace transfer
  {
    using namespace dealii;

    template <int dim>
    std::string
    particle_to_grid_domains(
      const BackgroundGrid<dim>                        &grid,
      Particles::ParticleHandler<dim>                  &particles,
      const std::vector<Body<dim>>                     &bodies,
      const double                                      time,
      const P2GContent                                  content,
      NodalVector                                      &nodal,
      remedies::StressFilter<dim>                       *filter,
      const shape_functions::DomainShapeFunctions<dim> &domains,
      const unsigned int                                affine)
    {
      using L = ParticleLayout<dim>;
      const P2GPass<dim> pass(content);
      const unsigned int nc          = pass.n_components;
      const unsigned int off_p       = pass.momentum_offset;
      const unsigned int off_f       = pass.force_offset;
      const bool         do_mass     = pass.mass;
      const bool         do_momentum = pass.momentum;
      const bool         do_force    = pass.force;
      const bool filtering = dim > 1 && do_force && filter && filter->any();

      std::vector<char> body_loaded(bodies.size()), present(bodies.size());
      for (unsigned int b = 0; b < bodies.size(); ++b)
        body_loaded[b] = bodies[b].has_body_force();

      if (content != P2GContent::force)
        nodal = 0.;
      double *const out = nodal.begin();
      std::string   error;
      Point<dim>    centre;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = 0.5;
      shape_functions::Stencil<dim> st;
      // Filtered stress = force only: per body, whether this cell's
      // projected field (filter->cartesian_field) gives its stresses.
      std::vector<char> by_field(bodies.size(), 0);

      domains.begin_pass(particles.n_locally_owned_particles());
      for_each_cell_with_particles(
        grid, particles, [&](const auto &cell, const auto &pic) {
          if constexpr (dim > 1)
            if (filtering)
              {
                // Project the filtered bodies' stresses of this cell first;
                // the force below then uses the projected stresses.
                std::fill(present.begin(), present.end(), 0);
                for (const auto &p : pic)
                  present[static_cast<unsigned int>(
                    p.get_properties()[L::body])] = 1;
                const Tensor<2, dim> J0 = grid.geometry(cell).jacobian(centre);
                double               beta[remedies::StressFilter<dim>::n_beta];
                for (unsigned int b = 0; b < bodies.size(); ++b)
                  by_field[b] =
                    present[b] && filter->filtered(b) &&
                    filter->filter_cell(J0, pic, b, beta) !=
                      remedies::StressFilter<dim>::Result::unchanged &&
                    !filter->writes_back(b);
              }
          const unsigned int index   = cell->active_cell_index();
          unsigned int       ordinal = 0;
          for (const auto &p : pic)
            {
              const double *prop = p.get_properties().data();
              if (!domains.evaluate(index, ordinal++, p, st, error))
                continue;
              const double   m = prop[L::mass];
              Tensor<2, dim> sigma;
              double         ext[dim] = {}, traction[dim];
              Tensor<1, dim> d_face;
              bool           loaded_face = false;
              if (do_force)
                {
                  const unsigned int b =
                    static_cast<unsigned int>(prop[L::body]);
                  sigma = in_plane_stress<dim>(prop + L::stress);
                  if constexpr (dim > 1)
                    if (by_field[b])
                      sigma = filter->cartesian_field(b).value(
                        p.get_reference_location());
                  sigma *= -prop[L::volume];
                  bodies[b].body_force_on(p.get_location(),
                                          prop + L::X,
                                          m,
                                          time,
                                          body_loaded[b],
                                          ext);
                  loaded_face = bodies[b].has_traction() &&
                                bodies[b].traction_force_on(p.get_location(),
                                                            prop,
                                                            time,
                                                            traction,
                                                            d_face);
                }
              // APIC: the affine velocity C_p
              Tensor<2, dim> C;
              Point<dim>     x_p;
              if (affine && do_momentum)
                {
                  // about the domain's centroid sum_i S_ip x_i, so that
                  // sum_i S_ip C (x_i - x_p) = 0 and momentum is kept
                  // (CPDI2's centroid is not its particle position)
                  C   = load_matrix<dim>(prop + affine);
                  x_p = stencil_centroid(st, grid);
                }
              for (unsigned int k = 0; k < st.n; ++k)
                {
                  double      *node = out + st.node[k] * nc;
                  const double S    = st.value[k];
                  if (do_mass)
                    node[0] += S * m;
                  if (do_momentum)
                    {
                      Tensor<1, dim> v;
                      for (unsigned int d = 0; d < dim; ++d)
                        v[d] = prop[L::velocity + d];
                      if (affine)
                        v += C * (grid.node_position(st.node[k]) - x_p);
                      for (unsigned int d = 0; d < dim; ++d)
                        node[off_p + d] += S * m * v[d];
                    }
                  if (do_force)
                    {
                      const Tensor<1, dim> f = sigma * st.gradient[k];
                      for (unsigned int d = 0; d < dim; ++d)
                        node[off_f + d] += f[d] + S * ext[d];
                    }
                }
              // The traction acts on the face at x_p + d_face:
              // sum_k (S_k + grad S_k . d) x_k = x_p + d.
              if (loaded_face)
                for (unsigned int k = 0; k < st.n; ++k)
                  {
                    double      *node   = out + st.node[k] * nc;
                    const double S_face = st.value[k] + st.gradient[k] * d_face;
                    for (unsigned int d = 0; d < dim; ++d)
                      node[off_f + d] += S_face * traction[d];
                  }
            }
        });
      domains.end_pass(error.empty());
      nodal.compress(VectorOperation::add);
      return error;
    }

#define MPM_INSTANTIATE(d)                            \
  template std::string particle_to_grid_domains<d>(   \
    const BackgroundGrid<d> &,                        \
    Particles::ParticleHandler<d> &,                  \
    const std::vector<Body<d>> &,                     \
    double,                                           \
    P2GContent,                                       \
    NodalVector &,                                    \
    remedies::StressFilter<d> *,                       \
    const shape_functions::DomainShapeFunctions<d> &, \
    unsigned int);
    MPM_INSTANTIATE(1)
    MPM_INSTANTIATE(2)
    MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
  } // namespace transfer
} // namespace mpm
