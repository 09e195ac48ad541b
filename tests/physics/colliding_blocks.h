// The case of family_conservation.cc and stencil_cache.cc: two blocks
// collide in the middle of a 16 x 16 grid, one linear elastic, spinning and
// stressed, the other neo-Hookean; no boundary conditions, no external
// force. The arguments are parameter lines added to the Shape functions and
// Time stepping sections and to body 1.
#pragma once

#include <string>

namespace mpm_test
{
  inline std::string
  colliding_blocks(const std::string &shape_functions,
                   const std::string &time_stepping,
                   const std::string &body_1 = "")
  {
    return R"(
set Number of bodies = 2
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 16
end
subsection Shape functions
)" + shape_functions +
           R"(
end
subsection Time stepping
)" + time_stepping +
           R"(
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.2, 0.3
    set Upper corner = 0.48, 0.62
    set Subdivisions = 4
    set Particles per direction = 2
    set Initial velocity = 1 - 3*(y - 0.46); 3*(x - 0.34)
    set Initial stress = 1e3*x; -2e3*y*x; 500*x*y
    subsection Material
      set Model = linear elastic
      set Density = 1000
    end
  end
  subsection Body 1
    set Lower corner = 0.52, 0.35
    set Upper corner = 0.8, 0.65
    set Subdivisions = 4
    set Particles per direction = 2
    set Initial velocity = -1; 0.2
    subsection Material
      set Model = neo-Hookean
      set Density = 2000
    end
)" + body_1 +
           R"(
  end
end)";
  }
} // namespace mpm_test
