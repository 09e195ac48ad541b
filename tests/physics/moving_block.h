// A parameter file shared by the tests of prescribed grid motion.
#pragma once

#include <string>

namespace mpm_test
{
  /**
   * One body that fills the grid of the unit square (cube), 4 cells per
   * direction, 2 x 2 (x 2) particles per cell, in plane strain in 2D;
   * quasi-static steps of @p step; the grid faces @p slip are slip walls,
   * the faces @p moving move with @p velocity. @p material is the text of
   * the body's subsection Material. Appended subsections override it.
   */
  template <int dim>
  std::string
  moving_block(const std::string &slip,
               const std::string &moving,
               const std::string &velocity,
               const std::string &step,
               const std::string &material)
  {
    const std::string zero   = dim == 2 ? "0, 0" : "0, 0, 0";
    const std::string corner = dim == 2 ? "1, 1" : "1, 1, 1";
    const std::string cells  = dim == 2 ? "4, 4" : "4, 4, 4";
    return std::string(dim == 2 ? "set Kinematic assumption = plane strain\n" :
                                  "") +
           "subsection Grid\n  set Lower corner = " + zero +
           "\n  set Upper corner = " + corner +
           "\n  set Subdivisions = " + cells +
           "\nend\nsubsection Time stepping\n  set Integrator = quasi-static"
           "\n  set Time step control = fixed\n  set Time step = " +
           step +
           "\nend\nsubsection Boundary conditions\n  set Slip boundary ids = " +
           slip + "\n  set Moving boundary ids = " + moving +
           "\n  set Moving boundary velocity = " + velocity +
           "\nend\nsubsection Output\n  set Directory = results\nend\n"
           "subsection Bodies\n  subsection Body 0\n    set Lower corner = " +
           zero + "\n    set Upper corner = " + corner +
           "\n    set Subdivisions = " + cells + "\n    subsection Material\n" +
           material + "\n    end\n  end\nend\n";
  }
} // namespace mpm_test
