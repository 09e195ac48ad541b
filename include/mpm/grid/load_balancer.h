#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>

#include <vector>

#include <boost/signals2/connection.hpp>

namespace mpm
{
  /// Particles per rank over all ranks.
  struct ParticleBalance
  {
    unsigned long long min = 0, max = 0, total = 0;
    unsigned int       n_ranks = 1;

    /// Largest rank's share over the mean (1 = perfectly balanced).
    double
    imbalance() const
    {
      return total == 0 ? 1. : double(max) * n_ranks / double(total);
    }
  };

  /**
   * Load balancing by particle count, as in deal.II's step-68: every cell
   * weighs `Cell weight + Particle weight * (particles in it)`, and
   * repartition() lets p4est cut the space-filling curve of the cells
   * into pieces of equal weight. The particles travel with their cells,
   * every property included (ParticleHandler's transfer around
   * Triangulation::repartition()); then the grid's nodes, partitioner,
   * cell geometry, face neighbours and boundary constraints are rebuilt
   * (BackgroundGrid::setup). Whoever holds nodal vectors must
   * re-initialize them afterwards; everything else of the step (particle
   * relocation, the domain families, the filters) works from the grid and
   * keeps no state of the partition.
   *
   * Only for the distributed grids of 2D and 3D (1D runs on one rank).
   */
  template <int dim>
  class LoadBalancer
  {
  public:
    /// Connects the cell weights to the triangulation's `weight` signal.
    LoadBalancer(const Parameters::LoadBalancing         &prm,
                 BackgroundGrid<dim>                     &grid,
                 dealii::Particles::ParticleHandler<dim> &particles);
    ~LoadBalancer();

    LoadBalancer(const LoadBalancer &) = delete;
    LoadBalancer &
    operator=(const LoadBalancer &) = delete;

    /**
     * Whether the step with this number starts with a repartition: every
     * `Repartition interval` steps, if the weights are out of balance
     * (unbalanced()). Collective at those steps.
     */
    bool
    due(const unsigned int step) const
    {
      return prm.interval > 0 && step > 0 && step % prm.interval == 0 &&
             unbalanced();
    }

    /**
     * Whether the largest rank's weight is more than 5% above the mean. A
     * repartition rebuilds the whole triangulation from p4est's forest,
     * which costs several steps, so a partition this close to balanced is
     * kept. Collective.
     */
    bool
    unbalanced() const
    {
      return weight_imbalance() > 1.05;
    }

    /// Largest rank's weight over the mean. Collective.
    double
    weight_imbalance() const;

    /// Repartition by weight, move the particles, rebuild the grid's
    /// nodes with the boundary conditions @p bc. Collective.
    void
    repartition(const Parameters::BoundaryConditions &bc);

    /**
     * Until called with nullptr, weigh the cells by these particle counts
     * (indexed by active cell index) instead of the particles the handler
     * holds, and let repartition() move no particles. The set-up balance
     * repartitions this way before the particles exist: no particle data
     * travels, and the set-up's memory peak stays that of the particles.
     */
    void
    weigh_by(const std::vector<unsigned int> *planned_counts)
    {
      planned = planned_counts;
    }

    /// The weight of an active cell with @p n_particles particles.
    unsigned int
    weight(const unsigned int n_particles) const
    {
      return prm.cell_weight + prm.particle_weight * n_particles;
    }

    /// Particles per rank now. Collective.
    static ParticleBalance
    balance(const dealii::Particles::ParticleHandler<dim> &particles,
            const MPI_Comm                                 comm);

    /// Particles per rank if this rank holds @p n_local. Collective.
    static ParticleBalance
    balance(const unsigned long long n_local, const MPI_Comm comm);

    unsigned int n_repartitions = 0;

  private:
    /// Particles in an owned cell: planned or held by the handler.
    unsigned int
    n_particles(
      const typename dealii::Triangulation<dim>::cell_iterator &cell) const
    {
      return planned ? (*planned)[cell->active_cell_index()] :
                       particles.n_particles_in_cell(cell);
    }

    const Parameters::LoadBalancing         &prm;
    BackgroundGrid<dim>                     &grid;
    dealii::Particles::ParticleHandler<dim> &particles;
    boost::signals2::connection              weight_connection;
    const std::vector<unsigned int>         *planned = nullptr;
  };
} // namespace mpm
