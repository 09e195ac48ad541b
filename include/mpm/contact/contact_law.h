#pragma once

#include <deal.II/base/tensor.h>

#include <mpm/contact/contact_parameters.h>

#include <cmath>

namespace mpm
{
  namespace contact
  {
    /// One velocity field's values at a node.
    template <int dim>
    struct FieldAtNode
    {
      double                 mass = 0;
      dealii::Tensor<1, dim> velocity;
      /// sum_p m_p grad N_ip over the field's particles: at a node on the
      /// field's boundary it points out of the field's bodies (grad N_i
      /// points towards node i)
      dealii::Tensor<1, dim> mass_gradient;
      /// the contact normal, out of the field's bodies (unit, or zero
      /// where no direction is known)
      dealii::Tensor<1, dim> normal;
      /// sum_p m_p N_ip x_p / sum_p m_p N_ip over the field's particles,
      /// and its distance from the field's surface when that passes
      /// through the node (centroid_offset()): the gap check's
      dealii::Tensor<1, dim> centroid;
      double                 surface_offset = 0;
      bool                   rigid          = false;
      /// found apart from the other fields by the gap check: no contact
      bool apart = false;
    };

    /// The first rigid field among the @p n at a node that is not apart,
    /// or -1.
    template <int dim>
    inline int
    first_rigid(const FieldAtNode<dim> *fields, const unsigned int n)
    {
      for (unsigned int f = 0; f < n; ++f)
        if (fields[f].rigid && !fields[f].apart)
          return static_cast<int>(f);
      return -1;
    }

    /**
     * The distance, in cell heights, from the surface of a body that
     * fills a half-space bounded by a plane through a node to its nodal
     * mass centroid sum_p m_p N_ip x_p / sum_p m_p N_ip, for particles
     * of spacing l on a lattice aligned with the plane: 1/3 + (l/h)^2 / 6
     * (1/3 in the continuum limit, 0.375 for 2 particles per cell
     * direction). @p size_ratio_squared: (l/h)^2.
     */
    inline double
    centroid_offset(const double size_ratio_squared)
    {
      return 1. / 3 + size_ratio_squared / 6;
    }

    /**
     * The gap check (doc/theory/contact.md): the fields at a node touch
     * where their mass centroids are no farther apart along the contact
     * normal than if their surfaces met at the node, the sum of their
     * surface_offset, plus @p tolerance (a length). A deformable field is
     * apart when every other field's centroid lies farther than that
     * beyond its own along its normal; a rigid field when every
     * deformable field that is not apart does. Call after
     * set_contact_normals(). Returns how many fields are not apart.
     */
    template <int dim>
    inline unsigned int
    mark_fields_apart(FieldAtNode<dim>  *fields,
                      const unsigned int n,
                      const double       tolerance)
    {
      auto touch = [&](const FieldAtNode<dim> &f, const FieldAtNode<dim> &g) {
        return (g.centroid - f.centroid) * f.normal <=
               f.surface_offset + g.surface_offset + tolerance;
      };
      unsigned int touching = 0;
      for (unsigned int f = 0; f < n; ++f)
        if (!fields[f].rigid)
          {
            fields[f].apart = true;
            for (unsigned int g = 0; g < n; ++g)
              if (g != f && touch(fields[f], fields[g]))
                fields[f].apart = false;
            touching += !fields[f].apart;
          }
      for (unsigned int f = 0; f < n; ++f)
        if (fields[f].rigid)
          {
            fields[f].apart = true;
            for (unsigned int g = 0; g < n; ++g)
              if (!fields[g].rigid && !fields[g].apart &&
                  touch(fields[g], fields[f]))
                fields[f].apart = false;
            touching += !fields[f].apart;
          }
      return touching;
    }

    /**
     * The contact normals of the @p n fields at a node
     * (doc/theory/contact.md): two fields share one direction, along the
     * difference of their mass gradients, with opposite signs (the
     * exchanged momentum is then equal and opposite); a field meeting a
     * rigid one takes the rigid body's surface normal, reversed (the
     * deformable field's own gradient would tilt it at the field's
     * corners, where a sliding body would catch on a flat surface); with
     * three or more fields each takes its own gradient. Zero where the
     * gradients vanish.
     */
    template <int dim>
    inline void
    set_contact_normals(FieldAtNode<dim> *fields, const unsigned int n)
    {
      auto unit = [](const dealii::Tensor<1, dim> &g) {
        const double norm = g.norm();
        return norm > 0 ? dealii::Tensor<1, dim>(g / norm) :
                          dealii::Tensor<1, dim>();
      };
      const int rigid = first_rigid(fields, n);
      for (unsigned int f = 0; f < n; ++f)
        {
          const dealii::Tensor<1, dim> &g = fields[f].mass_gradient;
          if (rigid >= 0)
            fields[f].normal = unit(-fields[rigid].mass_gradient);
          else if (n == 2)
            fields[f].normal = unit(g - fields[1 - f].mass_gradient);
          else
            fields[f].normal = unit(g);
        }
    }

    /**
     * Correct the velocities of the @p n >= 2 fields at a node by the
     * contact law (Bardenhagen et al. 2000; doc/theory/contact.md). The
     * reference velocity is the centre-of-mass velocity, or a rigid
     * field's. A field approaches when (v_f - v_ref) . n_f > 0; then its
     * normal relative velocity is removed, and its tangential one by
     * Coulomb's friction as far as mu times the normal correction goes
     * (stick beyond). No separation sets every field to the reference
     * velocity. Without a rigid field the total momentum is kept (exactly
     * with two fields, by a common shift with more). @p held: the node is
     * in contact whether the fields approach or not (the normal relative
     * velocity is removed either way). Returns whether any field was
     * corrected.
     */
    template <int dim>
    inline bool
    resolve_contact(const Parameters::Contact &law,
                    FieldAtNode<dim>          *fields,
                    const unsigned int         n,
                    const bool                 held = false)
    {
      using Law                    = Parameters::Contact::Law;
      const int              rigid = first_rigid(fields, n);
      dealii::Tensor<1, dim> v_ref;
      double                 mass = 0;
      for (unsigned int f = 0; f < n; ++f)
        if (!fields[f].apart)
          {
            v_ref += fields[f].mass * fields[f].velocity;
            mass += fields[f].mass;
          }
      if (rigid >= 0)
        v_ref = fields[rigid].velocity;
      else
        v_ref /= mass;

      bool                   active = false;
      dealii::Tensor<1, dim> momentum_change;
      for (unsigned int f = 0; f < n; ++f)
        {
          FieldAtNode<dim> &field = fields[f];
          if (field.rigid || field.apart)
            continue;
          const dealii::Tensor<1, dim> relative = field.velocity - v_ref;
          dealii::Tensor<1, dim>       change;
          if (law.law == Law::no_separation)
            change = -relative;
          else
            {
              const double normal_relative = relative * field.normal;
              if (!(normal_relative > 0) && !(held && normal_relative != 0))
                continue;
              // held contact may also pull separating fields together:
              // the friction limit follows the normal correction's size
              const double                 approach = std::abs(normal_relative);
              const dealii::Tensor<1, dim> tangential =
                relative - normal_relative * field.normal;
              const double slip = tangential.norm();
              if (law.law == Law::coulomb && slip <= law.friction * approach)
                change = -relative; // stick
              else
                {
                  change = -normal_relative * field.normal;
                  if (law.law == Law::coulomb && slip > 0)
                    change -= (law.friction * approach / slip) * tangential;
                }
            }
          field.velocity += change;
          momentum_change += field.mass * change;
          active = true;
        }
      // Two fields exchange equal and opposite momenta by construction;
      // more fields at a node are shifted together to keep the sum.
      if (rigid < 0 && n > 2 && active)
        for (unsigned int f = 0; f < n; ++f)
          if (!fields[f].apart)
            fields[f].velocity -= momentum_change / mass;
      return active;
    }
  } // namespace contact
} // namespace mpm
