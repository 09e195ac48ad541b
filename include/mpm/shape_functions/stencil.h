#pragma once

#include <deal.II/base/tensor.h>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * The weights of one particle: S_ip and grad S_ip for the nodes i it
     * reaches, as a list that may name a node more than once; sums over
     * the list are what the transfers need. CPDI merges through add()
     * (4 corners often share a cell: 16 corner-node pairs, about 9 nodes,
     * and CPDI ran 10-20% faster for it); GIMP appends one entry per
     * node of each cell of its block (a tensor-product version that
     * merged them had fewer instructions but was slower).
     */
    template <int dim>
    struct Stencil
    {
      /// 3^dim cells of 2^dim nodes (GIMP) >= 2^dim corners of 2^dim (CPDI)
      static constexpr unsigned int capacity = dim == 1 ? 6 :
                                               dim == 2 ? 36 :
                                                          216;

      unsigned int           n = 0;
      unsigned int           node[capacity];
      double                 value[capacity];
      dealii::Tensor<1, dim> gradient[capacity];

      /// Add S and grad S of node @p i (merged if already listed);
      /// returns its entry.
      unsigned int
      add(const unsigned int            i,
          const double                  S,
          const dealii::Tensor<1, dim> &grad_S)
      {
        for (unsigned int k = 0; k < n; ++k)
          if (node[k] == i)
            {
              add_to_entry(k, S, grad_S);
              return k;
            }
        node[n]     = i;
        value[n]    = S;
        gradient[n] = grad_S;
        return n++;
      }

      /// Add S and grad S to entry k, which add() returned.
      void
      add_to_entry(const unsigned int            k,
                   const double                  S,
                   const dealii::Tensor<1, dim> &grad_S)
      {
        value[k] += S;
        gradient[k] += grad_S;
      }
    };
  } // namespace shape_functions
} // namespace mpm
