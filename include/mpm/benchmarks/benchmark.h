#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/particles/particle_handler.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * A benchmark with an exact solution adds error columns to the
     * statistics file. Its parameters come from the parameter file's
     * `Constants` (so the expressions of the initial state and the exact
     * solution share them).
     */
    template <int dim>
    class Benchmark
    {
    public:
      virtual ~Benchmark() = default;

      virtual std::vector<std::string>
      columns() const = 0;

      /// Collective: the error measures at @p time.
      virtual std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const = 0;
    };

    /// Create a benchmark by name ("none" gives nullptr); InputError lists
    /// the known names or a missing constant.
    template <int dim>
    std::unique_ptr<Benchmark<dim>>
    create_benchmark(const std::string                   &name,
                     const std::map<std::string, double> &constants);
  } // namespace benchmarks
} // namespace mpm
