#pragma once

#include <chrono>

namespace mpm
{
  /// Seconds on a steady clock (for intervals: progress, checkpoints,
  /// throughput).
  inline double
  wall_seconds()
  {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
  }
} // namespace mpm
