#pragma once

#include <mpm/remedies/assumed_stress.h>

namespace mpm
{
  namespace remedies
  {
    /**
     * The settings of a body with `Stress filter = assumed stress`, as
     * StressFilter reads them (Selection::find); the remedy that declares,
     * parses and checks them is registered in assumed_stress_remedy.cc.
     */
    struct AssumedStressSettings
    {
      Metric metric = Metric::mass; ///< Filter metric
      /// Filter field = enriched (else Pian-Sumihara)
      bool enriched = false;
      /// Filtered stress = written back (else force only: the projection
      /// makes the force, the particles keep their own stresses)
      bool write_back = true;
    };
  } // namespace remedies
} // namespace mpm
