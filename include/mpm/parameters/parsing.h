#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

/// Reading and writing the texts of parameter-file entries.
namespace mpm
{
  namespace Parameters
  {
    /// Parse "a, b, c" into points and numbers with a message on failure.
    template <int dim>
    dealii::Point<dim>
    parse_point(const std::string &text, const std::string &entry);

    /// "1, 2, 5" into boundary ids (the pattern has checked the range).
    std::vector<dealii::types::boundary_id>
    parse_id_list(const std::string &text);

    /// "4" or "4, 2" into @p n positive integers (one number is repeated);
    /// InputError naming @p entry otherwise.
    std::vector<unsigned int>
    parse_unsigned_list(const std::string &text,
                        const unsigned int n,
                        const std::string &entry);

    /// Default texts of declared entries: "0; 0" for a vector-valued
    /// expression, "v, v" for a point.
    std::string
    default_expression(const int dim);
    std::string
    default_point(const int dim, const double value);
  } // namespace Parameters
} // namespace mpm
