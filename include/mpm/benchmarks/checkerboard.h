#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/particles/particle_handler.h>

#include <functional>

namespace mpm
{
  namespace benchmarks
  {
    /**
     * Collective: the RMS over all pairs of face-neighbouring background
     * cells holding particles of the jump of the cell's volume-averaged
     * @p error (sum_p e_p V_p / sum_p V_p over the cell's particles). A
     * smooth error has small jumps; one that oscillates from cell to cell
     * (a pressure checkerboard) does not. 0 if no pair exists.
     */
    template <int dim>
    double
    checkerboard(dealii::Particles::ParticleHandler<dim> &particles,
                 const std::function<double(const double *properties)> &error,
                 const MPI_Comm                                         comm);

    /**
     * The same for a quantity of the properties and the current position
     * of the particle (e.g. the pressure less a hydrostatic gradient).
     */
    template <int dim>
    double
    checkerboard_with_position(
      dealii::Particles::ParticleHandler<dim> &particles,
      const std::function<double(const double             *properties,
                                 const dealii::Point<dim> &location)> &error,
      const MPI_Comm                                                   comm);
  } // namespace benchmarks
} // namespace mpm
