#pragma once

#include <mpm/shape_functions/domain_weights.h>
#include <mpm/shape_functions/family_traits.h>

namespace mpm
{
  namespace shape_functions
  {
    /// What a particle-domain family's domain does over a step.
    enum class DomainMotion
    {
      fixed,               ///< fixed in shape, moves with its particle
      follows_deformation, ///< computed from F at every evaluation
      tracked_corners      ///< corners stored and moved with the grid
    };

    /// Which grids a particle-domain family works on.
    enum class GridNeed
    {
      any,          ///< distorted cells included
      axis_parallel ///< boxes only (exact box integrals)
    };

    /**
     * What the particle-domain families share: weights averaged over the
     * particle's domain (DomainShapeFunctions), which reach the nodes of
     * every cell the domain overlaps; APIC works with them, the 1D
     * convection correction (derived for standard MPM) does not. Each
     * family (domain_families.h) is one of these, with its id, its
     * domain's motion and the grids it needs.
     */
    template <Family       family_id,
              DomainMotion motion,
              GridNeed     grid = GridNeed::any>
    struct DomainFamily
    {
      static constexpr Family id = family_id;

      template <int dim>
      using Weights = DomainWeights<dim>;

      static constexpr bool has_domains = true;
      static constexpr bool needs_axis_parallel_grid =
        grid == GridNeed::axis_parallel;
      static constexpr bool domain_follows_deformation =
        motion == DomainMotion::follows_deformation;
      static constexpr bool tracks_corners =
        motion == DomainMotion::tracked_corners;
      static constexpr bool allows_apic = true;
    };

    /// The GIMP families: box domains, integrated exactly over the
    /// axis-parallel cells they overlap.
    template <Family family_id, DomainMotion motion>
    using GIMPFamily = DomainFamily<family_id, motion, GridNeed::axis_parallel>;
  } // namespace shape_functions
} // namespace mpm
