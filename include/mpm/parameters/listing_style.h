#pragma once

#include <deal.II/base/parameter_handler.h>

#include <optional>
#include <string>

namespace mpm
{
  namespace Parameters
  {
    /**
     * The output style of `--print-parameters DIM FORMAT`, shared by mpm
     * and mpm-fe: "prm" is parameter-file syntax, "json" the declaration
     * order in JSON (what scripts/parameter_reference.py reads to generate
     * the manual's parameter reference). Any other format: no value.
     */
    inline std::optional<dealii::ParameterHandler::OutputStyle>
    listing_style(const std::string &format)
    {
      if (format == "prm")
        return dealii::ParameterHandler::PRM;
      if (format == "json")
        return dealii::ParameterHandler::OutputStyle(
          dealii::ParameterHandler::JSON |
          dealii::ParameterHandler::KeepDeclarationOrder);
      return std::nullopt;
    }
  } // namespace Parameters
} // namespace mpm
