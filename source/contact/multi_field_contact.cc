#include <deal.II/base/mpi.h>

#include <mpm/contact/multi_field_contact.h>
#include <mpm/grid/nodal_layout.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/remedies/convection_correction_remedy.h>
#include <mpm/utilities/input_error.h>

#include <cmath>
#include <map>
#include <sstream>

namespace mpm
{
  namespace contact
  {
    using namespace dealii;

    namespace
    {
      /// Each body's field, numbered 0, 1, ... in the order bodies name
      /// them, from the bodies' Contact field numbers @p given; -1 is a
      /// field of the body's own.
      std::vector<unsigned char>
      number_fields(const std::vector<int> &given)
      {
        std::map<int, unsigned char> number;
        std::vector<unsigned char>   field(given.size());
        unsigned char                next = 0;
        for (unsigned int b = 0; b < given.size(); ++b)
          if (given[b] < 0)
            field[b] = next++;
          else
            {
              const auto found = number.find(given[b]);
              field[b]         = found != number.end() ? found->second :
                                                         (number[given[b]] = next++);
            }
        return field;
      }

      /// A body's parameters, from the parameter file's or the
      /// simulation's list of bodies.
      template <int dim>
      const Parameters::Body<dim> &
      parameters_of(const Parameters::Body<dim> &body)
      {
        return body;
      }

      template <int dim>
      const Parameters::Body<dim> &
      parameters_of(const Body<dim> &body)
      {
        return body.prm;
      }

      /// The Contact field numbers of the @p bodies.
      template <typename BodyList>
      std::vector<int>
      given_fields(const BodyList &bodies)
      {
        std::vector<int> given;
        for (const auto &body : bodies)
          given.push_back(parameters_of(body).contact_field);
        return given;
      }
    } // namespace

    template <int dim>
    MultiFieldContact<dim>::MultiFieldContact(
      const Parameters::Contact    &law,
      const std::vector<Body<dim>> &bodies)
      : law(law)
      , field_of_body(number_fields(given_fields(bodies)))
    {
      for (const unsigned char f : field_of_body)
        n = std::max(n, f + 1u);
      fields.resize(n);
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (bodies[b].is_rigid())
          {
            Field &field       = fields[field_of_body[b]];
            field.rigid_body   = static_cast<int>(b);
            const auto &n      = bodies[b].prm.contact_normal;
            field.given_normal = !n.empty();
            for (unsigned int d = 0; d < n.size(); ++d)
              field.normal[d] = n[d];
          }
    }

    template <int dim>
    void
    MultiFieldContact<dim>::initialize_vectors(const BackgroundGrid<dim> &grid)
    {
      for (auto &field : fields)
        {
          grid.initialize_vector(field.p2g, P2GLayout<dim>::n_components);
          grid.initialize_vector(field.kinematics,
                                 KinematicsLayout<dim>::n_components);
          grid.initialize_vector(field.remap, dim);
          grid.initialize_vector(field.mass_gradient, dim);
          if (law.gap_check)
            grid.initialize_vector(field.centroid, centroid_components);
        }
      in_contact.clear();
      // node numbers of the old partition
      nodal_forces.clear();
    }

    template <int dim>
    void
    MultiFieldContact<dim>::compute_mass_gradients(
      const BackgroundGrid<dim>       &grid,
      Particles::ParticleHandler<dim> &particles)
    {
      using L                          = ParticleLayout<dim>;
      constexpr unsigned int nv        = shape_functions::n_q1<dim>;
      constexpr unsigned int nc        = centroid_components;
      const bool             gap_check = law.gap_check;
      std::vector<double *>  out(n), moment(n);
      for (unsigned int f = 0; f < n; ++f)
        {
          fields[f].mass_gradient = 0.;
          out[f]                  = fields[f].mass_gradient.begin();
          if (gap_check)
            {
              fields[f].centroid = 0.;
              moment[f]          = fields[f].centroid.begin();
            }
        }
      Tensor<1, dim> G[nv];
      double         N[nv];
      for_each_cell_with_particles(
        grid, particles, [&](const auto &cell, const auto &pic) {
          const auto         &geo    = grid.geometry(cell);
          const unsigned int *nodes  = grid.nodes(cell);
          const double        height = grid.cell_height(cell);
          for (const auto &p : pic)
            {
              const double      *prop = p.get_properties().data();
              const unsigned int f =
                field_of_body[static_cast<unsigned int>(prop[L::body])];
              double *const g = out[f];
              geo.gradients(p.get_reference_location(), G);
              for (unsigned int v = 0; v < nv; ++v)
                for (unsigned int d = 0; d < dim; ++d)
                  g[nodes[v] * dim + d] += prop[L::mass] * G[v][d];
              if (!gap_check)
                continue;
              geo.values(p.get_reference_location(), N);
              const Point<dim> &x = p.get_location();
              const double size = std::pow(prop[L::volume], 1. / dim) / height;
              for (unsigned int v = 0; v < nv; ++v)
                {
                  double *const c = moment[f] + nodes[v] * nc;
                  const double  w = prop[L::mass] * N[v];
                  for (unsigned int d = 0; d < dim; ++d)
                    c[d] += w * x[d];
                  c[centroid_mass] += w;
                  c[centroid_height] += w * height;
                  c[centroid_size] += w * size * size;
                }
            }
        });
      for (auto &field : fields)
        {
          field.mass_gradient.compress(VectorOperation::add);
          if (gap_check)
            field.centroid.compress(VectorOperation::add);
        }
    }

    template <int dim>
    double
    MultiFieldContact<dim>::set_centroids(const unsigned int  i,
                                          FieldAtNode<dim>   *at_node,
                                          const unsigned int *present,
                                          const unsigned int  count) const
    {
      double mass = 0, height = 0;
      for (unsigned int a = 0; a < count; ++a)
        {
          const double *c =
            fields[present[a]].centroid.begin() + i * centroid_components;
          for (unsigned int d = 0; d < dim; ++d)
            at_node[a].centroid[d] = c[d] / c[centroid_mass];
          at_node[a].surface_offset =
            c[centroid_height] / c[centroid_mass] *
            centroid_offset(c[centroid_size] / c[centroid_mass]);
          mass += c[centroid_mass];
          height += c[centroid_height];
        }
      return height / mass;
    }

    template <int dim>
    std::string
    MultiFieldContact<dim>::resolve(const BackgroundGrid<dim>    &grid,
                                    const std::vector<Body<dim>> &bodies,
                                    const double                  min_mass,
                                    const Phase                   phase,
                                    const double                  t,
                                    const double                  t_old,
                                    const double                  kick)
    {
      using P                   = P2GLayout<dim>;
      using K                   = KinematicsLayout<dim>;
      const bool with_increment = phase == Phase::grid_update;
      // the rigid fields' velocities at t, and their change since t_old
      std::vector<Tensor<1, dim>> rigid_velocity(n), rigid_change(n);
      for (unsigned int f = 0; f < n; ++f)
        if (fields[f].rigid_body >= 0)
          {
            const auto &motion =
              bodies[fields[f].rigid_body].prescribed_velocity;
            double now[dim], before[dim];
            motion.value(Point<dim>(), t, now);
            motion.value(Point<dim>(), t_old, before);
            for (unsigned int d = 0; d < dim; ++d)
              {
                rigid_velocity[f][d] = now[d];
                rigid_change[f][d]   = now[d] - before[d];
              }
          }

      std::string                   error;
      std::vector<FieldAtNode<dim>> at_node(n);
      std::vector<unsigned int>     present(n);
      std::vector<Tensor<1, dim>>   uncorrected(n);
      unsigned long                 active = 0;
      // the stress update's velocities keep contact where the motion has
      // it (Phase)
      const bool hold_all  = phase == Phase::start_of_step;
      const bool hold      = phase == Phase::remap;
      const bool gap_check = law.gap_check;
      if (with_increment)
        {
          in_contact.assign(grid.n_owned_nodes(), 0);
          nodal_forces.clear();
        }
      for (unsigned int i = 0; i < grid.n_owned_nodes(); ++i)
        {
          unsigned int count = 0;
          for (unsigned int f = 0; f < n; ++f)
            {
              Field       &field = fields[f];
              const double m =
                field.p2g.local_element(i * P::n_components + P::mass);
              if (!(m > min_mass))
                continue;
              double *k = field.kinematics.begin() + i * K::n_components;
              if (field.rigid_body >= 0)
                {
                  double v[dim], dv[dim];
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      v[d]  = rigid_velocity[f][d];
                      dv[d] = rigid_change[f][d];
                    }
                  grid.constrain(i, v);
                  grid.constrain(i, dv);
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      k[K::velocity + d] = v[d];
                      if (with_increment)
                        k[K::increment + d] = dv[d];
                    }
                }
              FieldAtNode<dim> &a = at_node[count];
              a.mass              = m;
              a.rigid             = field.rigid_body >= 0;
              a.apart             = false;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  a.velocity[d] = k[K::velocity + d];
                  a.mass_gradient[d] =
                    field.mass_gradient.local_element(i * dim + d);
                }
              // a flat obstacle's own normal: its mass gradient's direction
              if (field.given_normal)
                a.mass_gradient = field.normal;
              // along a wall the bodies end at the wall, which is no
              // surface between them: the normal lies in the wall
              grid.constrain(i, a.mass_gradient.begin_raw());
              present[count++] = f;
            }
          if (count < 2)
            continue;
          for (unsigned int a = 0; a < count; ++a)
            uncorrected[a] = at_node[a].velocity;
          set_contact_normals(at_node.data(), count);
          if (gap_check &&
              mark_fields_apart(
                at_node.data(),
                count,
                law.gap_tolerance *
                  set_centroids(i, at_node.data(), present.data(), count)) < 2)
            continue;
          if (!resolve_contact(law,
                               at_node.data(),
                               count,
                               hold_all || (hold && in_contact.size() > i &&
                                            in_contact[i])))
            continue;
          ++active;
          if (with_increment)
            in_contact[i] = 1;
          // the force is the momentum change of the first deformable field
          // (fields in number order) not found apart: between two fields the
          // one force they exchange, with a sign that does not depend on
          // round-off
          Tensor<1, dim> impulse;
          bool           recorded = false;
          for (unsigned int a = 0; a < count; ++a)
            {
              if (at_node[a].rigid)
                continue;
              double *k =
                fields[present[a]].kinematics.begin() + i * K::n_components;
              double v[dim], change[dim];
              for (unsigned int d = 0; d < dim; ++d)
                {
                  v[d]      = at_node[a].velocity[d];
                  change[d] = v[d] - uncorrected[a][d];
                }
              // a wall's constraint wins over the contact
              grid.constrain(i, v);
              grid.constrain(i, change);
              if (!recorded && !at_node[a].apart)
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    impulse[d] = at_node[a].mass * change[d];
                  recorded = true;
                }
              for (unsigned int d = 0; d < dim; ++d)
                {
                  k[K::velocity + d] = v[d];
                  if (with_increment)
                    k[K::increment + d] += change[d];
                  if (!std::isfinite(v[d]) && error.empty())
                    {
                      std::ostringstream s;
                      s << "non-finite nodal velocity after contact at the "
                           "grid node at ("
                        << grid.node_position(i) << ")";
                      error = s.str();
                    }
                }
            }
          if (with_increment && kick > 0)
            nodal_forces.push_back({i, grid.node_position(i), impulse / kick});
        }
      if (with_increment)
        contact_nodes = active;
      for (auto &field : fields)
        field.kinematics.update_ghost_values();
      return error;
    }

    template <int dim>
    void
    MultiFieldContact<dim>::combine(const BackgroundGrid<dim> &grid,
                                    NodalVector               &p2g,
                                    NodalVector               &kinematics)
    {
      using P = P2GLayout<dim>;
      using K = KinematicsLayout<dim>;
      for (unsigned int i = 0; i < grid.n_owned_nodes(); ++i)
        {
          double *sum = p2g.begin() + i * P::n_components;
          double *cm  = kinematics.begin() + i * K::n_components;
          for (unsigned int c = 0; c < P::n_components; ++c)
            sum[c] = 0;
          for (unsigned int c = 0; c < K::n_components; ++c)
            cm[c] = 0;
          for (const auto &field : fields)
            {
              const double *s = field.p2g.begin() + i * P::n_components;
              const double *k = field.kinematics.begin() + i * K::n_components;
              for (unsigned int c = 0; c < P::n_components; ++c)
                sum[c] += s[c];
              for (unsigned int c = 0; c < K::n_components; ++c)
                cm[c] += s[P::mass] * k[c];
            }
          if (sum[P::mass] > 0)
            for (unsigned int c = 0; c < K::n_components; ++c)
              cm[c] /= sum[P::mass];
        }
      kinematics.update_ghost_values();
    }

    template <int dim>
    void
    check_parameters(const Parameters::AllParameters<dim> &params)
    {
      using Law                 = Parameters::Contact::Law;
      const auto       &contact = params.contact;
      const auto        field   = number_fields(given_fields(params.bodies));
      const std::string law = "Contact/Contact law = " + law_name(contact.law);
      if (!contact.enabled())
        {
          if (contact.gap_check)
            throw InputError(
              "Contact/Gap check = true has no effect with Contact/Contact "
              "law = none");
          for (unsigned int b = 0; b < params.bodies.size(); ++b)
            {
              if (!params.bodies[b].contact_normal.empty())
                throw InputError("Bodies/" + Parameters::body_section(b) +
                                 "/Contact normal has no effect with "
                                 "Contact/Contact law = none");
              if (params.bodies[b].contact_field >= 0)
                throw InputError(
                  "Bodies/" + Parameters::body_section(b) +
                  "/Contact field = " +
                  std::to_string(params.bodies[b].contact_field) +
                  " has no effect with Contact/Contact law = none: choose a "
                  "law, or leave the entry at -1");
            }
          return;
        }
      if (contact.friction > 0 && contact.law != Law::coulomb)
        {
          std::ostringstream s;
          s << "Contact/Friction coefficient = " << contact.friction
            << " is used by Contact law = Coulomb only, not by " << law;
          throw InputError(s.str());
        }
      if (params.time.integrator !=
          Parameters::TimeStepping::Integrator::explicit_dynamics)
        throw InputError(law +
                         ": contact is built for Time stepping/Integrator = "
                         "explicit only; the implicit integrators would "
                         "need its linearization");
      unsigned int n = 0;
      for (const unsigned char f : field)
        n = std::max(n, f + 1u);
      if (n < 2)
        throw InputError(
          law + " needs bodies in at least two velocity fields, but every "
                "body is in one field (Bodies/Body i/Contact field): contact "
                "acts between fields, never within one");
      for (unsigned int b = 0; b < params.bodies.size(); ++b)
        {
          const auto &body = params.bodies[b];
          if (body.locking_remedies
                .template find<remedies::ConvectionCorrectionSettings>())
            throw InputError(
              "Bodies/" + Parameters::body_section(b) +
              "/Locking remedies/Stress filter = convection correction "
              "cannot be combined with " +
              law + ": its nodal forces are not split by velocity field");
          if (!body.contact_normal.empty() && body.prescribed_velocity.empty())
            throw InputError("Bodies/" + Parameters::body_section(b) +
                             "/Contact normal is for rigid bodies (Prescribed "
                             "velocity) only");
          if (body.prescribed_velocity.empty())
            continue;
          for (unsigned int o = 0; o < params.bodies.size(); ++o)
            if (o != b && field[o] == field[b])
              throw InputError(
                "Bodies/" + Parameters::body_section(b) +
                " is rigid (Prescribed velocity) and shares its Contact field "
                "with Bodies/" +
                Parameters::body_section(o) +
                ": a rigid body needs a field of its own");
        }
    }

#define MPM_INSTANTIATE(d)             \
  template class MultiFieldContact<d>; \
  template void check_parameters<d>(const Parameters::AllParameters<d> &);
    MPM_INSTANTIATE(1)
    MPM_INSTANTIATE(2)
    MPM_INSTANTIATE(3)
#undef MPM_INSTANTIATE
  } // namespace contact
} // namespace mpm
