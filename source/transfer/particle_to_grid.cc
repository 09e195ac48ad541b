#include <mpm/remedies/assumed_stress.h>
#include <mpm/remedies/assumed_stress_force.h>
#include <mpm/remedies/stress_filter.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/transfer/particle_to_grid.h>

#include <algorithm>
#include <memory>
#include <type_traits>

namespace mpm
{
  namespace transfer
  {
    using namespace dealii;

    namespace
    {
      /// Half-vectors of the current particle domain, F r_i (columns).
      template <int dim>
      inline Tensor<2, dim>
      current_domain(const double *prop)
      {
        using L = ParticleLayout<dim>;
        return load_matrix<dim>(prop + L::F) *
               load_matrix<dim>(prop + L::domain);
      }
    } // namespace

    template <int dim>
    std::string
    particle_to_grid(const BackgroundGrid<dim>       &grid,
                     Particles::ParticleHandler<dim> &particles,
                     const std::vector<Body<dim>>    &bodies,
                     const double                     time,
                     const P2GContent                 content,
                     NodalVector                     &nodal,
                     remedies::StressFilter<dim>      *filter,
                     const shape_functions::DomainShapeFunctions<dim> *domains,
                     const unsigned int                                affine)
    {
      if (domains)
        return particle_to_grid_domains(grid,
                                        particles,
                                        bodies,
                                        time,
                                        content,
                                        nodal,
                                        filter,
                                        *domains,
                                        affine);
      // APIC needs a domain family (refused at set-up otherwise)
      Assert(affine == 0, ExcInternalError());
      using L                   = ParticleLayout<dim>;
      constexpr unsigned int nv = shape_functions::n_q1<dim>;
      const P2GPass<dim>     pass(content);
      const unsigned int     nc          = pass.n_components;
      const unsigned int     off_m       = 0;
      const unsigned int     off_p       = pass.momentum_offset;
      const unsigned int     off_f       = pass.force_offset;
      const bool             do_mass     = pass.mass;
      const bool             do_momentum = pass.momentum;
      const bool             do_force    = pass.force;

      std::vector<char> body_loaded(bodies.size());
      for (unsigned int b = 0; b < bodies.size(); ++b)
        body_loaded[b] = bodies[b].has_body_force();

      // The USF force pass adds to the mass and momentum of the first pass
      // (whose ghost entries compress() has already zeroed).
      if (content != P2GContent::force)
        nodal = 0.;
      double *const out = nodal.begin();

      // Filtered bodies: the force of their cell's assumed-stress field,
      // integrated over the particle domains (AssumedStressForce).
      constexpr bool has_filter = dim > 1;
      constexpr int  fdim       = dim == 1 ? 2 : dim; // no filter in 1D
      using Force               = remedies::AssumedStressForce<fdim>;
      const bool filtering = has_filter && do_force && filter && filter->any();
      std::vector<Force>        field_force(filtering ? bodies.size() : 0);
      std::vector<unsigned int> force_bodies;
      std::vector<unsigned int> cell_count(filtering ? bodies.size() : 0);
      std::vector<double>       cell_volume(filtering ? bodies.size() : 0);
      std::vector<char> domain_integration(filtering ? bodies.size() : 0);
      Tensor<2, dim>    J0_inverse;
      Point<dim>        centre;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = 0.5;

      double         N[nv];
      Tensor<1, dim> G[nv];
      // The cell body, compiled twice: without the filter it is the plain
      // particle sum (no filter branches in the hot loop).
      auto cell_body = [&](const auto  filtering_tag,
                           const auto &cell,
                           const auto &pic) {
        constexpr bool      with_filter = decltype(filtering_tag)::value;
        const auto         &geo         = grid.geometry(cell);
        const unsigned int *nodes       = grid.nodes(cell);
        Tensor<2, dim>      J0; // filtering: the Jacobian at the centre
        if constexpr (has_filter && with_filter)
          {
            J0         = geo.jacobian(centre);
            J0_inverse = invert(J0);
            // Which filtered bodies fill this cell (AssumedStressForce::
            // fills): count and volume first, while the particles come
            // into cache.
            std::fill(cell_count.begin(), cell_count.end(), 0u);
            std::fill(cell_volume.begin(), cell_volume.end(), 0.);
            for (const auto &p : pic)
              {
                const double      *prop = p.get_properties().data();
                const unsigned int b = static_cast<unsigned int>(prop[L::body]);
                ++cell_count[b];
                cell_volume[b] += prop[L::volume];
              }
            const double volume_of_cell = std::abs(determinant(J0));
            for (unsigned int b = 0; b < bodies.size(); ++b)
              domain_integration[b] =
                Force::fills(cell_count[b], cell_volume[b], volume_of_cell);
            filter->begin_cell(J0);
          }

        // Accumulate per cell, then scatter once.
        double local[nv][1 + 2 * dim] = {};
        for (const auto &p : pic)
          {
            const Point<dim> xi   = p.get_reference_location();
            const double    *prop = p.get_properties().data();
            const double     m    = prop[L::mass];
            if (do_force)
              geo.values_and_gradients(xi, N, G);
            else
              geo.values(xi, N);

            if (do_force)
              {
                const unsigned int b = static_cast<unsigned int>(prop[L::body]);
                const double       V = prop[L::volume];

                // Stress: the particle's own (midpoint rule), or its
                // share of the cell's filtered field.
                bool by_field = false;
                if constexpr (has_filter && with_filter)
                  if (filter->filtered(b))
                    {
                      if (field_force[b].empty())
                        force_bodies.push_back(b);
                      field_force[b].add_particle(
                        xi,
                        domain_integration[b] ?
                          Tensor<2, dim>(J0_inverse *
                                         current_domain<dim>(prop)) :
                          Tensor<2, dim>(),
                        V);
                      filter->add_particle(b, xi, prop);
                      by_field = true;
                    }
                Tensor<2, dim> sigma;
                if (!by_field)
                  sigma = -V * in_plane_stress<dim>(prop + L::stress);

                double ext[dim], traction[dim];
                bodies[b].body_force_on(
                  p.get_location(), prop + L::X, m, time, body_loaded[b], ext);
                for (unsigned int v = 0; v < nv; ++v)
                  {
                    const Tensor<1, dim> f = sigma * G[v];
                    for (unsigned int d = 0; d < dim; ++d)
                      local[v][1 + dim + d] += f[d] + N[v] * ext[d];
                  }
                // The traction acts on the loaded face at x_p + d_face;
                // a face that has left the particle's cell acts at the
                // nearest point of the cell, the last one whose nodes the
                // body reaches.
                Tensor<1, dim> d_face;
                if (bodies[b].has_traction() &&
                    bodies[b].traction_force_on(
                      p.get_location(), prop, time, traction, d_face))
                  {
                    Point<dim> xi_face =
                      xi + Point<dim>(invert(geo.jacobian(xi)) * d_face);
                    for (unsigned int d = 0; d < dim; ++d)
                      xi_face[d] = std::clamp(xi_face[d], 0., 1.);
                    double N_face[nv];
                    geo.values(xi_face, N_face);
                    for (unsigned int v = 0; v < nv; ++v)
                      for (unsigned int d = 0; d < dim; ++d)
                        local[v][1 + dim + d] += N_face[v] * traction[d];
                  }
              }
            if (do_momentum)
              for (unsigned int v = 0; v < nv; ++v)
                {
                  const double w = N[v] * m;
                  local[v][0] += w;
                  for (unsigned int d = 0; d < dim; ++d)
                    local[v][1 + d] += w * prop[L::velocity + d];
                }
          }

        // Filtered bodies: solve their projections in this cell (which
        // writes the projected stresses back), then the force of the
        // projected field.
        if constexpr (has_filter && with_filter)
          for (const unsigned int b : force_bodies)
            {
              double
                beta[remedies::AssumedStressProjection<3>::n_beta]; // the
                                                                   // largest
              double     f[nv * dim] = {};
              const auto result      = filter->finish_cell(pic, b, beta);
              if (result != remedies::StressFilter<dim>::Result::unchanged)
                field_force[b].add_internal_force(geo,
                                                  filter->projection(b),
                                                  beta,
                                                  filter->cartesian_field(b),
                                                  f);
              else
                // nothing to project onto: the particles' own stresses
                for (const auto &p : pic)
                  {
                    const double *prop = p.get_properties().data();
                    if (static_cast<unsigned int>(prop[L::body]) != b)
                      continue;
                    geo.values_and_gradients(p.get_reference_location(), N, G);
                    const Tensor<2, dim> sigma =
                      -prop[L::volume] * in_plane_stress<dim>(prop + L::stress);
                    for (unsigned int v = 0; v < nv; ++v)
                      {
                        const Tensor<1, dim> fv = sigma * G[v];
                        for (unsigned int d = 0; d < dim; ++d)
                          f[v * dim + d] += fv[d];
                      }
                  }
              for (unsigned int v = 0; v < nv; ++v)
                for (unsigned int d = 0; d < dim; ++d)
                  local[v][1 + dim + d] += f[v * dim + d];
              field_force[b].clear();
            }
        if constexpr (with_filter)
          force_bodies.clear();

        for (unsigned int v = 0; v < nv; ++v)
          {
            double *node = out + nodes[v] * nc;
            if (do_mass)
              node[off_m] += local[v][0];
            if (do_momentum)
              for (unsigned int d = 0; d < dim; ++d)
                node[off_p + d] += local[v][1 + d];
            if (do_force)
              for (unsigned int d = 0; d < dim; ++d)
                node[off_f + d] += local[v][1 + dim + d];
          }
      };
      if (filtering)
        for_each_cell_with_particles(grid,
                                     particles,
                                     [&](const auto &cell, const auto &pic) {
                                       cell_body(std::true_type(), cell, pic);
                                     });
      else
        for_each_cell_with_particles(grid,
                                     particles,
                                     [&](const auto &cell, const auto &pic) {
                                       cell_body(std::false_type(), cell, pic);
                                     });
      nodal.compress(VectorOperation::add);
      return {};
    }

    template std::string
    particle_to_grid<1>(const BackgroundGrid<1> &,
                        Particles::ParticleHandler<1> &,
                        const std::vector<Body<1>> &,
                        double,
                        P2GContent,
                        NodalVector &,
                        remedies::StressFilter<1> *,
                        const shape_functions::DomainShapeFunctions<1> *,
                        unsigned int);
    template std::string
    particle_to_grid<2>(const BackgroundGrid<2> &,
                        Particles::ParticleHandler<2> &,
                        const std::vector<Body<2>> &,
                        double,
                        P2GContent,
                        NodalVector &,
                        remedies::StressFilter<2> *,
                        const shape_functions::DomainShapeFunctions<2> *,
                        unsigned int);
    template std::string
    particle_to_grid<3>(const BackgroundGrid<3> &,
                        Particles::ParticleHandler<3> &,
                        const std::vector<Body<3>> &,
                        double,
                        P2GContent,
                        NodalVector &,
                        remedies::StressFilter<3> *,
                        const shape_functions::DomainShapeFunctions<3> *,
                        unsigned int);
  } // namespace transfer
} // namespace mpm
