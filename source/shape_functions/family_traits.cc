#include <mpm/shape_functions/family_registry.h>
#include <mpm/utilities/input_error.h>

#include <vector>

namespace mpm
{
  namespace shape_functions
  {
    namespace
    {
      /// "A, B or C": the names of the registered families that @p pick.
      template <typename Pick>
      std::string
      names_of(const Pick pick)
      {
        std::vector<std::string> names;
        for (const FamilyTraits &f : registered_families())
          if (pick(f))
            names.emplace_back(f.name);
        std::string list;
        for (std::size_t i = 0; i < names.size(); ++i)
          list += (i == 0                ? "" :
                   i + 1 == names.size() ? " or " :
                                           ", ") +
                  names[i];
        return list;
      }
    } // namespace

    void
    FamilyTraits::check(const FamilyUse &use) const
    {
      const std::string what = std::string("Shape functions/Family = ") + name;
      if (needs_axis_parallel_grid && !use.axis_parallel_grid)
        throw InputError(
          what +
          " needs a grid of axis-parallel boxes, and this grid has "
          "distorted cells; use " +
          names_of([](const FamilyTraits &f) {
            return f.has_domains && !f.needs_axis_parallel_grid;
          }) +
          " there");
      if (use.apic && !allows_apic)
        throw InputError(
          "Time stepping/Velocity transfer = APIC needs a particle-domain "
          "family (Shape functions/Family = " +
          names_of([](const FamilyTraits &f) { return f.allows_apic; }) +
          "): with the standard Q1 functions the affine transfer C_p = sum_i "
          "v_i grad N_ip grows without bound where a particle enters a cell "
          "whose far nodes only it reaches, and the step is unstable "
          "(doc/theory/apic.md)");
      if (use.fixed_geometry && domain_follows_deformation)
        throw InputError(
          "Implicit solver/Geometry = fixed keeps the particles' domains as "
          "they start, and " +
          what + " computes each domain from F; use " +
          names_of([](const FamilyTraits &f) {
            return !f.domain_follows_deformation;
          }) +
          " there");
    }
  } // namespace shape_functions
} // namespace mpm
