#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/shape_functions/q1_cell.h>
#include <mpm/shape_functions/stencil.h>

#include <algorithm>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * GIMP on an axis-parallel box cell: adds to @p s the contributions of
     * the part of the particle box [lower, upper] that lies in @p cell,
     *
     *   S_ip += (1/V) int_{box & cell} N_i dx,
     *   grad S_ip += (1/V) int_{box & cell} grad N_i dx,
     *
     * V the box volume. Summed over every cell the box overlaps this is
     * the exact domain average of the Q1 functions, i.e. uGIMP/cpGIMP. The
     * gradient integral reduces, direction by direction, to the values of
     * N at the box's ends (a cell boundary inside the box adds nothing
     * because N is continuous there).
     */
    template <int dim>
    inline void
    add_gimp_cell(const Q1Cell<dim>        &cell,
                  const unsigned int       *nodes,
                  const dealii::Point<dim> &lower,
                  const dealii::Point<dim> &upper,
                  const double              inverse_volume,
                  Stencil<dim>             &s)
    {
      // Per direction: integrals of (1 - xi) and xi over the overlap, and
      // their end values (for the gradient).
      double I[dim][2], D[dim][2];
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double a  = cell.vertices[0][d];
          const double h  = cell.extent[d];
          const double lo = std::max(a, lower[d]);
          const double hi = std::min(a + h, upper[d]);
          if (!(hi > lo))
            return;
          const double s0 = (lo - a) / h, s1 = (hi - a) / h;
          const double q       = 0.5 * (s1 * s1 - s0 * s0) * h;
          I[d][0]              = (hi - lo) - q;
          I[d][1]              = q;
          const bool lower_end = lo == lower[d], upper_end = hi == upper[d];
          D[d][0] = (upper_end ? 1. - s1 : 0.) - (lower_end ? 1. - s0 : 0.);
          D[d][1] = (upper_end ? s1 : 0.) - (lower_end ? s0 : 0.);
        }
      for (unsigned int v = 0; v < n_q1<dim>; ++v)
        {
          double                 w = inverse_volume;
          dealii::Tensor<1, dim> g;
          for (unsigned int d = 0; d < dim; ++d)
            g[d] = inverse_volume;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int side = (v >> d) & 1;
              w *= I[d][side];
              for (unsigned int e = 0; e < dim; ++e)
                g[e] *= (e == d) ? D[d][side] : I[d][side];
            }
          const unsigned int k = s.n++;
          s.node[k]            = nodes[v];
          s.value[k]           = w;
          s.gradient[k]        = g;
        }
    }
  } // namespace shape_functions
} // namespace mpm
