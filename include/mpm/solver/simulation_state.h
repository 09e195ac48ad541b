#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm/contact/multi_field_contact.h>
#include <mpm/grid/active_nodes.h>
#include <mpm/grid/background_grid.h>
#include <mpm/grid/load_balancer.h>
#include <mpm/parameters/parameters.h>
#include <mpm/particles/body.h>
#include <mpm/particles/field_selection.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/remedies/force_pass_hook.h>
#include <mpm/remedies/stress_filter.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/utilities/collective_errors.h>

#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * What the parts of a run share: the grid, the particles and their
   * bodies, the shape functions and remedies chosen for them, the nodal
   * fields of the current step, and the clock. The Simulator builds it
   * (initial state or checkpoint), a TimeIntegrator advances it, output
   * and checkpoints read it.
   */
  template <int dim>
  struct SimulationState
  {
    SimulationState(const Parameters::AllParameters<dim> &params,
                    const MPI_Comm                        comm,
                    dealii::ConditionalOStream           &pcout,
                    dealii::TimerOutput                  &timer)
      : params(params)
      , comm(comm)
      , pcout(pcout)
      , timer(timer)
      , background(comm)
    {}

    /// The nodal vectors of the current partition (set-up, repartition).
    void
    initialize_nodal_vectors();

    /// Sort the particles that moved into their new cells (and ranks);
    /// particles that left the grid stop the run unless they are to be
    /// removed (Boundary conditions/Particles leaving the grid).
    void
    relocate_moved_particles();

    /// The stress update of the particles from the grid velocity in
    /// kinematics over @p dt (timed; errors recorded). Returns the stable
    /// time step of the new state.
    double
    update_particle_stress(const double dt)
    {
      return update_particle_stress(dt, kinematics, FieldSelection());
    }

    /// The same from the velocities of @p velocities (KinematicsLayout),
    /// for the particles @p only selects (contact: one velocity field).
    double
    update_particle_stress(const double          dt,
                           const NodalVector    &velocities,
                           const FieldSelection &only);

    const Parameters::AllParameters<dim> &params;
    const MPI_Comm                        comm;
    dealii::ConditionalOStream           &pcout;
    dealii::TimerOutput                  &timer;

    BackgroundGrid<dim>                     background;
    dealii::Particles::ParticleHandler<dim> particle_handler;
    ParticleLayout<dim>                     layout;
    std::vector<Body<dim>>                  bodies;

    /// The particle-domain family's weights (null for standard MPM).
    std::unique_ptr<shape_functions::DomainShapeFunctions<dim>>
                                                 domain_functions;
    std::unique_ptr<remedies::StressFilter<dim>> stress_filter;
    /// The remedies around the P2G passes with forces (the 1D convection
    /// correction).
    std::vector<std::unique_ptr<remedies::ForcePassHook<dim>>> force_pass_hooks;
    /// The velocity fields of contact (null: one field, no contact law).
    std::unique_ptr<contact::MultiFieldContact<dim>> contact;
    /// Null unless load balancing is on.
    std::unique_ptr<LoadBalancer<dim>> balancer;

    /// Nodal fields of the step: P2G sums, velocities, MUSL's re-mapped
    /// momentum, and the node average of volumetric smoothing. No nodal
    /// value lives from one step to the next: the particles carry the
    /// whole state.
    NodalVector p2g, kinematics, remap, volume_sums;
    /// The nodes the particles reach in the step, which the explicit
    /// step's node passes over p2g, kinematics and remap are limited to.
    ActiveNodes active_nodes;
    /// Nodes lighter than this carry no velocity.
    double min_nodal_mass = 0;

    double       current_time = 0;
    unsigned int current_step = 0;
    double       last_dt      = 0;
    double       stable_dt    = 0; ///< from the last stress update (local)
    double       removed_mass = 0; ///< local
    /// Steps in which particle relocation fell back to deal.II's sort.
    unsigned int n_global_sorts = 0;
    /// The first problem found on this rank in the current step.
    FirstProblem             local_error;
    std::vector<std::string> lost_messages;
  };
} // namespace mpm
