#include <mpm/contact/contact_parameters.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <sstream>

namespace mpm
{
  namespace Parameters
  {
    void
    Contact::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.declare_entry(
        "Contact law",
        "none",
        dealii::Patterns::Selection("none|no separation|frictionless|Coulomb"),
        "none: every body moves in one velocity field, so bodies that meet "
        "stick together. Otherwise each velocity field (Bodies/Body i/"
        "Contact field) has its own nodal mass, momentum and force, and "
        "where two fields share a node their velocities are corrected by "
        "the law: no separation (the common velocity, as with one field), "
        "frictionless (no penetration, free sliding and separation) or "
        "Coulomb (no penetration; the tangential impulse is at most the "
        "Friction coefficient times the normal one). Explicit integrator "
        "only.");
      prm.declare_entry("Friction coefficient",
                        "0",
                        NumberOrConstant(),
                        "Coulomb's mu (Contact law = Coulomb), at least 0 (a "
                        "number or an expression of the Constants).");
      prm.leave_subsection();
    }

    void
    Contact::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      const std::string l = prm.get("Contact law");
      law                 = l == "none"          ? Law::none :
                            l == "no separation" ? Law::no_separation :
                            l == "frictionless"  ? Law::frictionless :
                                                   Law::coulomb;
      friction            = get_number(prm, "Friction coefficient");
      prm.leave_subsection();
      if (!(friction >= 0))
        {
          std::ostringstream msg;
          msg << "Contact/Friction coefficient = " << friction
              << " must be at least 0";
          throw InputError(msg.str());
        }
    }

    std::string
    law_name(const Contact::Law law)
    {
      switch (law)
        {
          case Contact::Law::none:
            return "none";
          case Contact::Law::no_separation:
            return "no separation";
          case Contact::Law::frictionless:
            return "frictionless";
          default:
            return "Coulomb";
        }
    }
  } // namespace Parameters
} // namespace mpm
