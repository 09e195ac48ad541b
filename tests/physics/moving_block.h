// A parameter file shared by the tests of prescribed grid motion.
#pragma once

#include <cctype>
#include <string>

namespace mpm_test
{
  /**
   * One body that fills the grid of the unit square (cube), 4 cells per
   * direction, 2 x 2 (x 2) particles per cell, in plane strain in 2D;
   * quasi-static steps of @p step; the grid faces @p slip are slip walls,
   * the faces @p moving move with @p velocity. The body's material is
   * @p model ("linear elastic" or "neo-Hookean") with E = 1e6 Pa,
   * nu = 0.3 and rho = 1000 kg/m^3. Appended subsections override the
   * text.
   */
  template <int dim>
  std::string
  moving_block(const std::string &slip,
               const std::string &moving,
               const std::string &velocity,
               const std::string &step,
               const std::string &model)
  {
    // the model's subsection: its name with the first letter upper-case
    std::string subsection   = model;
    subsection[0]            = static_cast<char>(std::toupper(subsection[0]));
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
           "\n    set Subdivisions = " + cells +
           "\n    subsection Material\n      set Model = " + model +
           "\n      set Density = 1000\n      subsection " + subsection +
           "\n        set Young's modulus = 1e6\n        set Poisson's "
           "ratio = 0.3\n      end\n    end\n  end\nend\n";
  }

  /**
   * moving_block()'s 2D block of @p model in the simple shear flow
   * v = (0.05 y, 0) that its four faces impose and that it starts with,
   * by Newmark steps of 0.01.
   */
  inline std::string
  newmark_shear_block(const std::string &model)
  {
    return moving_block<2>("", "0, 1, 2, 3", "0.05*y; 0", "0.01", model) +
           "subsection Time stepping\n  set Integrator = Newmark\nend\n"
           "subsection Bodies\n  subsection Body 0\n    set Initial "
           "velocity = 0.05*y; 0\n  end\nend\n";
  }
} // namespace mpm_test
