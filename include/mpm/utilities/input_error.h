#pragma once

#include <deal.II/base/exceptions.h>

#include <stdexcept>
#include <string>

namespace mpm
{
  /**
   * An error the user can fix: bad input, an unstable setting, a particle
   * that left the grid. main() prints its message and exits with status 1;
   * nothing else is written.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * The useful part of a deal.II exception text: what follows
   * "Additional information:", without the stack trace, on one paragraph.
   */
  inline std::string
  clean_dealii_message(std::string msg)
  {
    const auto info = msg.find("Additional information:");
    if (info != std::string::npos)
      msg = msg.substr(info + 23);
    const auto trace = msg.find("Stacktrace:");
    if (trace != std::string::npos)
      msg = msg.substr(0, trace);
    std::string out;
    for (const char c : msg)
      if (c == '\n' || c == ' ')
        {
          if (!out.empty() && out.back() != ' ')
            out += ' ';
        }
      else
        out += c;
    while (!out.empty() && out.back() == ' ')
      out.pop_back();
    return out;
  }

  /**
   * Run @p parse (a parse_parameters() call): a deal.II exception from it
   * is a value that its pattern accepts but get_double() cannot represent
   * (1e-320 underflows to a denormal, 1e400 overflows), an InputError
   * naming the entry.
   */
  template <typename Parse>
  void
  parse_with_range_check(const Parse &parse)
  {
    try
      {
        parse();
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError(clean_dealii_message(e.what()) +
                         " (a number outside the range of double precision, "
                         "about 2.2e-308 to 1.8e308?)");
      }
  }

  /**
   * An error found while the simulation runs (NaN, a particle outside the
   * grid). Output written so far is kept; main() exits with status 2.
   */
  class RuntimeError : public std::runtime_error
  {
  public:
    explicit RuntimeError(const std::string &message)
      : std::runtime_error(message)
    {}
  };
} // namespace mpm
