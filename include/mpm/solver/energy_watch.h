#pragma once

#include <mpm/io/statistics.h>
#include <mpm/parameters/parameters.h>
#include <mpm/particles/body.h>

#include <ostream>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * The energy balance at every output: kinetic + strain energy less the
   * work of the loads since the start. Walls, damping, plasticity,
   * viscosity and PIC only take energy out, so a balance that grows
   * beyond Output/Energy balance tolerance (relative to the largest
   * energy seen) is energy created by the model or the scheme
   * (doc/theory/statistics_and_conservation.md ("Energy balance")). The work of
   * a load is known exactly for constant body forces and tractions (m b . (x -
   * X)); with a load that varies, or a rigid body with a prescribed motion, the
   * balance is not watched.
   */
  template <int dim>
  class EnergyWatch
  {
  public:
    EnergyWatch(const Parameters::Output     &output,
                const std::vector<Body<dim>> &bodies);

    /// Why the balance is not watched ("" if it is).
    const std::string &
    not_watched() const
    {
      return reason;
    }

    /**
     * Compare the statistics of an output with the first ones seen (the
     * start, or the resume point). Warns once on @p warnings (rank 0
     * passes std::cerr); with Energy balance check = stop, throws a
     * RuntimeError naming the step instead.
     */
    void
    check(const GlobalStatistics<dim> &stats,
          const unsigned int           step,
          const double                 time,
          std::ostream                *warnings);

  private:
    Parameters::Output::EnergyCheck action;
    double                          tolerance;
    std::string                     reason;
    /// The first body whose filtered stress (mass metric, written back)
    /// sets its strain energy ("" if none): named as a possible cause.
    std::string  mass_filter;
    bool         started = false, warned = false;
    double       initial_balance = 0, scale = 0;
    unsigned int initial_step = 0;
  };
} // namespace mpm
