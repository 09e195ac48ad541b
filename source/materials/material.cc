#include <mpm/materials/material.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>

namespace mpm
{
  std::string
  to_string(const KinematicAssumption k)
  {
    switch (k)
      {
        case KinematicAssumption::three_dimensional:
          return "three-dimensional";
        case KinematicAssumption::plane_strain:
          return "plane strain";
        case KinematicAssumption::plane_stress:
          return "plane stress";
        case KinematicAssumption::uniaxial_strain:
          return "uniaxial strain";
        case KinematicAssumption::uniaxial_stress:
          return "uniaxial stress";
      }
    return "unknown";
  }

  namespace materials
  {
    namespace
    {
      // A function-local static is constructed on first use, so
      // registrations from other translation units work whatever the order
      // of static initialisation. Keyed by name, which keeps it sorted.
      std::map<std::string, MaterialEntry> &
      registry()
      {
        static std::map<std::string, MaterialEntry> entries;
        return entries;
      }

      std::string
      default_model()
      {
        const auto &entries = registry();
        if (entries.count("linear elastic") > 0)
          return "linear elastic";
        return entries.begin()->first;
      }
    } // namespace



    bool
    register_material(const MaterialEntry &entry)
    {
      // Two models with one name is a programming error; failing loudly at
      // start-up is better than silently picking one of them.
      if (entry.name.empty() || !entry.create || !entry.declare_parameters)
        throw std::logic_error("Invalid material registration '" + entry.name +
                               "'");
      if (!registry().emplace(entry.name, entry).second)
        throw std::logic_error("Material model '" + entry.name +
                               "' is registered twice");
      return true;
    }



    std::vector<MaterialEntry>
    registered_materials()
    {
      std::vector<MaterialEntry> result;
      result.reserve(registry().size());
      for (const auto &name_and_entry : registry())
        result.push_back(name_and_entry.second);
      return result;
    }



    std::string
    subsection_name(const std::string &model_name)
    {
      std::string section = model_name;
      if (!section.empty())
        section[0] = static_cast<char>(
          std::toupper(static_cast<unsigned char>(section[0])));
      return section;
    }



    void
    declare_material_parameters(dealii::ParameterHandler &prm)
    {
      if (registry().empty())
        throw std::logic_error("No material model is registered");

      std::string names, models;
      for (const auto &[name, entry] : registry())
        {
          names += (names.empty() ? "" : "|") + name;
          models += "\n" + name + ": " + entry.description;
        }

      prm.declare_entry("Model",
                        default_model(),
                        dealii::Patterns::Selection(names),
                        "Constitutive model. Its parameters are read from "
                        "the subsection whose name is the model's with an "
                        "upper-case first letter; the subsections of the "
                        "other models are ignored." +
                          models);
      prm.declare_entry("Density",
                        "1000",
                        mpm::NumberOrConstant(),
                        "Reference (initial) mass density rho_0 [kg/m^3], "
                        "positive. A particle's mass is rho_0 times its "
                        "initial volume and never changes.");

      for (const auto &name_and_entry : registry())
        {
          prm.enter_subsection(subsection_name(name_and_entry.first));
          name_and_entry.second.declare_parameters(prm);
          prm.leave_subsection();
        }
    }



    std::unique_ptr<Material>
    create_material(dealii::ParameterHandler &prm,
                    const KinematicAssumption k,
                    const std::string        &where)
    {
      const std::string model_name = prm.get("Model");
      const auto        entry      = registry().find(model_name);
      // The Selection pattern normally prevents this.
      if (entry == registry().end())
        throw InputError(where + ": unknown material model '" + model_name +
                         "'");

      const double density = mpm::get_number(prm, "Density");
      if (!(density > 0) || !std::isfinite(density))
        throw InputError(where + ": Density = " + prm.get("Density") +
                         " must be positive");

      std::unique_ptr<Material> material = entry->second.create();
      material->set_common(density, k);
      if (!material->supports(k))
        throw InputError(where + ": material model '" + model_name +
                         "' does not support the kinematic assumption '" +
                         to_string(k) + "'");

      prm.enter_subsection(subsection_name(model_name));
      try
        {
          material->parse_parameters(prm);
        }
      catch (const InputError &e)
        {
          // Models do not know where they are used; add it here.
          prm.leave_subsection();
          throw InputError(where + ": " + subsection_name(model_name) + ": " +
                           e.what());
        }
      prm.leave_subsection();
      return material;
    }
  } // namespace materials
} // namespace mpm
