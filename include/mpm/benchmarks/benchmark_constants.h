#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * One physical constant a benchmark reads from the parameter file's
     * `Constants`. Made by the functions below, which say whether it must
     * be given and what a valid value is.
     */
    struct ConstantDeclaration
    {
      std::string name;
      std::string meaning;
      /// The default as the documentation states it ("0", "a/10"); empty
      /// if the constant must be given.
      std::string default_value;
      /// What a valid value satisfies, as the message states it ("> 0");
      /// empty if any value is valid.
      std::string condition;
      /// Why the condition is needed, for the message.
      std::string                 reason;
      std::function<bool(double)> is_valid;
    };

    /// A constant that must be given; any value is valid.
    ConstantDeclaration
    required_constant(const std::string &name, const std::string &meaning);

    /// A constant that may be left out; the benchmark then uses
    /// @p default_value (how the documentation states the default).
    ConstantDeclaration
    optional_constant(const std::string &name,
                      const std::string &meaning,
                      const std::string &default_value);

    /// A constant that must be given and be > 0, because of @p reason.
    ConstantDeclaration
    positive_constant(const std::string &name,
                      const std::string &meaning,
                      const std::string &reason);

    /// A constant that must be given and be != 0, because of @p reason.
    ConstantDeclaration
    nonzero_constant(const std::string &name,
                     const std::string &meaning,
                     const std::string &reason);

    /**
     * The constants of one benchmark, checked against its declarations
     * when constructed: InputError names the benchmark and the first
     * missing or invalid constant. Asking for a constant that was not
     * declared (or reading an optional one without its default) is a
     * programming error (std::logic_error).
     */
    class BenchmarkConstants
    {
    public:
      BenchmarkConstants(const std::string                      &benchmark,
                         const std::vector<ConstantDeclaration> &declared,
                         const std::map<std::string, double>    &constants);

      /// The value of a constant that must be given.
      double
      operator[](const std::string &name) const;

      /// The value of an optional constant, @p default_value if not given.
      double
      value_or(const std::string &name, const double default_value) const;

    private:
      const ConstantDeclaration &
      declaration(const std::string &name) const;

      std::string                      benchmark;
      std::vector<ConstantDeclaration> declared;
      std::map<std::string, double>    given;
    };
  } // namespace benchmarks
} // namespace mpm
