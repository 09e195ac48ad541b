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
        {Family::standard, "standard", "Q1 at the particle"},
        {Family::ugimp,
         "uGIMP",
         "average over a box domain of fixed size (axis-parallel grids only)"},
        {Family::cpgimp,
         "cpGIMP",
         "the box follows the stretch of the particle"},
        {Family::cpdi,
         "CPDI",
         "average over the parallelogram (parallelepiped) F r_i"},
        {Family::cpdi2,
         "CPDI2",
         "over the quadrilateral (hexahedron) of corners moved with the grid "
         "velocity"}};

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
      std::string text;
      for (const FamilyTraits &f : registered_families())
        text += (text.empty() ? "" : "; ") + std::string(f.name) + ": " +
                f.description;
      return text + ". Domains come from the body mesh (doc/theory.md, "
                    "section 9).";
    }
  } // namespace shape_functions
} // namespace mpm
