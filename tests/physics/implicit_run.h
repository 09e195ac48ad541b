// A few quasi-static steps of a case and what the implicit step reports:
// for cell_pressure_preconditioner and direct_solver, which solve the same
// case with different linear solvers and compare.
#pragma once

#include <string>

#include "../tests.h"

namespace implicit_run
{
  struct Result
  {
    double energy, newton, linear, reaction = 0;
  };

  /// @p steps steps of @p dt of the case @p text with @p n_bodies bodies:
  /// the strain energy at the end, the Newton and linear iterations summed
  /// over the steps, and with two bodies the rigid platen's reaction.
  inline Result
  run(const std::string &text,
      const unsigned int n_bodies,
      const double       dt,
      const unsigned int steps)
  {
    mpm_test::Case<2> c(text, n_bodies);
    auto             &sim = *c.simulator;
    Result            r{0, 0, 0};
    for (unsigned int step = 0; step < steps; ++step)
      {
        sim.do_time_step(dt);
        r.newton += mpm_test::integrator_value(sim, "newton_iterations");
        r.linear += mpm_test::integrator_value(sim, "linear_iterations");
      }
    r.energy = sim.statistics().strain_energy;
    if (n_bodies == 2)
      r.reaction = mpm_test::integrator_value(sim, "reaction_y");
    return r;
  }
} // namespace implicit_run
