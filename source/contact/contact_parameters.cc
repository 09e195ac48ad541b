#include <deal.II/base/utilities.h>

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
      prm.declare_entry(
        "Gap check",
        "false",
        dealii::Patterns::Bool(),
        "false: two fields at a node are in contact whenever they approach "
        "each other there, which happens up to two cells before their "
        "surfaces meet. true: also only where they touch: where the "
        "distance along the contact normal between the fields' mass "
        "centroids at the node (sum_p m_p N_ip x_p / sum_p m_p N_ip) is at "
        "most what it is for two bodies that touch along a surface "
        "through the node, plus the Gap tolerance (doc/theory/contact.md, "
        "the gap check). Lets a cylinder roll (doc/benchmarks/"
        "sliding_block.md).");
      prm.declare_entry("Gap tolerance",
                        dealii::Utilities::to_string(default_gap_tolerance),
                        dealii::Patterns::Double(-0.5, 0.5),
                        "With Gap check: added to the touching distance, in "
                        "cell heights; below 0 bodies overlap before they "
                        "meet, above 0 they meet before they touch.");
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
      gap_check           = prm.get_bool("Gap check");
      gap_tolerance       = prm.get_double("Gap tolerance");
      prm.leave_subsection();
      if (!(friction >= 0))
        {
          std::ostringstream msg;
          msg << "Contact/Friction coefficient = " << friction
              << " must be at least 0";
          throw InputError(msg.str());
        }
      if (!gap_check && gap_tolerance != default_gap_tolerance)
        {
          std::ostringstream msg;
          msg << "Contact/Gap tolerance = " << gap_tolerance
              << " has no effect without Contact/Gap check = true";
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
