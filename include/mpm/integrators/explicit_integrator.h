#pragma once

#include <mpm/integrators/time_integrator.h>
#include <mpm/shape_functions/family_traits.h>
#include <mpm/transfer/particle_to_grid.h>

namespace mpm
{
  /**
   * The explicit MPM step (doc/theory/explicit_step.md). One step reads as
   * the algorithm, a list of named phases:
   *   USL, MUSL: P2G -> grid update -> G2P [+ MUSL re-map] -> stress
   *              update -> position update;
   *   USF:       P2G (mass, momentum) -> nodal velocity -> stress update ->
   *              P2G (force) -> grid update -> G2P -> position update.
   * The step length is fixed or a CFL fraction of the stability limit
   * that the stress update measures.
   *
   * With a contact law each phase runs once per velocity field, on that
   * field's particles and nodal vectors, and the fields' nodal velocities
   * meet by the law after each phase that makes them (the contact phase,
   * contact/multi_field_contact.h). One field is the plain step.
   */
  template <int dim>
  class ExplicitIntegrator : public TimeIntegrator<dim>
  {
  public:
    using TimeIntegrator<dim>::TimeIntegrator;

    std::string
    name() const override
    {
      return "explicit";
    }

    /// The stability limit of the initial state; a fixed step above it,
    /// or a damping that reverses the motion within a step, is refused.
    void
    initialize() override;

    double
    next_step_length() const override;

    void
    advance(const double dt) override;

    /// Nodal mass, momentum and velocity from the particles.
    void
    compute_nodal_fields() override;

    /// With contact: the nodes where fields met in the last step.
    std::vector<std::string>
    statistics_columns() const override;
    std::vector<double>
    statistics_values() const override;

  private:
    using TimeIntegrator<dim>::state;

    // The phases of one step.
    void
    particle_to_grid(const transfer::P2GContent content);
    /// USF: the nodal velocity from the first P2G pass.
    void
    nodal_velocity_from_momentum();
    void
    update_grid(const double dt);
    void
    grid_to_particle(const double dt);
    void
    remap_momentum();
    void
    update_stress(const double dt);
    void
    update_positions();

    /// The contact phase: the fields' velocities at time @p t meet by the
    /// contact law after @p phase (no-op with one field); @p kick: the
    /// grid update's time step, for the contact forces.
    void
    resolve_contact(const contact::Phase phase,
                    const double         t,
                    const double         kick);

    /// The velocity fields: one without contact, whose vectors are the
    /// state's own.
    unsigned int
    n_fields() const;
    NodalVector &
    p2g(const unsigned int f);
    NodalVector &
    kinematics(const unsigned int f);
    NodalVector &
    remap(const unsigned int f);

    /// The nodes the node passes are limited to: null (every node) with
    /// contact, whose fields the contact law combines over the whole
    /// grid, and with a remedy that adds forces after the P2G pass.
    ActiveNodes *
    active_nodes();

    /// Where the transfers find the particles, grid and family weights,
    /// for the particles of field @p f.
    transfer::TransferContext<dim>
    transfer_context(const unsigned int f) const;

    /// Nodes where the fields met in the last step (all ranks).
    double contact_nodes = 0;
    /// The shape-function family's behaviour.
    const shape_functions::FamilyTraits &
    family() const;
  };
} // namespace mpm
