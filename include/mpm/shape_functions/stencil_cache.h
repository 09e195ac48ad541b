#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/particles/property_pool.h> // types::particle_index

#include <mpm/shape_functions/stencil.h>

#include <limits>
#include <vector>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * The domain families' stencils of one step, kept so that each is
     * built once per step instead of once per pass. Within a step every
     * pass (P2G, G2P with MUSL's re-map, the stress update) sees the
     * domain where it was at the start of the step, so the stencil is the
     * same; building it (the corner walk of CPDI, the cell sums of GIMP)
     * was about half of a CPDI step.
     *
     * A particle is found by its cell (active index) and its place among
     * the cell's particles, which no pass changes; its id is stored too,
     * and a stencil whose id does not match is not used. The owner calls
     * forget() whenever a domain or the particles' cells may have changed
     * (positions updated, F changed for cpGIMP/CPDI, repartition).
     *
     * Entries are stored merged by node (GIMP appends one entry per node of
     * each cell it overlaps), so a lookup copies at most 3^dim entries.
     */
    template <int dim>
    class StencilCache
    {
    public:
      /// Drop every stencil; the next pass fills the cache again.
      void
      forget()
      {
        state = State::empty;
      }

      /// Whether the stencils are there to be read.
      bool
      ready() const
      {
        return state == State::ready;
      }

      /**
       * Called before a pass over all locally owned particles: an empty
       * cache starts filling (@p n_active_cells sizes the cell index,
       * @p n_particles the storage).
       */
      void
      begin_pass(const unsigned int n_active_cells,
                 const std::size_t  n_particles)
      {
        if (state != State::empty)
          return;
        state = State::filling;
        cell_first.assign(n_active_cells, unset);
        first_entry.assign(1, 0);
        ids.clear();
        entries.clear();
        // Room for this fill at the last fill's entries per particle (at
        // first 3^dim, the most a merged stencil of one cell's neighbours
        // has), so that the vectors do not grow by doubling, which would
        // hold up to three times the cache at the moment of the copy.
        const double per_particle = last_particles > 0 ?
                                      1.05 * last_entries / last_particles :
                                      (dim == 1 ? 3. :
                                       dim == 2 ? 9. :
                                                  27.);
        ids.reserve(n_particles);
        first_entry.reserve(n_particles + 1);
        entries.reserve(static_cast<std::size_t>(per_particle * n_particles));
      }

      /// After the pass: a complete fill (@p ok: every stencil built) is
      /// ready for the next passes of the step; an incomplete one is not.
      void
      end_pass(const bool ok)
      {
        if (state == State::filling)
          {
            state          = ok ? State::ready : State::empty;
            last_particles = ids.size();
            last_entries   = entries.size();
          }
      }

      /**
       * The stencil of particle @p id, the @p ordinal-th of cell @p cell,
       * into @p s; false if it is not stored.
       */
      bool
      load(const unsigned int                  cell,
           const unsigned int                  ordinal,
           const dealii::types::particle_index id,
           Stencil<dim>                       &s) const
      {
        if (state != State::ready || cell_first[cell] == unset)
          return false;
        const unsigned int k = cell_first[cell] + ordinal;
        if (k >= ids.size() || ids[k] != id)
          return false;
        s.n = 0;
        for (unsigned int e = first_entry[k]; e < first_entry[k + 1]; ++e)
          {
            s.node[s.n]     = entries[e].node;
            s.value[s.n]    = entries[e].value;
            s.gradient[s.n] = entries[e].gradient;
            ++s.n;
          }
        return true;
      }

      /**
       * While filling: store the stencil @p s of particle @p id, the
       * @p ordinal-th of cell @p cell. Particles must come cell by cell in
       * their order within the cell. @p merged: s names each node once
       * already (CPDI, CPDI2), so no merging is needed.
       */
      void
      store(const unsigned int                  cell,
            const unsigned int                  ordinal,
            const dealii::types::particle_index id,
            const Stencil<dim>                 &s,
            const bool                          merged = false)
      {
        if (state != State::filling)
          return;
        if (ordinal == 0)
          cell_first[cell] = ids.size();
        else if (cell_first[cell] + ordinal != ids.size())
          {
            // out of order (a skipped particle): not usable this step
            state = State::broken;
            return;
          }
        ids.push_back(id);
        const std::size_t start = entries.size();
        if (merged)
          {
            entries.resize(start + s.n);
            for (unsigned int k = 0; k < s.n; ++k)
              entries[start + k] = {s.node[k], s.value[k], s.gradient[k]};
            first_entry.push_back(entries.size());
            return;
          }
        for (unsigned int k = 0; k < s.n; ++k)
          {
            std::size_t e = start;
            while (e < entries.size() && entries[e].node != s.node[k])
              ++e;
            if (e < entries.size())
              {
                entries[e].value += s.value[k];
                entries[e].gradient += s.gradient[k];
              }
            else
              entries.push_back({s.node[k], s.value[k], s.gradient[k]});
          }
        first_entry.push_back(entries.size());
      }

      /// Bytes held (for the memory report).
      std::size_t
      memory_consumption() const
      {
        return cell_first.capacity() * sizeof(unsigned int) +
               first_entry.capacity() * sizeof(std::size_t) +
               ids.capacity() * sizeof(dealii::types::particle_index) +
               entries.capacity() * sizeof(Entry);
      }

    private:
      enum class State
      {
        empty,   ///< nothing stored; the next pass fills
        filling, ///< a pass is storing
        ready,   ///< complete for this step
        broken   ///< a fill went out of order: unused until forget()
      };
      struct Entry
      {
        unsigned int           node;
        double                 value;
        dealii::Tensor<1, dim> gradient;
      };
      static constexpr unsigned int unset =
        std::numeric_limits<unsigned int>::max();

      State                                      state = State::empty;
      std::vector<unsigned int>                  cell_first;
      std::vector<std::size_t>                   first_entry;
      std::vector<dealii::types::particle_index> ids;
      std::vector<Entry>                         entries;
      std::size_t last_particles = 0; ///< of the last complete fill
      std::size_t last_entries   = 0;
    };
  } // namespace shape_functions
} // namespace mpm
