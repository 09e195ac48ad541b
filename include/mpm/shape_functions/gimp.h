#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/shape_functions/family.h>
#include <mpm/shape_functions/q1_cell.h>

#include <algorithm>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * GIMP (uGIMP, cpGIMP) on axis-parallel box cells: the exact average
     * of the Q1 functions over the particle box, V its volume. Box and Q1
     * functions are both products over the directions, so the average is
     * a product of 1D integrals of hat functions,
     *
     *   S_ip = (1/V) prod_d W_d(j_d),
     *   d S_ip / dx_e = (1/V) G_e(j_e) prod_{d != e} W_d(j_d),
     *
     * and each direction is integrated once instead of once per cell of
     * the block (shared nodes come out merged; the per-cell sums of the
     * first version cost 17% of a uGIMP run). Along direction d the
     * box reaches the cell below (offset -1), the particle's cell (0) and
     * the cell above (+1); the 1D nodes are numbered j = 0..3 from below,
     * the cell with offset o having nodes o + 1 and o + 2.
     */
    struct GimpFactors1D
    {
      double W[4] = {}; ///< int over the box of the 1D hat of node j
      double G[4] = {}; ///< its derivative integrated: end values

      /**
       * Add the part of the box [lower, upper] in the cell [a, a + h] with
       * 1D offset o: the integrals of (1 - xi) and xi over the overlap, and
       * their values at the box's ends inside the cell (a cell boundary
       * inside the box adds nothing to G: the hat is continuous there).
       */
      void
      add_cell(const int    o,
               const double a,
               const double h,
               const double lower,
               const double upper)
      {
        const double lo = std::max(a, lower), hi = std::min(a + h, upper);
        if (!(hi > lo))
          return;
        const double s0 = (lo - a) / h, s1 = (hi - a) / h;
        const double q         = 0.5 * (s1 * s1 - s0 * s0) * h;
        const bool   lower_end = lo == lower, upper_end = hi == upper;
        W[o + 1] += (hi - lo) - q;
        W[o + 2] += q;
        G[o + 1] += (upper_end ? 1. - s1 : 0.) - (lower_end ? 1. - s0 : 0.);
        G[o + 2] += (upper_end ? s1 : 0.) - (lower_end ? s0 : 0.);
      }
    };
  } // namespace shape_functions
} // namespace mpm
