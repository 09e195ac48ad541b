#include <mpm/integrators/explicit_integrator.h>
#include <mpm/integrators/implicit_integrator.h>
#include <mpm/integrators/time_integrator.h>

namespace mpm
{
  template <int dim>
  std::unique_ptr<TimeIntegrator<dim>>
  create_time_integrator(SimulationState<dim> &state)
  {
    using Integrator = Parameters::TimeStepping::Integrator;
    if (state.params.time.integrator != Integrator::explicit_dynamics)
      return std::make_unique<ImplicitIntegrator<dim>>(state);
    return std::make_unique<ExplicitIntegrator<dim>>(state);
  }

  template std::unique_ptr<TimeIntegrator<1>>
  create_time_integrator(SimulationState<1> &);
  template std::unique_ptr<TimeIntegrator<2>>
  create_time_integrator(SimulationState<2> &);
  template std::unique_ptr<TimeIntegrator<3>>
  create_time_integrator(SimulationState<3> &);
} // namespace mpm
