#pragma once

#include <stdexcept>
#include <string>

namespace mpm
{
  /**
   * An error the user can fix: bad input, an unstable setting, a particle
   * that left the grid. main() prints its message and exits with status 1;
   * nothing else is written.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * An error found while the simulation runs (NaN, a particle outside the
   * grid). Output written so far is kept; main() exits with status 2.
   */
  class RuntimeError : public std::runtime_error
  {
  public:
    explicit RuntimeError(const std::string &message)
      : std::runtime_error(message)
    {}
  };
} // namespace mpm
