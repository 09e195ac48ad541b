#pragma once

#include <mpm/shape_functions/domain_family.h>

namespace mpm
{
  namespace shape_functions
  {
    /// uGIMP: a box of fixed size about the particle.
    using UGIMPFamily = GIMPFamily<Family::ugimp, DomainMotion::fixed>;

    /// Contiguous GIMP: uGIMP's box with its half-widths stretched by F.
    using CPGIMPFamily =
      GIMPFamily<Family::cpgimp, DomainMotion::follows_deformation>;

    /// CPDI (CPDI1): the parallelogram (parallelepiped) of half-vectors
    /// F r_i, through the Q1 values at its corners.
    using CPDIFamily =
      DomainFamily<Family::cpdi, DomainMotion::follows_deformation>;

    /// CPDI2: the quadrilateral (hexahedron) of corners that are particle
    /// properties (corner slots in the particle layout), moved with the
    /// grid velocity after G2P.
    using CPDI2Family =
      DomainFamily<Family::cpdi2, DomainMotion::tracked_corners>;
  } // namespace shape_functions
} // namespace mpm
