#pragma once

#include <string>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * The ids of the shape-function families of the transfers
     * (doc/theory/explicit_step.md). Each family is a type of its own
     * (standard_family.h, ...) listed in family_registry.h, which gives
     * names, traits and the dispatch from an id to the family's type.
     */
    enum class Family
    {
      standard, ///< Q1 at the particle centre
      ugimp,    ///< box domain of fixed size (uGIMP)
      cpgimp,   ///< box domain following the stretch (contiguous GIMP)
      cpdi,     ///< parallelogram/parallelepiped domain F r_i (CPDI1)
      cpdi2     ///< quadrilateral/hexahedral domain of tracked corners
    };

    /// The family's name in parameter files.
    const char *
    family_name(const Family f);

    /// The family named @p name (which the pattern has already checked).
    Family
    parse_family(const std::string &name);

    /// The prm pattern of every registered name, "standard|uGIMP|...".
    std::string
    family_pattern();

    /// The documentation of Shape functions/Family: every family's name
    /// with its description.
    std::string
    family_documentation();

    /// The box-domain families: their stencils list a node once per cell
    /// of the box (not merged).
    inline bool
    is_gimp(const Family f)
    {
      return f == Family::ugimp || f == Family::cpgimp;
    }
  } // namespace shape_functions
} // namespace mpm
