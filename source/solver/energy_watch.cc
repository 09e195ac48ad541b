#include <mpm/remedies/assumed_stress_remedy.h>
#include <mpm/solver/energy_watch.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mpm
{
  template <int dim>
  EnergyWatch<dim>::EnergyWatch(const Parameters::Output     &output,
                                const std::vector<Body<dim>> &bodies)
    : action(output.energy_check)
    , tolerance(output.energy_tolerance)
  {
    using Check = Parameters::Output::EnergyCheck;
    if (action == Check::none)
      reason = "Output/Energy balance check = none";
    for (const auto &body : bodies)
      {
        const std::string name =
          "Bodies/" + Parameters::body_section(body.index);
        if (reason.empty())
          {
            if (body.is_rigid())
              reason = name + " moves as prescribed (its work is not known)";
            else if (!body.body_force.is_constant())
              reason = name + "/Body force varies (its work is not known)";
            else if (body.has_traction() && !body.traction.is_constant())
              reason = name + "/Traction varies (its work is not known)";
            else if (body.prm.inflow.enabled)
              reason = name + "/Inflow brings energy in with its particles";
          }
        // The mass metric's projection of a locked pressure has deviatoric
        // parts, which carry far more energy per unit of stress.
        const auto *filter =
          body.prm.locking_remedies
            .template find<remedies::AssumedStressSettings>();
        if (mass_filter.empty() && filter && filter->write_back &&
            filter->metric == remedies::Metric::mass)
          mass_filter = name;
      }
  }

  template <int dim>
  void
  EnergyWatch<dim>::check(const GlobalStatistics<dim> &stats,
                          const unsigned int           step,
                          const double                 time,
                          std::ostream                *warnings)
  {
    if (!reason.empty() || !std::isfinite(stats.load_work))
      return;
    const double energy  = stats.kinetic_energy + stats.strain_energy;
    const double balance = energy - stats.load_work;
    scale                = std::max({scale, energy, std::abs(stats.load_work)});
    if (!started)
      {
        started         = true;
        initial_balance = balance;
        initial_step    = step;
        return;
      }
    const double growth = balance - initial_balance;
    if (scale <= 0 || growth <= tolerance * scale || warned)
      return;
    std::ostringstream s;
    s.precision(3);
    s << "at step " << step << " (t = " << time
      << "): kinetic + strain energy less the work of the loads has grown by "
      << growth << " since step " << initial_step << ", "
      << 100. * growth / scale
      << "% of the largest energy (Output/Energy balance tolerance = "
      << tolerance << "; kinetic " << stats.kinetic_energy << ", strain "
      << stats.strain_energy << ", work of the loads " << stats.load_work
      << "). Energy is being created: by a rate-form model (linear "
         "elastic) at large strain, which a hyperelastic one (neo-Hookean) "
         "avoids, or by USL's update at nodes of little mass, which MUSL "
         "and USF avoid";
    if (!mass_filter.empty())
      s << ", or by the assumed-stress filter of " << mass_filter
        << " with Filter metric = mass, whose filtered stress in nearly "
           "incompressible material has more strain energy than the "
           "particles' own (Filter metric = compliance avoids it)";
    s << " (doc/theory/statistics_and_conservation.md, \"Energy balance\").";
    if (action == Parameters::Output::EnergyCheck::stop)
      throw RuntimeError(s.str());
    warned = true;
    if (warnings)
      *warnings << "mpm: warning: " << s.str() << std::endl;
  }

  template class EnergyWatch<1>;
  template class EnergyWatch<2>;
  template class EnergyWatch<3>;
} // namespace mpm
