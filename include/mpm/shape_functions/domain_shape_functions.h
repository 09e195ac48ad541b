#pragma once

#include <deal.II/base/point.h>

#include <mpm/grid/background_grid.h>
#include <mpm/shape_functions/cpdi.h>
#include <mpm/shape_functions/family.h>
#include <mpm/shape_functions/stencil.h>
#include <mpm/shape_functions/stencil_cache.h>

#include <string>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * The weights of the particle-domain families (uGIMP, cpGIMP, CPDI,
     * CPDI2) for one particle, from its properties and the cell it is in.
     * The domain is walked through the grid by face neighbours starting
     * from the particle's cell, never by a global search:
     *
     * - GIMP (axis-parallel grids only): the box of half-widths l_d,
     *   integrated exactly over the up to 3^dim cells it overlaps.
     * - CPDI, CPDI2: the corners are located in their cells (the walk
     *   crosses the face with the largest violation of 0 <= xi <= 1, as
     *   particle relocation does) and the Q1 values there are combined
     *   with the corner weights (cpdi.h).
     *
     * Ghost cells count: a domain that reaches a ghost cell adds to its
     * nodes, and the transfers' compress() sends that to the owner.
     */
    template <int dim>
    class DomainShapeFunctions
    {
    public:
      enum class Status
      {
        ok,
        outside_grid,  ///< part of the domain lies outside the grid
        beyond_ghosts, ///< the domain reaches cells this rank does not know
        too_wide,      ///< a GIMP box wider than the neighbouring cell
        collapsed,     ///< CPDI domain inverted or nearly flat
        lost_corner    ///< a corner not found within a few cells
      };

      /**
       * @p clamp: clip domains at the grid boundary (GIMP boxes are cut
       * there and averaged over the part inside; CPDI corners outside are
       * moved to the boundary) instead of reporting outside_grid.
       * @p corner_offset: where CPDI2's corners start in the particle
       * properties (ParticleLayout::corners()). @p cache_stencils: keep
       * each step's stencils (StencilCache).
       */
      DomainShapeFunctions(const BackgroundGrid<dim> &grid,
                           const Family               family,
                           const bool                 clamp,
                           const unsigned int         corner_offset,
                           const bool                 cache_stencils = false);

      Family
      family() const
      {
        return which;
      }

      /// Where CPDI2's corners start in the particle properties.
      unsigned int
      corner_slots() const
      {
        return corner_offset;
      }

      /**
       * The stencil of the particle at reference coordinates @p xi
       * (properties @p prop) in the cell with active index @p cell; for
       * CPDI and CPDI2 also the corners with their weights (@p corners,
       * may be null). The centre is taken from cell and xi, not from the
       * particle's location: within a step every pass then sees the
       * domain where it was at the start of the step, as standard MPM
       * does with its reference coordinates.
       */
      Status
      evaluate(const unsigned int        cell,
               const dealii::Point<dim> &xi,
               const double             *prop,
               Stencil<dim>             &stencil,
               CornerWeights<dim>       *corners = nullptr) const;

      /**
       * evaluate() for a particle of deal.II's ParticleHandler, the
       * @p ordinal-th of the cell with active index @p cell; on failure
       * sets @p error (if still empty) to message() and returns false.
       * With the cache on, the step's stencil is built once (by the first
       * pass between begin_pass() and end_pass()) and read back after.
       */
      template <typename Particle>
      bool
      evaluate(const unsigned int cell,
               const unsigned int ordinal,
               const Particle    &p,
               Stencil<dim>      &stencil,
               std::string       &error) const
      {
        if (cache_on && cache.load(cell, ordinal, p.get_id(), stencil))
          return true;
        const Status status = evaluate(cell,
                                       p.get_reference_location(),
                                       p.get_properties().data(),
                                       stencil);
        if (status == Status::ok)
          {
            if (cache_on)
              cache.store(cell, ordinal, p.get_id(), stencil, !is_gimp(which));
            return true;
          }
        if (error.empty())
          error = message(status, p.get_id(), p.get_location());
        return false;
      }

      /// Around every pass over the @p n_particles locally owned particles
      /// that evaluates stencils (@p ok: no evaluation failed).
      void
      begin_pass(const std::size_t n_particles) const
      {
        if (cache_on)
          cache.begin_pass(grid.triangulation().n_active_cells(), n_particles);
      }
      void
      end_pass(const bool ok) const
      {
        cache.end_pass(ok);
      }

      /// The domains or the particles' cells changed: build anew.
      void
      forget_stencils()
      {
        cache.forget();
      }

      /// Bytes held by the stencil cache.
      std::size_t
      memory_consumption() const
      {
        return cache.memory_consumption();
      }

      /**
       * CPDI2 only: move the corners of the particle in @p cell at @p xi
       * by dt times the grid velocity there (@p velocity: nodal values,
       * @p stride numbers per node).
       */
      Status
      move_corners(const unsigned int        cell,
                   const dealii::Point<dim> &xi,
                   double                   *prop,
                   const double             *velocity,
                   const unsigned int        stride,
                   const double              dt) const;

      /// "the domain of particle <id> at (<x>) <what went wrong>".
      std::string
      message(const Status              status,
              const unsigned long long  id,
              const dealii::Point<dim> &x) const;

      /// GIMP's reference half-widths of a domain with half-vectors R0
      /// (columns): the bounding box of the parallelogram, scaled to its
      /// volume.
      static dealii::Tensor<1, dim>
      gimp_half_widths(const dealii::Tensor<2, dim> &R0);

    private:
      Status
      evaluate_gimp(const unsigned int        cell,
                    const dealii::Point<dim> &x,
                    const double             *prop,
                    Stencil<dim>             &stencil) const;

      Status
      locate(unsigned int              cell,
             const dealii::Point<dim> &x,
             const dealii::Point<dim> &start,
             unsigned int             &found,
             dealii::Point<dim>       &xi) const;

      const BackgroundGrid<dim> &grid;
      const Family               which;
      const bool                 clamp;
      const unsigned int         corner_offset;
      const bool                 cache_on;
      /// This step's stencils: a memo, filled by whichever pass comes first.
      mutable StencilCache<dim> cache;
    };

    /// The family whose weights @p domains gives (null: standard MPM).
    template <int dim>
    inline Family
    family_of(const DomainShapeFunctions<dim> *domains)
    {
      return domains ? domains->family() : Family::standard;
    }
  } // namespace shape_functions
} // namespace mpm
