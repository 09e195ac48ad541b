#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm/contact/nodal_contact_force.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * A benchmark with an exact solution adds error columns to the
     * statistics file. Its parameters come from the parameter file's
     * `Constants` (so the expressions of the initial state and the exact
     * solution share them). Each benchmark registers itself
     * (benchmark_registry.h) with the constants it reads, the dimensions
     * it supports and its columns.
     */
    template <int dim>
    class Benchmark
    {
    public:
      /// @p columns: the names of the values measure() returns, in order.
      explicit Benchmark(std::vector<std::string> columns)
        : column_names(std::move(columns))
      {}

      virtual ~Benchmark() = default;

      std::vector<std::string>
      columns() const
      {
        return column_names;
      }

      /// Collective: the error measures at @p time.
      virtual std::vector<double>
      measure(dealii::Particles::ParticleHandler<dim> &particles,
              const double                             time,
              const MPI_Comm                           comm) const = 0;

      /// Collective: the measures at @p time, given also the contact
      /// forces of the last step at this rank's nodes (empty without
      /// contact). What the simulator calls; benchmarks that measure the
      /// contact forces override it, the others measure the particles.
      virtual std::vector<double>
      measure_with_contact(
        dealii::Particles::ParticleHandler<dim> &particles,
        const double                             time,
        const MPI_Comm                           comm,
        const contact::NodalContactForces<dim>  &contact_forces) const
      {
        (void)contact_forces;
        return measure(particles, time, comm);
      }

    private:
      std::vector<std::string> column_names;
    };

    /// Create a registered benchmark by name ("none" gives nullptr);
    /// InputError if it does not support @p dim or a constant it needs is
    /// missing or invalid.
    template <int dim>
    std::unique_ptr<Benchmark<dim>>
    create_benchmark(const std::string                   &name,
                     const std::map<std::string, double> &constants);
  } // namespace benchmarks
} // namespace mpm
