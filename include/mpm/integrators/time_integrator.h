#pragma once

#include <mpm/solver/simulation_state.h>

#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * How the state advances from one time to the next. The Simulator's
   * loop asks the integrator for the length of the next step and lets it
   * advance; it does the rest itself (time and step count, the collective
   * error check, repartitioning, output, checkpoints), so a new integrator
   * changes nothing in the loop.
   */
  template <int dim>
  class TimeIntegrator
  {
  public:
    explicit TimeIntegrator(SimulationState<dim> &state)
      : state(state)
    {}
    virtual ~TimeIntegrator() = default;

    virtual std::string
    name() const = 0;

    /// Checks of the set-up against the initial state (throws
    /// InputError), and what the first step needs from it. Not called on
    /// a restart: the checkpoint holds that state.
    virtual void
    initialize() = 0;

    /// The length of the next step (the loop shortens the last one to
    /// end at the end time).
    virtual double
    next_step_length() const = 0;

    /// Advance the particles by one step of length @p dt. Problems are
    /// recorded in state.local_error and collected by the caller.
    virtual void
    advance(const double dt) = 0;

    /// Fill the nodal fields that the grid output shows from the
    /// particles (before the first output, when no step has made them).
    virtual void
    compute_nodal_fields() = 0;

    /// Names of the integrator's own columns of the statistics file
    /// (the solver's iteration counts of an implicit step, say).
    virtual std::vector<std::string>
    statistics_columns() const
    {
      return {};
    }

    /// Their values for the last step.
    virtual std::vector<double>
    statistics_values() const
    {
      return {};
    }

  protected:
    SimulationState<dim> &state;
  };

  /// The integrator chosen in the parameters of @p state.
  template <int dim>
  std::unique_ptr<TimeIntegrator<dim>>
  create_time_integrator(SimulationState<dim> &state);
} // namespace mpm
