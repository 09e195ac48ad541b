#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/utilities/input_error.h>

#include <map>
#include <stdexcept>

namespace mpm
{
  namespace benchmarks
  {
    namespace
    {
      // A function-local static, so that registrations from other
      // translation units work whatever the order of static
      // initialisation. Keyed by name, which keeps it sorted.
      std::map<std::string, BenchmarkEntry> &
      registry()
      {
        static std::map<std::string, BenchmarkEntry> entries;
        return entries;
      }

      /// "none", then the registered names, with @p separator between.
      std::string
      names_joined(const std::string &separator)
      {
        std::string names = "none";
        for (const auto &name_and_entry : registry())
          names += separator + name_and_entry.first;
        return names;
      }

      /// "1D/2D/3D" in the documentation.
      std::string
      dimensions_text(const std::vector<unsigned int> &dimensions)
      {
        std::string text;
        for (const unsigned int d : dimensions)
          text += (text.empty() ? "" : "/") + std::to_string(d) + "D";
        return text;
      }

      /// "Dimension = 2" or "Dimension 2 or 3" in a message.
      std::string
      needed_dimension(const std::vector<unsigned int> &dimensions)
      {
        if (dimensions.size() == 1)
          return "Dimension = " + std::to_string(dimensions[0]);
        std::string text = "Dimension ";
        for (unsigned int i = 0; i < dimensions.size(); ++i)
          text += (i == 0                     ? "" :
                   i + 1 == dimensions.size() ? " or " :
                                                ", ") +
                  std::to_string(dimensions[i]);
        return text;
      }

      /// "L, E, x0 (default 0)" in the documentation.
      std::string
      constants_text(const std::vector<ConstantDeclaration> &constants)
      {
        std::string text;
        for (const auto &constant : constants)
          text += (text.empty() ? "" : ", ") + constant.name +
                  (constant.default_value.empty() ?
                     "" :
                     " (default " + constant.default_value + ")");
        return text;
      }
    } // namespace

    bool
    add_benchmark(const BenchmarkEntry &entry)
    {
      // Two benchmarks with one name is a programming error; failing
      // loudly at start-up is better than silently picking one of them.
      const auto &name = entry.declaration.name;
      if (name.empty() || name == "none" || entry.dimensions.empty())
        throw std::logic_error("Invalid benchmark registration '" + name + "'");
      if (!registry().emplace(name, entry).second)
        throw std::logic_error("Benchmark '" + name + "' is registered twice");
      return true;
    }

    std::string
    benchmark_names_pattern()
    {
      return names_joined("|");
    }

    std::string
    benchmark_list()
    {
      std::string list;
      for (const auto &[name, entry] : registry())
        list += "\n" + name + " (" + dimensions_text(entry.dimensions) + "; " +
                constants_text(entry.declaration.constants) +
                "): " + entry.declaration.summary;
      return list;
    }

    template <int dim>
    std::unique_ptr<Benchmark<dim>>
    create_benchmark(const std::string                   &name,
                     const std::map<std::string, double> &constants)
    {
      if (name == "none" || name.empty())
        return nullptr;
      const auto it = registry().find(name);
      // The Selection pattern of the entry normally prevents this.
      if (it == registry().end())
        throw InputError("Benchmark = '" + name +
                         "' is unknown; known: " + names_joined(", "));
      const BenchmarkEntry &entry  = it->second;
      const auto           &create = std::get<dim - 1>(entry.factories);
      if (!create)
        throw InputError("Benchmark = " + name + " needs " +
                         needed_dimension(entry.dimensions));
      return create(
        BenchmarkConstants(name, entry.declaration.constants, constants));
    }

    template std::unique_ptr<Benchmark<1>>
    create_benchmark<1>(const std::string &,
                        const std::map<std::string, double> &);
    template std::unique_ptr<Benchmark<2>>
    create_benchmark<2>(const std::string &,
                        const std::map<std::string, double> &);
    template std::unique_ptr<Benchmark<3>>
    create_benchmark<3>(const std::string &,
                        const std::map<std::string, double> &);
  } // namespace benchmarks
} // namespace mpm
