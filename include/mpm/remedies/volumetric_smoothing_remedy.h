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
    };
  } // namespace remedies
} // namespace mpm
