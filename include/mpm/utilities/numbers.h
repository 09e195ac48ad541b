#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * A parameter that is a number or an expression of the parameter file's
   * named `Constants`, e.g. `set Young's modulus = E` or `= 2*rho`. So a
   * benchmark states each physical constant once, and a user varies it with
   * one override. The value is checked when it is read (get_number()).
   */
  class NumberOrConstant : public dealii::Patterns::PatternBase
  {
  public:
    bool
    match(const std::string &test_string) const override;

    std::string
    description(const OutputStyle style = Machine) const override;

    std::unique_ptr<dealii::Patterns::PatternBase>
    clone() const override;
  };

  /**
   * While an object of this class lives, get_number() evaluates
   * expressions with these constants.
   */
  class ConstantsScope
  {
  public:
    explicit ConstantsScope(const std::map<std::string, double> &constants);
    ~ConstantsScope();

  private:
    const std::map<std::string, double> *previous;
  };

  /// The value of a NumberOrConstant entry; InputError naming the entry if
  /// it is neither a number nor an expression of the known constants.
  double
  get_number(const dealii::ParameterHandler &prm, const std::string &entry);

  /// @p n such values separated by ';' in one entry.
  std::vector<double>
  get_numbers(const dealii::ParameterHandler &prm,
              const std::string              &entry,
              const unsigned int              n);
} // namespace mpm
