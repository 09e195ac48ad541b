#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <mpm/grid/load_balancer.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  using namespace dealii;

  namespace Parameters
  {
    void
    LoadBalancing::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load balancing");
      prm.declare_entry(
        "Balance at set-up",
        "true",
        Patterns::Bool(),
        "Repartition the grid among the MPI ranks by weight once the "
        "particles are placed (or read from a checkpoint), if the largest "
        "rank's weight is more than 5% above the mean. p4est first gives "
        "every rank the same number of cells, so a body that fills only "
        "part of the grid leaves some ranks with more particles. Runs on "
        "one rank and 1D runs are never repartitioned.");
      prm.declare_entry(
        "Repartition interval (steps)",
        "0",
        Patterns::Integer(0),
        "Check the balance every this many steps and repartition if the "
        "largest rank's weight is more than 5% above the mean (0: never "
        "after set-up). A cell weighs Cell weight + Particle weight x its "
        "particles; the particles move with their cells, unchanged. A "
        "repartition of 410 000 cells took about as long as ten steps "
        "(doc/performance.md), so a body that moves less than a cell per "
        "step needs a check only every 50 to 100 steps. 2D and 3D only: in "
        "1D a value above 0 is refused (1D runs on one rank).");
      prm.declare_entry("Cell weight",
                        "1",
                        Patterns::Integer(1),
                        "Work of a cell without particles, in the units of "
                        "Particle weight (at least 1: p4est needs positive "
                        "weights).");
      prm.declare_entry("Particle weight",
                        "10",
                        Patterns::Integer(0),
                        "Work of one particle, in the units of Cell weight. "
                        "With the defaults a cell with 4 particles weighs "
                        "41: the particles dominate, and empty cells still "
                        "count a little.");
      prm.leave_subsection();
    }

    void
    LoadBalancing::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load balancing");
      at_setup        = prm.get_bool("Balance at set-up");
      interval        = prm.get_integer("Repartition interval (steps)");
      cell_weight     = prm.get_integer("Cell weight");
      particle_weight = prm.get_integer("Particle weight");
      prm.leave_subsection();
    }
  } // namespace Parameters

  template <int dim>
  LoadBalancer<dim>::LoadBalancer(const Parameters::LoadBalancing &prm,
                                  BackgroundGrid<dim>             &grid,
                                  Particles::ParticleHandler<dim> &particles)
    : prm(prm)
    , grid(grid)
    , particles(particles)
  {
    if constexpr (dim == 1)
      throw InputError(
        "Load balancing/Repartition interval (steps) > 0 needs a grid "
        "distributed among MPI ranks, and 1D runs on one rank; set it to 0");
    else
      {
        using Tria        = parallel::distributed::Triangulation<dim>;
        weight_connection = grid.triangulation().signals.weight.connect(
          [this](const typename Triangulation<dim>::cell_iterator &cell,
                 const typename Triangulation<dim>::CellStatus     status)
            -> unsigned int {
            // The grid is never refined or coarsened: every cell persists.
            // The other states are handled for completeness.
            unsigned int n = 0;
            switch (status)
              {
                case Tria::CELL_PERSIST:
                  n = this->n_particles(cell);
                  break;
                case Tria::CELL_COARSEN:
                  for (const auto &child : cell->child_iterators())
                    n += this->n_particles(child);
                  break;
                default: // CELL_REFINE: the parent's particles are unknown
                  break;
              }
            return weight(n);
          });
      }
  }

  template <int dim>
  LoadBalancer<dim>::~LoadBalancer()
  {
    weight_connection.disconnect();
  }

  template <int dim>
  void
  LoadBalancer<dim>::repartition(const Parameters::BoundaryConditions &bc)
  {
    if constexpr (dim > 1)
      {
        auto &tria = dynamic_cast<parallel::distributed::Triangulation<dim> &>(
          grid.triangulation());
        // The particles are attached to their cells, go where the cells go
        // and come back with location, reference location, id and every
        // property unchanged. Planned counts: no particles exist yet.
        if (!planned)
          particles.prepare_for_coarsening_and_refinement();
        tria.repartition();
        if (!planned)
          particles.unpack_after_coarsening_and_refinement();
        // Nodes, ghost layer, cell caches and constraints of the new
        // partition (the mapping is kept: the particle handler holds it).
        grid.setup(bc);
        if (!planned)
          particles.update_cached_numbers();
        grid.particles_changed_cells();
        ++n_repartitions;
      }
    (void)bc;
  }

  template <int dim>
  double
  LoadBalancer<dim>::weight_imbalance() const
  {
    unsigned long long local = 0;
    for (const auto &cell : grid.owned_cells())
      local += weight(n_particles(cell));
    const MPI_Comm comm = grid.triangulation().get_communicator();
    const double   mean = Utilities::MPI::sum(local, comm) /
                        double(Utilities::MPI::n_mpi_processes(comm));
    return mean > 0 ? Utilities::MPI::max(local, comm) / mean : 1.;
  }

  template <int dim>
  ParticleBalance
  LoadBalancer<dim>::balance(const Particles::ParticleHandler<dim> &particles,
                             const MPI_Comm                         comm)
  {
    return balance(particles.n_locally_owned_particles(), comm);
  }

  template <int dim>
  ParticleBalance
  LoadBalancer<dim>::balance(const unsigned long long n, const MPI_Comm comm)
  {
    ParticleBalance b;
    b.min     = Utilities::MPI::min(n, comm);
    b.max     = Utilities::MPI::max(n, comm);
    b.total   = Utilities::MPI::sum(n, comm);
    b.n_ranks = Utilities::MPI::n_mpi_processes(comm);
    return b;
  }

  template class LoadBalancer<1>;
  template class LoadBalancer<2>;
  template class LoadBalancer<3>;
} // namespace mpm
