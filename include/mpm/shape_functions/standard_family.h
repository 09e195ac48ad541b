#pragma once

#include <mpm/shape_functions/cell_q1_weights.h>
#include <mpm/shape_functions/family_traits.h>

namespace mpm
{
  namespace shape_functions
  {
    /// Standard MPM: the Q1 functions of the particle's cell, evaluated at
    /// the particle.
    struct StandardFamily
    {
      static constexpr Family id = Family::standard;

      template <int dim>
      using Weights = CellQ1Weights<dim>;

      static constexpr bool has_domains                = false;
      static constexpr bool needs_axis_parallel_grid   = false;
      static constexpr bool domain_follows_deformation = false;
      static constexpr bool tracks_corners             = false;
      /// C_p = sum_i v_i grad N_ip grows like 1/xi where a particle is
      /// a fraction xi into a cell whose far nodes only it reaches, and
      /// the step is unstable (doc/theory/apic.md).
      static constexpr bool allows_apic = false;
      /// The 1D convection correction is derived for this family.
    };
  } // namespace shape_functions
} // namespace mpm
