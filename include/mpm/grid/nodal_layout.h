#pragma once

namespace mpm
{
  /// Components per node of the kinematics vector: velocity at the end of
  /// the step, and its increment over the step (for FLIP).
  template <int dim>
  struct KinematicsLayout
  {
    static constexpr unsigned int velocity     = 0;
    static constexpr unsigned int increment    = dim;
    static constexpr unsigned int n_components = 2 * dim;
  };

  /// Components per node of the P2G vector: mass, momentum (dim),
  /// force (dim). Offsets of each part.
  template <int dim>
  struct P2GLayout
  {
    static constexpr unsigned int mass         = 0;
    static constexpr unsigned int momentum     = 1;
    static constexpr unsigned int force        = 1 + dim;
    static constexpr unsigned int n_components = 1 + 2 * dim;
  };
} // namespace mpm
