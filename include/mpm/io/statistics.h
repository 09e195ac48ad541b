#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/particles/body.h>

#include <fstream>
#include <string>
#include <vector>

namespace mpm
{
  /// Global sums over all particles, for the statistics file and tests.
  template <int dim>
  struct GlobalStatistics
  {
    unsigned long long n_particles         = 0;
    double             mass                = 0;
    double             kinetic_energy      = 0;
    double             strain_energy       = 0;
    double             momentum[dim]       = {};
    double             angular_momentum[3] = {}; // about the origin
    double             removed_mass        = 0;
    /// Work of the constant body forces and tractions since the start,
    /// sum of (m b + A t) . (x - X); NaN if a load varies.
    double load_work = 0;

    /// Compute on every rank (collective).
    void
    compute(dealii::Particles::ParticleHandler<dim> &particles,
            const std::vector<Body<dim>>            &bodies,
            const MPI_Comm                           comm);
  };

  /**
   * The statistics file: one row per output time, whitespace separated,
   * with a header line naming every column: pandas.read_csv(f,
   * sep=r"\s+") and gnuplot (plot f using 'time':'kinetic_energy') read
   * it as it is.
   */
  template <int dim>
  class StatisticsFile
  {
  public:
    void
    open(const std::string              &file_name,
         const std::vector<std::string> &extra_columns);

    /// Continue a run: replace the file by @p content (the file as it was
    /// at a checkpoint, header included) and append to it.
    void
    resume(const std::string &file_name, const std::string &content);

    void
    write_row(const double                 time,
              const unsigned int           step,
              const double                 dt,
              const GlobalStatistics<dim> &s,
              const std::vector<double>   &extra);

    static std::vector<std::string>
    column_names(const std::vector<std::string> &extra_columns);

  private:
    std::ofstream out;
  };
} // namespace mpm
