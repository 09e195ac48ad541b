#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/remedies/cell_pressure_force.h>
#include <mpm/remedies/stress_filter.h>
#include <mpm/shape_functions/family_registry.h>
#include <mpm/transfer/integrated_field_force.h>
#include <mpm/transfer/nodal_sum.h>
#include <mpm/transfer/own_stress.h>
#include <mpm/transfer/particle_to_grid.h>
#include <mpm/transfer/projected_stress_force.h>
#include <mpm/transfer/velocity_gradient.h>

#include <type_traits>

namespace mpm
{
  namespace transfer
  {
    using namespace dealii;

    namespace
    {
      /**
       * The P2G pass of family @p Family with the stresses of @p Stresses
       * (OwnStress, or the family's filtered force): per cell, the
       * family's weights of each particle, summed into the nodes as the
       * family asks (NodalSum). Compiled per family: no family branch in
       * the loop.
       */
      template <typename Family, int dim, typename Stresses>
      std::string
      p2g_pass(const P2GContext<dim> &c, Stresses &stresses)
      {
        using L       = ParticleLayout<dim>;
        using P       = P2GLayout<dim>;
        using Weights = typename Family::template Weights<dim>;
        using Sum     = NodalSum<Family, dim, P::n_components>;
        const P2GPass<dim> pass(c.content);
        const bool         do_mass     = pass.mass;
        const bool         do_momentum = pass.momentum;
        const bool         do_force    = pass.force;
        // the components of the node's values this pass adds
        const unsigned int first = do_mass ? P::mass : P::force;
        const unsigned int last  = do_force ? P::n_components : P::force;

        std::vector<char> body_loaded(c.bodies.size());
        for (unsigned int b = 0; b < c.bodies.size(); ++b)
          body_loaded[b] = c.bodies[b].has_body_force();

        // The USF force pass adds to the mass and momentum of the first
        // pass (whose ghost entries compress() has already zeroed).
        if (c.content != P2GContent::force)
          {
            if (c.active)
              {
                c.active->clear_marks();
                c.active->zero(c.nodal, P::n_components);
              }
            else
              c.nodal = 0.;
          }
        double *const        out   = c.nodal.begin();
        unsigned char *const marks = c.active ? c.active->marks() : nullptr;
        std::string          error;
        Weights              weights(c.grid, c.domains);
        // a fluid's cell pressure acts over its cell
        remedies::CellPressureForce<dim> cell_pressure(c.bodies);
        const bool over_cell = do_force && cell_pressure.any();

        weights.begin_pass(c.particles.n_locally_owned_particles());
        for_each_cell_with_particles(
          c.grid, c.particles, [&](const auto &cell, const auto &pic) {
            stresses.begin_cell(cell, pic);
            weights.begin_cell(cell);
            if (over_cell)
              cell_pressure.begin_cell(c.grid.geometry(cell));
            Sum sum(out, P::n_components, marks);
            for (const auto &p : pic)
              {
                const double *prop = p.get_properties().data();
                if (c.only.template skips<dim>(prop) ||
                    !weights.evaluate(p, do_force, error))
                  continue;
                const double   m = prop[L::mass];
                Tensor<2, dim> sigma; // -V_p sigma_p
                double         ext[dim] = {}, traction[dim];
                Tensor<1, dim> d_face;
                bool           loaded_face = false;
                if (do_force)
                  {
                    const unsigned int b =
                      static_cast<unsigned int>(prop[L::body]);
                    const Body<dim> &body = c.bodies[b];
                    sigma = stresses.weighted_stress(p, prop, b);
                    if (over_cell)
                      cell_pressure.take_pressure(b, sigma);
                    body.body_force_on(p.get_location(),
                                       prop + L::X,
                                       m,
                                       c.time,
                                       body_loaded[b],
                                       ext);
                    loaded_face = body.has_traction() &&
                                  body.traction_force_on(p.get_location(),
                                                         prop,
                                                         c.time,
                                                         traction,
                                                         d_face);
                  }
                // APIC: the affine velocity C_p, about the domain's
                // centroid sum_i S_ip x_i, so that sum_i S_ip C (x_i -
                // x_c) = 0 and momentum is kept (CPDI2's centroid is not
                // its particle position)
                Tensor<2, dim> C;
                Point<dim>     x_c;
                if constexpr (Family::allows_apic)
                  if (c.affine && do_momentum)
                    {
                      C   = load_matrix<dim>(prop + c.affine);
                      x_c = stencil_centroid(weights.stencil(), c.grid);
                    }
                Tensor<1, dim> v_p;
                if (do_momentum)
                  for (unsigned int d = 0; d < dim; ++d)
                    v_p[d] = prop[L::velocity + d];
                const auto add_mass = [&](double *node, const unsigned int k) {
                  node[P::mass] += weights.value(k) * m;
                };
                const auto add_momentum = [&](double            *node,
                                              const unsigned int k) {
                  const double   w = weights.value(k) * m;
                  Tensor<1, dim> v = v_p;
                  if constexpr (Family::allows_apic)
                    if (c.affine)
                      v += C * (c.grid.node_position(weights.node(k)) - x_c);
                  for (unsigned int d = 0; d < dim; ++d)
                    node[P::momentum + d] += w * v[d];
                };
                const auto add_force = [&](double *node, const unsigned int k) {
                  const double         S = weights.value(k);
                  const Tensor<1, dim> f = sigma * weights.gradient(k);
                  for (unsigned int d = 0; d < dim; ++d)
                    node[P::force + d] += f[d] + S * ext[d];
                };
                if constexpr (Weights::summation ==
                              shape_functions::NodalSummation::per_cell)
                  {
                    // The cell's buffer: one loop per content, with no
                    // branch inside.
                    const unsigned int n = weights.size();
                    if (do_mass)
                      for (unsigned int k = 0; k < n; ++k)
                        add_mass(sum.slot(weights, k), k);
                    if (do_momentum)
                      for (unsigned int k = 0; k < n; ++k)
                        add_momentum(sum.slot(weights, k), k);
                    if (do_force)
                      for (unsigned int k = 0; k < n; ++k)
                        add_force(sum.slot(weights, k), k);
                  }
                else
                  // straight into the nodes: each node's address once
                  for (unsigned int k = 0; k < weights.size(); ++k)
                    {
                      double *node = sum.slot(weights, k);
                      if (do_mass)
                        add_mass(node, k);
                      if (do_momentum)
                        add_momentum(node, k);
                      if (do_force)
                        add_force(node, k);
                    }
                // The traction acts on the loaded face at x_p + d_face.
                if (loaded_face)
                  {
                    double S_face[Weights::n_entries];
                    weights.face_values(d_face, S_face);
                    for (unsigned int k = 0; k < weights.size(); ++k)
                      {
                        double *node = sum.slot(weights, k);
                        for (unsigned int d = 0; d < dim; ++d)
                          node[P::force + d] += S_face[k] * traction[d];
                      }
                  }
              }
            stresses.finish_cell(cell, pic, sum, weights);
            sum.finish(weights, first, last);
            if (over_cell)
              {
                cell_pressure.add_to_nodes(c.grid.nodes(cell),
                                           out,
                                           P::n_components,
                                           P::force);
                if (marks)
                  for (unsigned int v = 0; v < BackgroundGrid<dim>::n_vertices;
                       ++v)
                    marks[c.grid.nodes(cell)[v]] = 1;
              }
          });
        weights.end_pass(error.empty());
        c.nodal.compress(VectorOperation::add);
        if (c.active)
          {
            c.active->collect();
            c.active->record(c.nodal);
          }
        return error;
      }

      /// The family's way of including the assumed-stress filter.
      template <typename Family, int dim>
      using FilteredStresses =
        std::conditional_t<Family::template Weights<dim>::filtered_force ==
                             shape_functions::FilteredForce::integrated_field,
                           IntegratedFieldForce<dim>,
                           ProjectedStressForce<dim>>;
    } // namespace

    template <int dim>
    std::string
    particle_to_grid(const P2GContext<dim> &c)
    {
      // no filter in 1D; a pass without forces needs no stresses
      const bool filtering =
        dim > 1 && c.content != P2GContent::mass_momentum && c.filter.any();
      return shape_functions::with_family(
        shape_functions::family_of(c.domains), [&](const auto f) {
          using Family = decltype(f);
          if constexpr (dim > 1)
            if (filtering)
              {
                FilteredStresses<Family, dim> stresses(c);
                return p2g_pass<Family>(c, stresses);
              }
          OwnStress<dim> stresses;
          return p2g_pass<Family>(c, stresses);
        });
    }

    template <int dim>
    std::string
    particle_to_grid(const BackgroundGrid<dim>       &grid,
                     Particles::ParticleHandler<dim> &particles,
                     const std::vector<Body<dim>>    &bodies,
                     const double                     time,
                     const P2GContent                 content,
                     NodalVector                     &nodal,
                     remedies::StressFilter<dim>     *filter,
                     const shape_functions::DomainShapeFunctions<dim> *domains,
                     const unsigned int                                affine)
    {
      // of no body: filters nothing
      static const std::vector<Body<dim>> no_bodies;
      remedies::StressFilter<dim>         no_filter(no_bodies);
      return particle_to_grid(
        P2GContext<dim>{{grid, particles, domains, affine},
                        bodies,
                        filter ? *filter : no_filter,
                        time,
                        content,
                        nodal});
    }

#define MPM_INSTANTIATE(d)                                         \
  template std::string particle_to_grid<d>(const P2GContext<d> &); \
  template std::string particle_to_grid<d>(                        \
    const BackgroundGrid<d> &,                                     \
    Particles::ParticleHandler<d> &,                               \
    const std::vector<Body<d>> &,                                  \
    double,                                                        \
    P2GContent,                                                    \
    NodalVector &,                                                 \
    remedies::StressFilter<d> *,                                   \
    const shape_functions::DomainShapeFunctions<d> *,              \
    unsigned int);
    MPM_INSTANTIATE(1)
    MPM_INSTANTIATE(2)
    MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
  } // namespace transfer
} // namespace mpm
