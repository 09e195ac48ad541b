#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/contact/contact_law.h>
#include <mpm/contact/contact_parameters.h>
#include <mpm/contact/nodal_contact_force.h>
#include <mpm/grid/background_grid.h>
#include <mpm/parameters/parameters.h>
#include <mpm/particles/body.h>
#include <mpm/particles/field_selection.h>

#include <string>
#include <vector>

namespace mpm
{
  namespace contact
  {
    /**
     * The phases after which the fields' velocities meet. The stress
     * update must see the velocities the particles move with, or an
     * elastic impact gains energy (doc/theory/contact.md, "Energy"): so
     * the phases whose velocities only the stress update uses keep
     * contact where the fields may not approach any more.
     */
    enum class Phase
    {
      /// the new velocities and their increments (FLIP's) of the grid
      /// update: the law acts where the fields approach
      grid_update,
      /// USF: the velocities of the first P2G pass, for the stress
      /// update: the law acts at every node the fields share
      start_of_step,
      /// MUSL: the re-mapped velocities, for the stress update: the law
      /// acts where the fields approach and where the grid update of the
      /// step found contact
      remap
    };

    /**
     * Multi-velocity-field contact (doc/theory/contact.md): each velocity
     * field (a body, or the bodies that share a Contact field number)
     * has nodal vectors of its own, filled by the transfers run once per
     * field (FieldSelection), and where two fields share a node their
     * velocities are corrected by the contact law (resolve_contact()).
     * A rigid body (Prescribed velocity) is a field whose nodal velocity
     * is its prescribed one, and whose surface normal may be given.
     *
     * No nodal value lives from one step to the next, so checkpoints need
     * nothing from here.
     */
    template <int dim>
    class MultiFieldContact
    {
    public:
      MultiFieldContact(const Parameters::Contact    &law,
                        const std::vector<Body<dim>> &bodies);

      unsigned int
      n_fields() const
      {
        return n;
      }

      /// The particles of field @p f.
      FieldSelection
      selection(const unsigned int f) const
      {
        return {&field_of_body, f};
      }

      /// The field's vectors for the current partition.
      void
      initialize_vectors(const BackgroundGrid<dim> &grid);

      /// Field @p f's P2G sums (P2GLayout), velocities (KinematicsLayout)
      /// and MUSL's re-mapped momentum (dim per node).
      NodalVector &
      p2g(const unsigned int f)
      {
        return fields[f].p2g;
      }
      NodalVector &
      kinematics(const unsigned int f)
      {
        return fields[f].kinematics;
      }
      NodalVector &
      remap(const unsigned int f)
      {
        return fields[f].remap;
      }

      /**
       * Each field's nodal mass gradient sum_p m_p grad N_ip, with the Q1
       * functions of the particle's cell, for the contact normals of the
       * step (at the positions of its start); with the gap check also
       * the fields' nodal mass centroids (Field::centroid).
       */
      void
      compute_mass_gradients(
        const BackgroundGrid<dim>               &grid,
        dealii::Particles::ParticleHandler<dim> &particles);

      /**
       * Apply the contact law to the fields' velocities at time @p t
       * after @p phase, on owned nodes; ghosts updated. A rigid field's
       * velocity is its prescribed one at @p t (and in the grid update its
       * increment the prescribed change since @p t_old). Fields lighter
       * than @p min_mass at a node do not take part. @p kick: the time
       * over which the grid update changed the momentum (the step, or
       * half of it for the leapfrog start), which turns the grid update's
       * corrections into forces(). Returns an empty string or the first
       * non-finite velocity.
       */
      std::string
      resolve(const BackgroundGrid<dim>    &grid,
              const std::vector<Body<dim>> &bodies,
              const double                  min_mass,
              const Phase                   phase,
              const double                  t,
              const double                  t_old,
              const double                  kick);

      /// The nodes (owned by this rank) where the last grid update's
      /// resolve corrected a field.
      unsigned long
      n_contact_nodes() const
      {
        return contact_nodes;
      }

      /**
       * The contact forces of the last grid update, at the owned nodes
       * where the law acted: the momentum the law gave the deformable
       * field of the lowest number there, over the step
       * (doc/theory/contact.md, "Contact forces"). Between two deformable
       * fields that is the force between them, as the first one feels it;
       * against a rigid field, the force on the deformable one.
       */
      const NodalContactForces<dim> &
      forces() const
      {
        return nodal_forces;
      }

      /// The sum of the fields into @p p2g (owned nodes) and their
      /// centre-of-mass velocity and increment into @p kinematics (ghosts
      /// updated): what one field would show in the output.
      void
      combine(const BackgroundGrid<dim> &grid,
              NodalVector               &p2g,
              NodalVector               &kinematics);

    private:
      struct Field
      {
        int rigid_body = -1; ///< the rigid body, or -1
        /// a rigid body's Contact normal (outward), if given
        bool                   given_normal = false;
        dealii::Tensor<1, dim> normal;
        NodalVector            p2g, kinematics, remap, mass_gradient;
        /// per node sum_p m_p N_ip (x_p, 1, h_p, (l_p/h_p)^2), h_p the
        /// height of the particle's cell and l_p = V_p^(1/dim) its size:
        /// the gap check's centroid, cell height and surface offset
        NodalVector centroid;
      };
      /// The centroids and surface offsets at owned node @p i of the
      /// @p count fields @p present there, into @p at_node; returns the
      /// mass-weighted cell height around the node.
      double
      set_centroids(const unsigned int  i,
                    FieldAtNode<dim>   *at_node,
                    const unsigned int *present,
                    const unsigned int  count) const;

      static constexpr unsigned int centroid_mass       = dim,
                                    centroid_height     = dim + 1,
                                    centroid_size       = dim + 2,
                                    centroid_components = dim + 3;
      Parameters::Contact        law;
      std::vector<unsigned char> field_of_body;
      unsigned int               n = 0;
      std::vector<Field>         fields;
      unsigned long              contact_nodes = 0;
      NodalContactForces<dim>    nodal_forces;
      /// per owned node, whether the grid update's resolve of this step
      /// acted (read by the re-map's)
      std::vector<char> in_contact;
    };

    /**
     * The contact settings of @p params checked against the bodies and
     * the integrator (InputError naming the entry): a law with bodies in
     * fewer than two fields, fields without a law, a friction coefficient
     * that the law does not use, a rigid body sharing a field, the
     * implicit integrators, the 1D convection correction.
     */
    template <int dim>
    void
    check_parameters(const Parameters::AllParameters<dim> &params);
  } // namespace contact
} // namespace mpm
