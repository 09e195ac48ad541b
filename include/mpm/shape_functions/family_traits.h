#pragma once

#include <mpm/shape_functions/family.h>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * How a family's transfers sum into the nodal vectors (a property of
     * its Weights type). The order of the floating-point sums is part of
     * the results, so it is fixed at compile time.
     */
    enum class NodalSummation
    {
      per_cell, ///< a cell's particles into a buffer over its nodes, added once
      per_entry ///< every stencil entry straight into the nodal vector
    };

    /// How the assumed-stress filter enters a family's internal force (a
    /// property of its Weights type).
    enum class FilteredForce
    {
      /// the projected field integrated exactly over the particle domains
      integrated_field,
      /// the projected field's value at each particle, times its gradients
      projected_stress
    };

    /// What a run combines with its family, for FamilyTraits::check().
    struct FamilyUse
    {
      bool axis_parallel_grid; ///< every cell an axis-parallel box
      bool apic;               ///< Velocity transfer = APIC
      bool fixed_geometry;     ///< Implicit solver/Geometry = fixed
    };

    /**
     * A registered family as the solver sees it at run time: its name and
     * the behaviour the step depends on. Made from the family's type and
     * the registry's name and description by traits_of()
     * (family_registry.h lists the families).
     */
    struct FamilyTraits
    {
      Family      id;
      const char *name;
      /// For the parameter's documentation.
      const char *description;
      /// The weights come from particle domains (DomainShapeFunctions).
      bool has_domains;
      /// The weights need axis-parallel cells (GIMP's box integrals).
      bool needs_axis_parallel_grid;
      /// The domain is computed from F: after USF's stress update mass
      /// and momentum must be mapped again with the new domain.
      bool domain_follows_deformation;
      /// The domain's corners are particle properties, moved after G2P.
      bool tracks_corners;
      bool allows_apic;

      /// Throws an InputError if @p use is not possible with this family.
      void
      check(const FamilyUse &use) const;
    };

    /// The run-time record of the family type @p F, named @p name.
    template <typename F>
    constexpr FamilyTraits
    traits_of(const char *name, const char *description)
    {
      return {F::id,
              name,
              description,
              F::has_domains,
              F::needs_axis_parallel_grid,
              F::domain_follows_deformation,
              F::tracks_corners,
              F::allows_apic};
    }
  } // namespace shape_functions
} // namespace mpm
