#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/contact/nodal_contact_force.h>
#include <mpm/grid/background_grid.h>
#include <mpm/io/atomic_files.h>
#include <mpm/particles/particle_layout.h>

#include <string>
#include <utility>
#include <vector>

namespace mpm
{
  /**
   * Writes what ParaView and scripts read: particles-NNNNN.pvtu and
   * grid-NNNNN.pvtu with particles.pvd / grid.pvd time series, and the
   * particle table particles-NNNNN.csv (all properties, sorted by id,
   * gathered on rank 0), and with contact the nodal contact forces (on the
   * grid, and as contact-NNNNN.csv). Files are written to a temporary name and
   * renamed into place, so an interrupted run never leaves a half-written file.
   */
  template <int dim>
  class OutputWriter
  {
  public:
    OutputWriter(const MPI_Comm                  comm,
                 const std::string              &directory,
                 const ParticleLayout<dim>      &layout,
                 const std::vector<std::string> &history_names);

    void
    write_particles_vtu(dealii::Particles::ParticleHandler<dim> &particles,
                        const double                             time);

    /// The grid fields; with @p contact_forces (contact on) also the
    /// nodal contact force (zero where the law did not act).
    void
    write_grid_vtu(const BackgroundGrid<dim>              &grid,
                   const NodalVector                      &p2g,
                   const NodalVector                      &kinematics,
                   const contact::NodalContactForces<dim> *contact_forces,
                   const double                            time);

    void
    write_particles_csv(dealii::Particles::ParticleHandler<dim> &particles,
                        const double                             time);

    /// contact-NNNNN.csv: the nodes where the contact law acted in the
    /// last step, with their position and contact force, sorted by
    /// position (gathered on rank 0).
    void
    write_contact_csv(const contact::NodalContactForces<dim> &forces);

    /// Number of outputs written so far (the NNNNN of the file names).
    unsigned int
    counter() const
    {
      return n_outputs;
    }
    void
    advance()
    {
      ++n_outputs;
    }

    /// The ParaView series so far: (time, .pvtu file) of every output.
    const std::vector<std::pair<double, std::string>> &
    particle_series() const
    {
      return particle_records;
    }
    const std::vector<std::pair<double, std::string>> &
    grid_series() const
    {
      return grid_records;
    }

    /// Continue after the outputs of a checkpoint.
    void
    restore(const unsigned int                                 n_outputs,
            const std::vector<std::pair<double, std::string>> &particles,
            const std::vector<std::pair<double, std::string>> &grid);

    /// Rewrite particles.pvd and grid.pvd (those that have records) from
    /// the records. Rank 0.
    void
    write_series() const;

  private:
    MPI_Comm                                    comm;
    std::string                                 directory;
    ParticleLayout<dim>                         layout;
    std::vector<std::string>                    history_names;
    unsigned int                                n_outputs = 0;
    std::vector<std::pair<double, std::string>> particle_records, grid_records;
  };

} // namespace mpm
