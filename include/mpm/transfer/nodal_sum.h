#pragma once

#include <mpm/shape_functions/family_traits.h>

#include <type_traits>

namespace mpm
{
  namespace transfer
  {
    /**
     * Per-cell summation (standard MPM): the particles of a cell add into
     * a buffer over its nodes (stencil entry k is vertex k), and the
     * buffer goes to the nodal vector once, at the end of the cell. A
     * non-null @p marks (ActiveNodes) gets the nodes added to.
     */
    template <unsigned int n_nodes, unsigned int n_values>
    class CellSum
    {
    public:
      CellSum(double              *nodal,
              const unsigned int   stride,
              unsigned char *const marks = nullptr)
        : nodal(nodal)
        , stride(stride)
        , marks(marks)
      {}

      /// Where entry @p k of the stencil adds its values.
      template <typename Weights>
      double *
      slot(const Weights &, const unsigned int k)
      {
        return local[k];
      }

      /// Add components [first, last) of the buffer to the nodes.
      template <typename Weights>
      void
      finish(const Weights     &weights,
             const unsigned int first,
             const unsigned int last)
      {
        for (unsigned int v = 0; v < n_nodes; ++v)
          {
            if (marks)
              marks[weights.node(v)] = 1;
            double *node = nodal + weights.node(v) * stride;
            for (unsigned int c = first; c < last; ++c)
              node[c] += local[v][c];
          }
      }

    private:
      double *const        nodal;
      const unsigned int   stride;
      unsigned char *const marks;
      double               local[n_nodes][n_values] = {};
    };

    /// Per-entry summation (the particle-domain families): every stencil
    /// entry adds straight into its node.
    class EntrySum
    {
    public:
      EntrySum(double              *nodal,
               const unsigned int   stride,
               unsigned char *const marks = nullptr)
        : nodal(nodal)
        , stride(stride)
        , marks(marks)
      {}

      template <typename Weights>
      double *
      slot(const Weights &weights, const unsigned int k)
      {
        const unsigned int node = weights.node(k);
        if (marks)
          marks[node] = 1;
        return nodal + node * stride;
      }

      template <typename Weights>
      void
      finish(const Weights &, const unsigned int, const unsigned int)
      {}

    private:
      double *const        nodal;
      const unsigned int   stride;
      unsigned char *const marks;
    };

    /// The summation of a cell's contributions that the family @p Family
    /// asks for, over values of @p n_values components per node.
    template <typename Family, int dim, unsigned int n_values>
    using NodalSum = std::conditional_t<
      Family::template Weights<dim>::summation ==
        shape_functions::NodalSummation::per_cell,
      CellSum<Family::template Weights<dim>::n_entries, n_values>,
      EntrySum>;
  } // namespace transfer
} // namespace mpm
