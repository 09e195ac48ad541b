#include <mpm/parameters/parameters.h>
#include <mpm/remedies/registry.h>
#include <mpm/utilities/input_error.h>

#include <map>
#include <stdexcept>

namespace mpm
{
  namespace remedies
  {
    namespace
    {
      /// A parameter that chooses one remedy per body. Its documentation
      /// is the introduction followed by one line per remedy.
      struct Slot
      {
        const char *name;
        const char *introduction;
      };

      constexpr Slot slots[] = {
        {"Stress filter",
         "The locking remedy that acts on this body's stresses where the "
         "internal force is computed (none: the stresses as the material "
         "computes them)."},
        {"Volumetric smoothing",
         "The volumetric-locking remedy (doc/theory/volumetric_smoothing.md): "
         "the volume change that sets the pressure is averaged, the deviatoric "
         "part stays the particle's (none: no averaging). It works with every "
         "scheme, family and dimension."}};

      // Constructed on first use, so registrations from other translation
      // units work whatever the order of static initialisation. Keyed by
      // slot and name, which keeps each slot's selection sorted.
      std::map<std::string, std::map<std::string, RemedyEntry>> &
      registry()
      {
        static std::map<std::string, std::map<std::string, RemedyEntry>>
          entries;
        return entries;
      }
    } // namespace

    bool
    register_remedy(const RemedyEntry &entry)
    {
      bool known_slot = false;
      for (const Slot &slot : slots)
        known_slot = known_slot || entry.slot == slot.name;
      // A broken registration is a programming error: fail at start-up.
      if (!known_slot || entry.name.empty() || entry.name == "none" ||
          !entry.create || !entry.declare_parameters)
        throw std::logic_error("Invalid remedy registration '" + entry.slot +
                               " = " + entry.name + "'");
      if (!registry()[entry.slot].emplace(entry.name, entry).second)
        throw std::logic_error("Remedy '" + entry.slot + " = " + entry.name +
                               "' is registered twice");
      return true;
    }

    void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      for (const Slot &slot : slots)
        {
          const auto &entries = registry()[slot.name];
          std::string names   = "none";
          std::string doc     = slot.introduction;
          for (const auto &[name, entry] : entries)
            {
              names += "|" + name;
              doc += "\n" + entry.description;
            }
          prm.declare_entry(slot.name,
                            "none",
                            dealii::Patterns::Selection(names),
                            doc);
          for (const auto &name_and_entry : entries)
            name_and_entry.second.declare_parameters(prm);
        }
    }

    Selection
    parse_selection(dealii::ParameterHandler &prm)
    {
      Selection selection;
      for (const Slot &slot : slots)
        {
          const std::string name = prm.get(slot.name);
          if (name == "none")
            continue;
          // The Selection pattern admits registered names only.
          std::unique_ptr<Remedy> remedy =
            registry()[slot.name].at(name).create();
          remedy->parse_parameters(prm);
          selection.add(std::move(remedy));
        }
      return selection;
    }
    void
    require_explicit_integrator(const Context     &context,
                                const std::string &remedy)
    {
      if (context.time.integrator !=
          Parameters::TimeStepping::Integrator::explicit_dynamics)
        throw InputError(context.where + "/Locking remedies: " + remedy +
                         " has no linearization for the implicit "
                         "Time stepping/Integrator (quasi-static, Newmark) "
                         "yet; remove it or use Integrator = explicit");
    }
  } // namespace remedies
} // namespace mpm
