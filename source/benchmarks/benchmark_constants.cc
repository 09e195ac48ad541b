#include <mpm/benchmarks/benchmark_constants.h>
#include <mpm/utilities/input_error.h>

#include <sstream>
#include <stdexcept>

namespace mpm
{
  namespace benchmarks
  {
    ConstantDeclaration
    required_constant(const std::string &name, const std::string &meaning)
    {
      return {name, meaning, "", "", "", [](const double) { return true; }};
    }

    ConstantDeclaration
    optional_constant(const std::string &name,
                      const std::string &meaning,
                      const std::string &default_value)
    {
      ConstantDeclaration constant = required_constant(name, meaning);
      constant.default_value       = default_value;
      return constant;
    }

    ConstantDeclaration
    positive_constant(const std::string &name,
                      const std::string &meaning,
                      const std::string &reason)
    {
      return {name, meaning, "", "> 0", reason, [](const double v) {
                return v > 0;
              }};
    }

    ConstantDeclaration
    nonzero_constant(const std::string &name,
                     const std::string &meaning,
                     const std::string &reason)
    {
      return {name, meaning, "", "!= 0", reason, [](const double v) {
                return v != 0;
              }};
    }

    BenchmarkConstants::BenchmarkConstants(
      const std::string                      &benchmark,
      const std::vector<ConstantDeclaration> &declared,
      const std::map<std::string, double>    &constants)
      : benchmark(benchmark)
      , declared(declared)
    {
      for (const auto &constant : declared)
        {
          const auto it = constants.find(constant.name);
          if (it == constants.end())
            {
              if (constant.default_value.empty())
                throw InputError("Benchmark = " + benchmark +
                                 " needs the constant '" + constant.name +
                                 "' (" + constant.meaning +
                                 ") in the entry Constants");
              continue;
            }
          if (!constant.is_valid(it->second))
            {
              std::ostringstream value;
              value << it->second;
              throw InputError("Benchmark = " + benchmark +
                               " needs the constant " + constant.name + " " +
                               constant.condition + " (" + constant.reason +
                               "), not " + constant.name + " = " + value.str());
            }
          given.insert(*it);
        }
    }

    const ConstantDeclaration &
    BenchmarkConstants::declaration(const std::string &name) const
    {
      for (const auto &constant : declared)
        if (constant.name == name)
          return constant;
      throw std::logic_error("Benchmark " + benchmark +
                             " reads the constant '" + name +
                             "' it does not declare");
    }

    double
    BenchmarkConstants::operator[](const std::string &name) const
    {
      if (!declaration(name).default_value.empty())
        throw std::logic_error("Benchmark " + benchmark +
                               " reads the optional constant '" + name +
                               "' without its default");
      return given.at(name);
    }

    double
    BenchmarkConstants::value_or(const std::string &name,
                                 const double       default_value) const
    {
      if (declaration(name).default_value.empty())
        throw std::logic_error("Benchmark " + benchmark +
                               " gives the constant '" + name +
                               "' a default it does not declare");
      const auto it = given.find(name);
      return it == given.end() ? default_value : it->second;
    }
  } // namespace benchmarks
} // namespace mpm
