#pragma once

#include <mpm/shape_functions/domain_families.h>
#include <mpm/shape_functions/family_traits.h>
#include <mpm/shape_functions/standard_family.h>

#include <array>

namespace mpm
{
  namespace shape_functions
  {
    template <typename... Families>
    struct FamilyList
    {
      static constexpr std::size_t size = sizeof...(Families);
    };

    /// Every family, in the order of the parameter's pattern. A new family
    /// is a type with the traits of StandardFamily, listed here and named
    /// in family_registry.cc.
    using RegisteredFamilies = FamilyList<StandardFamily,
                                          UGIMPFamily,
                                          CPGIMPFamily,
                                          CPDIFamily,
                                          CPDI2Family>;

    /// The run-time records of the registered families, in their order.
    const std::array<FamilyTraits, RegisteredFamilies::size> &
    registered_families();

    /// The record of family @p id.
    const FamilyTraits &
    family_traits(const Family id);

    namespace internal
    {
      template <typename Visitor, typename First, typename... Rest>
      decltype(auto)
      visit_family(const Family id, Visitor &&visit, FamilyList<First, Rest...>)
      {
        if constexpr (sizeof...(Rest) == 0)
          return visit(First{});
        else if (id == First::id)
          return visit(First{});
        else
          return visit_family(id,
                              std::forward<Visitor>(visit),
                              FamilyList<Rest...>{});
      }
    } // namespace internal

    /**
     * visit(F{}) with F the type of family @p id: the one run-time
     * dispatch of a pass, after which the pass is compiled for F.
     */
    template <typename Visitor>
    decltype(auto)
    with_family(const Family id, Visitor &&visit)
    {
      return internal::visit_family(id,
                                    std::forward<Visitor>(visit),
                                    RegisteredFamilies{});
    }
  } // namespace shape_functions
} // namespace mpm
