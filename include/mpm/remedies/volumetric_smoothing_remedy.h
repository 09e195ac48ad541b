#pragma once

namespace mpm
{
  namespace remedies
  {
    /// Where the volume change that sets a body's pressure is averaged.
    enum class VolumeAverage
    {
      none,
      cell, ///< volume-weighted over the body's particles in the cell
      node  ///< mass-weighted to the grid nodes and interpolated back
    };

    /**
     * The setting of a body with `Volumetric smoothing = cell | node`, as
     * VolumetricSmoothing reads it (Selection::find); the remedies are
     * registered in volumetric_smoothing_remedy.cc.
     */
    struct VolumetricSmoothingSettings
    {
      VolumeAverage average = VolumeAverage::none;
      /// `Particle volume = smoothed` (cell average): a solid's particles
      /// keep the smoothed F_bar and V = J_bar V0 after each step, as a
      /// fluid's always do; false: each keeps its own F and volume.
      bool keeps_smoothed_volume = false;
    };
  } // namespace remedies
} // namespace mpm
