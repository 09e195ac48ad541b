#pragma once

#include <deal.II/base/point.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * A vector-valued muparser expression (muparser used directly: deal.II's
   * FunctionParser exists only for 1 to 3 variables, loads need 2*dim+1) of
   * n_vars spatial variables and, optionally, time. Expressions that use no
   * variable are recognised and evaluated once, so constant loads cost nothing
   * in the time loop. Syntax errors are reported at construction as InputError
   * naming the parameter.
   */
  template <int n_vars>
  class Expression
  {
  public:
    Expression() = default;

    Expression(const std::string                   &text,
               const unsigned int                   n_components,
               const std::string                   &variables,
               const std::map<std::string, double> &constants,
               const bool                           time_dependent,
               const std::string                   &where);

    bool
    is_constant() const
    {
      return constant;
    }

    unsigned int
    n_components() const
    {
      return constant_value.size();
    }

    void
    value(const dealii::Point<n_vars> &p, const double t, double *out) const;

  private:
    bool                constant = true;
    std::vector<double> constant_value;
    struct Parsers;
    std::shared_ptr<Parsers> parsers;
  };

  /// Parse "a=1, b=2.5" into a map; InputError on a malformed entry.
  std::map<std::string, double>
  parse_constants(const std::string &text, const std::string &entry);
} // namespace mpm
