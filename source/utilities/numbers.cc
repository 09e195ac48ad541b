#include <deal.II/base/utilities.h>

#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <cmath>

#include <muParser.h>

namespace mpm
{
  namespace
  {
    const std::map<std::string, double> *current_constants = nullptr;
  }

  bool
  NumberOrConstant::match(const std::string &s) const
  {
    return s.find_first_not_of(" \t") != std::string::npos;
  }

  std::string
  NumberOrConstant::description(const OutputStyle) const
  {
    return "[Number or expression of Constants]";
  }

  std::unique_ptr<dealii::Patterns::PatternBase>
  NumberOrConstant::clone() const
  {
    return std::make_unique<NumberOrConstant>();
  }

  ConstantsScope::ConstantsScope(const std::map<std::string, double> &c)
    : previous(current_constants)
  {
    current_constants = &c;
  }

  ConstantsScope::~ConstantsScope()
  {
    current_constants = previous;
  }

  namespace
  {
    /// The whole text as a plain number (stod also reads "inf" and "nan").
    bool
    plain_number(const std::string &text, double &value)
    {
      try
        {
          std::size_t used = 0;
          value            = std::stod(text, &used);
          return text.find_first_not_of(" \t", used) == std::string::npos;
        }
      catch (...)
        {
          return false;
        }
    }

    /// An expression of pi and the Constants.
    double
    constant_expression(const std::string &entry, const std::string &text)
    {
      try
        {
          mu::Parser p;
          p.DefineConst("pi", M_PI);
          if (current_constants)
            for (const auto &[name, value] : *current_constants)
              p.DefineConst(name, value);
          p.SetExpr(text);
          return p.Eval();
        }
      catch (const mu::Parser::exception_type &e)
        {
          std::string known;
          if (current_constants)
            for (const auto &c : *current_constants)
              known += (known.empty() ? "" : ", ") + c.first;
          throw InputError(entry + " = '" + text +
                           "' is neither a number nor an expression of the "
                           "Constants (" +
                           (known.empty() ? "none defined" : known) +
                           "): " + e.GetMsg());
        }
    }

    /// @p part of entry @p entry's @p text as a number or an expression
    /// of the Constants, finite.
    double
    finite_number(const std::string &entry,
                  const std::string &text,
                  const std::string &part)
    {
      double value;
      if (!plain_number(part, value))
        value = constant_expression(entry, part);
      if (!std::isfinite(value))
        throw InputError(entry + " = '" + text + "' is not finite");
      return value;
    }
  } // namespace

  double
  get_number(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    const std::string text = prm.get(entry);
    return finite_number(entry, text, text);
  }

  std::vector<double>
  get_numbers(const dealii::ParameterHandler &prm,
              const std::string              &entry,
              const unsigned int              n)
  {
    const std::string text  = prm.get(entry);
    const auto        parts = dealii::Utilities::split_string_list(text, ';');
    if (parts.size() != n)
      throw InputError(entry + " = '" + text + "': expected " +
                       std::to_string(n) + " values separated by ';'");
    std::vector<double> values(n);
    for (unsigned int k = 0; k < n; ++k)
      values[k] = finite_number(entry, text, parts[k]);
    return values;
  }
} // namespace mpm
