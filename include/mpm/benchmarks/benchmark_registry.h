#pragma once

#include <mpm/benchmarks/benchmark.h>
#include <mpm/benchmarks/benchmark_constants.h>

#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace mpm
{
  namespace benchmarks
  {
    /// What a benchmark states about itself besides its dimensions.
    struct BenchmarkDeclaration
    {
      std::string name;
      /// One line for the documentation of the entry Benchmark.
      std::string summary;
      /// In the order they are checked.
      std::vector<ConstantDeclaration> constants;
      /// The names of the values its measure() returns.
      std::vector<std::string> columns;
    };

    template <int dim>
    using BenchmarkFactory = std::function<std::unique_ptr<Benchmark<dim>>(
      const BenchmarkConstants &)>;

    /**
     * Registry of benchmarks. A benchmark registers itself once with
     * MPM_REGISTER_BENCHMARK in its source file; the parameter file
     * chooses it by name in `set Benchmark = ...`.
     */
    struct BenchmarkEntry
    {
      BenchmarkDeclaration      declaration;
      std::vector<unsigned int> dimensions;
      /// One per dimension 1, 2, 3; empty where it is not supported.
      std::tuple<BenchmarkFactory<1>, BenchmarkFactory<2>, BenchmarkFactory<3>>
        factories;
    };

    /// Add a benchmark to the registry (called at static initialisation).
    bool
    add_benchmark(const BenchmarkEntry &entry);

    /// "none|name|name...": the values of the entry Benchmark.
    std::string
    benchmark_names_pattern();

    /// One line per registered benchmark: name, dimensions, constants and
    /// summary, for the documentation of the entry Benchmark.
    std::string
    benchmark_list();

    /**
     * Register @p Class (a class template of the dimension constructible
     * from BenchmarkConstants) for the dimensions @p dims.
     */
    template <template <int> class Class, int... dims>
    bool
    register_benchmark(const BenchmarkDeclaration &declaration)
    {
      static_assert(sizeof...(dims) > 0 && ((dims >= 1 && dims <= 3) && ...),
                    "a benchmark supports some of the dimensions 1, 2, 3");
      BenchmarkEntry entry{declaration, {dims...}, {}};
      ((std::get<dims - 1>(entry.factories) =
          [](const BenchmarkConstants &constants)
          -> std::unique_ptr<Benchmark<dims>> {
         return std::make_unique<Class<dims>>(constants);
       }),
       ...);
      return add_benchmark(entry);
    }
  } // namespace benchmarks
} // namespace mpm

/**
 * Register the benchmark class template @p classname, declared by the
 * BenchmarkDeclaration @p declaration, for the dimensions that follow
 * (e.g. `2, 3`). Used in namespace mpm::benchmarks of the benchmark's
 * source file, after the class.
 */
#define MPM_REGISTER_BENCHMARK(classname, declaration, ...)        \
  namespace                                                        \
  {                                                                \
    const bool registered_##classname =                            \
      mpm::benchmarks::register_benchmark<classname, __VA_ARGS__>( \
        declaration);                                              \
  }
