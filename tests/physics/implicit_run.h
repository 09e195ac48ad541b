// A few quasi-static steps of a case and what the implicit step reports,
// and the check that two runs reached the same solution: for
// cell_pressure_preconditioner and direct_solver, which solve the same
// case with different linear solvers and compare.
#pragma once

#include <cmath>
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

  /// Report whether @p b reached the solution of @p a: the strain energy
  /// and (with a platen) its reaction to 1e-8, the same Newton iterations.
  inline void
  same_solution(const std::string &name, const Result &a, const Result &b)
  {
    const double de = (b.energy - a.energy) / a.energy;
    mpm_test::report(std::abs(de) <= 1e-8,
                     name + ": the same strain energy to 1e-8",
                     de);
    if (a.reaction != 0)
      {
        const double dr = (b.reaction - a.reaction) / a.reaction;
        mpm_test::report(std::abs(dr) <= 1e-8,
                         name + ": the same platen reaction to 1e-8",
                         dr);
      }
    mpm_test::report(a.newton == b.newton,
                     name + ": the same Newton iterations",
                     b.newton);
  }
} // namespace implicit_run
