#include <mpm/grid/grid_update.h>
#include <mpm/integrators/explicit_integrator.h>
#include <mpm/shape_functions/family_registry.h>
#include <mpm/solver/stress_update.h>
#include <mpm/transfer/grid_to_particle.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace mpm
{
  using namespace dealii;
  using contact::Phase;

  template <int dim>
  void
  ExplicitIntegrator<dim>::initialize()
  {
    using StepControl = Parameters::TimeStepping::StepControl;
    const auto &time  = state.params.time;
    // the caller's bound (particles that are still to enter) and the
    // particles' own
    state.stable_dt    = std::min(state.stable_dt,
                               ::mpm::stable_time_step(state.background,
                                                       state.particle_handler,
                                                       state.bodies));
    state.stable_dt    = Utilities::MPI::min(state.stable_dt, state.comm);
    const double limit = state.stable_dt;
    if (time.step_control == StepControl::fixed && time.time_step > limit)
      {
        std::ostringstream msg;
        msg << "Time stepping/Time step = " << time.time_step
            << " exceeds the stability limit min_p h/(c_p + |v_p|) = " << limit
            << " of the initial state"
            << (std::any_of(state.bodies.begin(),
                            state.bodies.end(),
                            [](const auto &b) {
                              return b.prm.inflow.enabled;
                            }) ?
                  " and of the particles the inlets will create" :
                  "")
            << "; choose at most that, or "
            << "Time step control = CFL";
        throw InputError(msg.str());
      }
    // Mass-proportional damping scales the grid velocity by (1 - c dt) in
    // a step: above c dt = 1 it reverses the motion every step, above 2 it
    // grows without bound.
    const double first_dt = time.step_control == StepControl::fixed ?
                              time.time_step :
                              time.cfl_number * limit;
    if (time.damping * first_dt > 1.)
      {
        std::ostringstream msg;
        msg << "Time stepping/Damping coefficient = " << time.damping
            << " times the first time step " << first_dt << " is "
            << time.damping * first_dt
            << " > 1: the damping would reverse the velocity within a step "
            << "(explicit damping needs c dt <= 1); choose at most "
            << 1. / first_dt << " or a smaller step";
        throw InputError(msg.str());
      }
  }

  template <int dim>
  double
  ExplicitIntegrator<dim>::next_step_length() const
  {
    const auto &time = state.params.time;
    return time.step_control == Parameters::TimeStepping::StepControl::fixed ?
             time.time_step :
             time.cfl_number * state.stable_dt;
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::advance(const double dt)
  {
    using Scheme = Parameters::TimeStepping::Scheme;
    using transfer::P2GContent;
    // The particles moved (and may have changed cells or ranks) since the
    // stencils were built.
    if (state.domain_functions)
      state.domain_functions->forget_stencils();
    const double t_new = state.current_time + dt;
    // Leapfrog start: the grid velocities of every step are then those at
    // the middle of the step, which the position update x += dt v assumes.
    const double kick =
      state.params.time.leapfrog_start && state.current_step == 0 ? dt / 2 : dt;
    if (state.params.time.scheme == Scheme::usf)
      {
        particle_to_grid(P2GContent::mass_momentum);
        nodal_velocity_from_momentum();
        resolve_contact(Phase::start_of_step, state.current_time, dt);
        update_stress(dt);
        // cpGIMP and CPDI take their domains from F, which the stress
        // update has just changed: the force pass and G2P see the new
        // domain, so mass and momentum must be mapped with it again, or
        // G2P's weights no longer sum to the nodal masses and momentum is
        // not conserved.
        const bool new_domains = family().domain_follows_deformation;
        if (new_domains)
          state.domain_functions->forget_stencils();
        particle_to_grid(new_domains ? P2GContent::mass_momentum_force :
                                       P2GContent::force);
        update_grid(kick);
        resolve_contact(Phase::grid_update, t_new, kick);
        grid_to_particle(dt);
      }
    else
      {
        particle_to_grid(P2GContent::mass_momentum_force);
        update_grid(kick);
        resolve_contact(Phase::grid_update, t_new, kick);
        grid_to_particle(dt);
        if (state.params.time.scheme == Scheme::musl)
          {
            remap_momentum();
            resolve_contact(Phase::remap, t_new, dt);
          }
        update_stress(dt);
      }
    update_positions();
    if (state.contact)
      {
        state.contact->combine(state.background, state.p2g, state.kinematics);
        contact_nodes = Utilities::MPI::sum(
          static_cast<double>(state.contact->n_contact_nodes()), state.comm);
      }
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::compute_nodal_fields()
  {
    particle_to_grid(transfer::P2GContent::mass_momentum);
    nodal_velocity_from_momentum();
    resolve_contact(Phase::start_of_step, state.current_time, 0.);
    if (state.contact)
      state.contact->combine(state.background, state.p2g, state.kinematics);
  }

  template <int dim>
  std::vector<std::string>
  ExplicitIntegrator<dim>::statistics_columns() const
  {
    if (!state.contact)
      return {};
    return {"contact_nodes"};
  }

  template <int dim>
  std::vector<double>
  ExplicitIntegrator<dim>::statistics_values() const
  {
    if (!state.contact)
      return {};
    return {contact_nodes};
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::particle_to_grid(const transfer::P2GContent content)
  {
    // Remedies around the force pass change the forces of this pass only
    // (the 1D convection correction: doc/theory/convection_correction.md;
    // refused with contact).
    const bool force_pass =
      content == transfer::P2GContent::force ||
      content == transfer::P2GContent::mass_momentum_force;
    if (force_pass)
      for (const auto &hook : state.force_pass_hooks)
        {
          TimerOutput::Scope t(state.timer, hook->name());
          hook->before_force_pass(state.background,
                                  state.particle_handler,
                                  state.bodies,
                                  state.current_time);
        }
    {
      TimerOutput::Scope t(state.timer, "P2G");
      for (unsigned int f = 0; f < n_fields(); ++f)
        {
          const transfer::P2GContext<dim> context{transfer_context(f),
                                                  state.bodies,
                                                  *state.stress_filter,
                                                  state.current_time,
                                                  content,
                                                  p2g(f),
                                                  active_nodes()};
          state.local_error.record(transfer::particle_to_grid(context));
        }
    }
    if (force_pass)
      for (const auto &hook : state.force_pass_hooks)
        hook->after_force_pass(state.p2g);
    if (state.contact && content != transfer::P2GContent::force)
      {
        TimerOutput::Scope t(state.timer, "contact");
        state.contact->compute_mass_gradients(state.background,
                                              state.particle_handler);
      }
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::nodal_velocity_from_momentum()
  {
    TimerOutput::Scope t(state.timer, "grid update");
    for (unsigned int f = 0; f < n_fields(); ++f)
      state.local_error.record(
        nodal_velocity(state.background,
                       p2g(f),
                       p2g(f),
                       transfer::P2GLayout<dim>::n_components,
                       transfer::P2GLayout<dim>::momentum,
                       state.min_nodal_mass,
                       kinematics(f),
                       active_nodes()));
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::update_grid(const double dt)
  {
    TimerOutput::Scope t(state.timer, "grid update");
    for (unsigned int f = 0; f < n_fields(); ++f)
      state.local_error.record(::mpm::update_grid(state.background,
                                                  p2g(f),
                                                  dt,
                                                  state.params.time.damping,
                                                  state.min_nodal_mass,
                                                  kinematics(f),
                                                  active_nodes()));
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::resolve_contact(const Phase  phase,
                                           const double t,
                                           const double kick)
  {
    if (!state.contact)
      return;
    TimerOutput::Scope t_scope(state.timer, "contact");
    state.local_error.record(state.contact->resolve(state.background,
                                                    state.bodies,
                                                    state.min_nodal_mass,
                                                    phase,
                                                    t,
                                                    state.current_time,
                                                    kick));
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::grid_to_particle(const double dt)
  {
    TimerOutput::Scope t(state.timer, "G2P");
    // MUSL's re-map is fused into G2P (one pass over the particles).
    const bool fused_remap =
      state.params.time.scheme == Parameters::TimeStepping::Scheme::musl;
    for (unsigned int f = 0; f < n_fields(); ++f)
      state.local_error.record(transfer::grid_to_particle(
        transfer::G2PContext<dim>{transfer_context(f),
                                  kinematics(f),
                                  dt,
                                  state.params.time.flip_fraction,
                                  fused_remap ? &remap(f) : nullptr,
                                  active_nodes()}));
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::remap_momentum()
  {
    // The re-mapped momentum is in `remap` (G2P filled it).
    TimerOutput::Scope t(state.timer, "MUSL re-map");
    for (unsigned int f = 0; f < n_fields(); ++f)
      state.local_error.record(nodal_velocity(state.background,
                                              p2g(f),
                                              remap(f),
                                              dim,
                                              0,
                                              state.min_nodal_mass,
                                              kinematics(f),
                                              active_nodes()));
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::update_stress(const double dt)
  {
    state.stable_dt = std::numeric_limits<double>::max();
    for (unsigned int f = 0; f < n_fields(); ++f)
      state.stable_dt =
        std::min(state.stable_dt,
                 state.update_particle_stress(dt,
                                              kinematics(f),
                                              transfer_context(f).only));
  }

  template <int dim>
  void
  ExplicitIntegrator<dim>::update_positions()
  {
    TimerOutput::Scope t(state.timer, "position update");
    if (family().tracks_corners)
      for (unsigned int f = 0; f < n_fields(); ++f)
        state.local_error.record(
          transfer::move_domain_corners(state.background,
                                        state.particle_handler,
                                        kinematics(f),
                                        state.last_dt,
                                        *state.domain_functions,
                                        transfer_context(f).only));
    state.relocate_moved_particles();
  }

  template <int dim>
  unsigned int
  ExplicitIntegrator<dim>::n_fields() const
  {
    return state.contact ? state.contact->n_fields() : 1;
  }

  template <int dim>
  NodalVector &
  ExplicitIntegrator<dim>::p2g(const unsigned int f)
  {
    return state.contact ? state.contact->p2g(f) : state.p2g;
  }

  template <int dim>
  NodalVector &
  ExplicitIntegrator<dim>::kinematics(const unsigned int f)
  {
    return state.contact ? state.contact->kinematics(f) : state.kinematics;
  }

  template <int dim>
  NodalVector &
  ExplicitIntegrator<dim>::remap(const unsigned int f)
  {
    return state.contact ? state.contact->remap(f) : state.remap;
  }

  template <int dim>
  ActiveNodes *
  ExplicitIntegrator<dim>::active_nodes()
  {
    if (state.contact || !state.force_pass_hooks.empty())
      return nullptr;
    return &state.active_nodes;
  }

  template <int dim>
  transfer::TransferContext<dim>
  ExplicitIntegrator<dim>::transfer_context(const unsigned int f) const
  {
    return {state.background,
            state.particle_handler,
            state.domain_functions.get(),
            state.layout.affine(),
            state.contact ? state.contact->selection(f) : FieldSelection()};
  }

  template <int dim>
  const shape_functions::FamilyTraits &
  ExplicitIntegrator<dim>::family() const
  {
    return shape_functions::family_traits(state.params.shape_functions.family);
  }

  template class ExplicitIntegrator<1>;
  template class ExplicitIntegrator<2>;
  template class ExplicitIntegrator<3>;
} // namespace mpm
