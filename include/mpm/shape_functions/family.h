#pragma once

#include <deal.II/base/tensor.h>

#include <string>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * The shape-function families of the transfers (doc/theory.md,
     * section 5). Standard MPM evaluates the Q1 functions of the cell at
     * the particle; the others average them over the particle's domain,
     * so a particle reaches the nodes of every cell its domain overlaps.
     */
    enum class Family
    {
      standard, ///< Q1 at the particle centre
      ugimp,    ///< box domain of fixed size (uGIMP)
      cpgimp,   ///< box domain following the stretch (contiguous GIMP)
      cpdi,     ///< parallelogram/parallelepiped domain F r_i (CPDI1)
      cpdi2     ///< quadrilateral/hexahedral domain of tracked corners
    };

    /// The names used in parameter files, in the order of Family.
    inline const char *
    family_name(const Family f)
    {
      switch (f)
        {
          case Family::standard:
            return "standard";
          case Family::ugimp:
            return "uGIMP";
          case Family::cpgimp:
            return "cpGIMP";
          case Family::cpdi:
            return "CPDI";
          case Family::cpdi2:
            return "CPDI2";
        }
      return "?";
    }

    /// The prm pattern "standard|uGIMP|cpGIMP|CPDI|CPDI2".
    inline std::string
    family_pattern()
    {
      return "standard|uGIMP|cpGIMP|CPDI|CPDI2";
    }

    inline Family
    parse_family(const std::string &name)
    {
      for (const Family f : {Family::standard,
                             Family::ugimp,
                             Family::cpgimp,
                             Family::cpdi,
                             Family::cpdi2})
        if (name == family_name(f))
          return f;
      return Family::standard; // the pattern has already checked the name
    }

    inline bool
    is_gimp(const Family f)
    {
      return f == Family::ugimp || f == Family::cpgimp;
    }

    /**
     * The weights of one particle: S_ip and grad S_ip for the nodes i it
     * reaches, as a list that may name a node more than once; sums over
     * the list are what the transfers need. CPDI merges through add()
     * (4 corners often share a cell: 16 corner-node pairs, about 9 nodes,
     * and CPDI ran 10-20% faster for it); GIMP appends one entry per
     * node of each cell of its block (a tensor-product version that
     * merged them had fewer instructions but was slower, issue 6).
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

      /// Add S and grad S of node @p i (merged if already listed).
      void
      add(const unsigned int            i,
          const double                  S,
          const dealii::Tensor<1, dim> &grad_S)
      {
        for (unsigned int k = 0; k < n; ++k)
          if (node[k] == i)
            {
              value[k] += S;
              gradient[k] += grad_S;
              return;
            }
        node[n]     = i;
        value[n]    = S;
        gradient[n] = grad_S;
        ++n;
      }
    };
  } // namespace shape_functions
} // namespace mpm
