// A rigid platen of prescribed motion pressing a linear elastic block
// (plane strain, E = 1e6, 1 m x 1 m on a grid of h = 0.25) between slip
// walls, two quasi-static steps of 0.25: for rigid_platen and
// cell_pressure_preconditioner.
#pragma once

#include <string>

namespace platen_block
{
  /// The parameter text: the block's Poisson's ratio @p nu (as written),
  /// the platen's vertical velocity @p velocity (an expression of t), and
  /// @p block_text added to the block's subsection.
  inline std::string
  parameters(const std::string &nu,
             const std::string &velocity,
             const std::string &block_text = "")
  {
    return R"(
set Number of bodies = 2
set Kinematic assumption = plane strain
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1.5
  set Subdivisions = 4, 6
end
subsection Time stepping
  set Integrator = quasi-static
  set Time step control = fixed
  set Time step = 0.25
  set End time = 0.5
end
subsection Boundary conditions
  set Slip boundary ids = 0, 1, 2
end
subsection Output
  set Directory = results
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0, 0
    set Upper corner = 1, 1
    set Subdivisions = 4, 4
    subsection Material
      set Model = linear elastic
      set Density = 1000
      subsection Linear elastic
        set Young's modulus = 1e6
        set Poisson's ratio = )" +
           nu + R"(
      end
    end
)" + block_text +
           R"(  end
  subsection Body 1
    set Lower corner = 0, 1
    set Upper corner = 1, 1.25
    set Subdivisions = 4, 1
    set Prescribed velocity = 0; )" +
           velocity + R"(
    set Prescribed directions = y
    subsection Material
      set Model = rigid
      set Density = 1000
    end
  end
end)";
  }
} // namespace platen_block
