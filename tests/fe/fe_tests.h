// Helpers for the mpm-fe tests: parameters from parameter-file text, and
// the check lines of ../tests.h.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <mpm/fe_reference/parameters.h>

#include <string>

#include "../tests.h"

namespace fe_test
{
  /// mpm-fe parameters from text (all entries declared, `Dimension` added).
  template <int dim>
  mpm::fe_reference::AllParameters<dim>
  parameters(const std::string &text)
  {
    dealii::ParameterHandler prm;
    mpm::fe_reference::AllParameters<dim>::declare_parameters(prm);
    prm.parse_input_from_string("set Dimension = " + std::to_string(dim) +
                                "\n" + text);
    mpm::fe_reference::AllParameters<dim> p;
    p.file_name = "test.prm";
    p.parse_parameters(prm);
    return p;
  }
} // namespace fe_test
