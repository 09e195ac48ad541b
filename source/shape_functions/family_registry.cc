#include <mpm/shape_functions/family_registry.h>

namespace mpm
{
  namespace shape_functions
  {
    namespace
    {
      /// What the parameter file and its documentation call a family.
      struct FamilyText
      {
        Family      id;
        const char *name;
        const char *description;
      };

      constexpr FamilyText texts[] = {
        {Family::standard,
         "standard",
         "the Q1 functions of the particle's cell, at its centre"},
        {Family::ugimp,
         "uGIMP",
         "averaged over a box of fixed size around the particle (grids of "
         "axis-parallel boxes only)"},
        {Family::cpgimp,
         "cpGIMP",
         "the box follows the stretch of the particle (grids of "
         "axis-parallel boxes only)"},
        {Family::cpdi,
         "CPDI",
         "averaged over the parallelogram (parallelepiped) spanned by F "
         "times the particle's initial half-vectors r_i"},
        {Family::cpdi2,
         "CPDI2",
         "averaged over the quadrilateral (hexahedron) of the particle's "
         "corners, which move with the grid velocity"}};

      constexpr const FamilyText &
      text_of(const Family id)
      {
        std::size_t i = 0;
        while (texts[i].id != id)
          ++i;
        return texts[i];
      }

      template <typename... Families>
      constexpr std::array<FamilyTraits, sizeof...(Families)>
      records_of(FamilyList<Families...>)
      {
        return {{traits_of<Families>(text_of(Families::id).name,
                                     text_of(Families::id).description)...}};
      }
    } // namespace

    const std::array<FamilyTraits, RegisteredFamilies::size> &
    registered_families()
    {
      static constexpr auto records = records_of(RegisteredFamilies{});
      return records;
    }

    const FamilyTraits &
    family_traits(const Family id)
    {
      for (const FamilyTraits &f : registered_families())
        if (f.id == id)
          return f;
      return registered_families().front(); // every id is registered
    }

    const char *
    family_name(const Family f)
    {
      return family_traits(f).name;
    }

    Family
    parse_family(const std::string &name)
    {
      for (const FamilyTraits &f : registered_families())
        if (name == f.name)
          return f.id;
      return Family::standard; // the pattern has already checked the name
    }

    std::string
    family_pattern()
    {
      std::string pattern;
      for (const FamilyTraits &f : registered_families())
        pattern += (pattern.empty() ? "" : "|") + std::string(f.name);
      return pattern;
    }

    std::string
    family_documentation()
    {
      std::string text =
        "The shape functions of every transfer between particles and grid. "
        "The families other than standard average over particle domains, "
        "which come from the body mesh "
        "(doc/theory/particle_domain_families.md), so distorted body cells "
        "give distorted domains. Every family works with every scheme and "
        "locking remedy except Stress filter = convection correction, which "
        "needs standard. A domain that reaches beyond the neighbours of its "
        "particle's cell (GIMP) or beyond the cells its MPI rank knows, or "
        "that collapses (CPDI: a corner angle with sine below 1e-4), stops "
        "the run (status 2).";
      for (const FamilyTraits &f : registered_families())
        text += "\n" + std::string(f.name) + ": " + f.description + ".";
      return text;
    }
  } // namespace shape_functions
} // namespace mpm
