#pragma once

namespace mpm
{
  namespace remedies
  {
    /**
     * The settings of a body with `Stress filter = convection correction`,
     * as ConvectionCorrection reads them (Selection::find); the remedy that
     * declares, parses and checks them is registered in
     * convection_correction_remedy.cc.
     */
    struct ConvectionCorrectionSettings
    {
      /// Body force correction: integrate the body force the same way.
      bool body_force = true;
    };
  } // namespace remedies
} // namespace mpm
