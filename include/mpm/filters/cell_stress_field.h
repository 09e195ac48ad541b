#pragma once

#include <mpm/filters/assumed_stress.h>

#include <vector>

namespace mpm
{
  namespace filters
  {
    /**
     * The filtered stress of the last filter phase, kept per cell: for
     * every filtered body and active cell, the coefficients beta of the
     * cell's assumed-stress field (or nothing, if the body had no
     * particle there). The filter writes it; the next internal-force
     * computation integrates it (AssumedStressForce). Nothing moves the
     * particles in between, so the field belongs to the particles the
     * cell holds when the force is computed.
     */
    template <int dim>
    class CellStressField
    {
    public:
      static constexpr unsigned int n_beta =
        AssumedStressProjection<dim>::n_beta;

      /// One slot per body that is filtered (@p filtered[b] != 0).
      void
      reinit(const std::vector<char> &filtered, const unsigned int n_cells)
      {
        slot.assign(filtered.size(), -1);
        n_slots = 0;
        for (unsigned int b = 0; b < filtered.size(); ++b)
          if (filtered[b])
            slot[b] = n_slots++;
        n_active = n_cells;
        beta.assign(std::size_t(n_slots) * n_cells * n_beta, 0.);
        set.assign(std::size_t(n_slots) * n_cells, 0);
      }

      /// Forget every cell's field (before a new filter phase).
      void
      clear()
      {
        std::fill(set.begin(), set.end(), 0);
      }

      bool
      filtered(const unsigned int body) const
      {
        return body < slot.size() && slot[body] >= 0;
      }

      /// The coefficients of @p body in cell @p cell, or nullptr.
      const double *
      get(const unsigned int body, const unsigned int cell) const
      {
        if (!filtered(body))
          return nullptr;
        const std::size_t i = std::size_t(slot[body]) * n_active + cell;
        return set[i] ? beta.data() + i * n_beta : nullptr;
      }

      /// Storage for the coefficients of @p body in @p cell, marked set.
      double *
      store(const unsigned int body, const unsigned int cell)
      {
        const std::size_t i = std::size_t(slot[body]) * n_active + cell;
        set[i]              = 1;
        return beta.data() + i * n_beta;
      }

    private:
      std::vector<int>    slot;
      unsigned int        n_slots  = 0;
      unsigned int        n_active = 0;
      std::vector<double> beta;
      std::vector<char>   set;
    };
  } // namespace filters
} // namespace mpm
