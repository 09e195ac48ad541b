#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/particles/data_out.h>

#include <mpm/contact/gather_contact_forces.h>
#include <mpm/grid/grid_update.h>
#include <mpm/io/output_writer.h>
#include <mpm/transfer/particle_to_grid.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace mpm
{
  namespace
  {
    /// Rows of @p row values from every rank, gathered on rank 0 and
    /// sorted by their first @p key values (empty on the other ranks).
    struct GatheredRows
    {
      GatheredRows(const MPI_Comm             comm,
                   const std::vector<double> &local,
                   const unsigned int         row,
                   const unsigned int         key)
        : parts(dealii::Utilities::MPI::gather(comm, local, 0))
      {
        for (const auto &part : parts)
          for (std::size_t i = 0; i < part.size(); i += row)
            rows.push_back(part.data() + i);
        std::sort(rows.begin(),
                  rows.end(),
                  [key](const double *a, const double *b) {
                    return std::lexicographical_compare(a, a + key, b, b + key);
                  });
      }
      std::vector<std::vector<double>> parts;
      std::vector<const double *>      rows;
    };
  } // namespace

  using namespace dealii;

  template <int dim>
  OutputWriter<dim>::OutputWriter(const MPI_Comm                  comm,
                                  const std::string              &directory,
                                  const ParticleLayout<dim>      &layout,
                                  const std::vector<std::string> &history_names)
    : comm(comm)
    , directory(directory)
    , layout(layout)
    , history_names(history_names)
  {}

  template <int dim>
  void
  OutputWriter<dim>::restore(
    const unsigned int                                 n,
    const std::vector<std::pair<double, std::string>> &particles,
    const std::vector<std::pair<double, std::string>> &grid)
  {
    n_outputs        = n;
    particle_records = particles;
    grid_records     = grid;
  }

  template <int dim>
  void
  OutputWriter<dim>::write_series() const
  {
    for (const auto &[records, name] :
         {std::make_pair(&particle_records, "particles.pvd"),
          std::make_pair(&grid_records, "grid.pvd")})
      if (!records->empty())
        {
          std::ostringstream pvd;
          DataOutBase::write_pvd_record(pvd, *records);
          write_file_atomically(directory + "/" + name, pvd.str());
        }
  }

  template <int dim>
  void
  OutputWriter<dim>::write_particles_vtu(
    Particles::ParticleHandler<dim> &particles,
    const double                     time)
  {
    Particles::DataOut<dim> out;
    out.build_patches(particles,
                      layout.names(history_names),
                      layout.interpretations());
    const std::string name = out.write_vtu_with_pvtu_record(
      directory + "/", "particles", n_outputs, comm, 5, 8);
    particle_records.emplace_back(time, name);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ostringstream pvd;
        DataOutBase::write_pvd_record(pvd, particle_records);
        write_file_atomically(directory + "/particles.pvd", pvd.str());
      }
  }

  template <int dim>
  void
  OutputWriter<dim>::write_grid_vtu(
    const BackgroundGrid<dim>              &grid,
    const NodalVector                      &p2g,
    const NodalVector                      &kinematics,
    const contact::NodalContactForces<dim> *contact_forces,
    const double                            time)
  {
    using P = transfer::P2GLayout<dim>;
    using K = KinematicsLayout<dim>;
    // Unpack to one scalar vector per field in the DoF numbering.
    const auto               part = grid.node_partitioner();
    std::vector<NodalVector> fields(contact_forces ? 1 + 2 * dim : 1 + dim);
    for (auto &f : fields)
      f.reinit(part);
    if (contact_forces)
      for (const auto &f : *contact_forces)
        for (unsigned int d = 0; d < dim; ++d)
          fields[1 + dim + d].local_element(f.node) = f.force[d];
    for (unsigned int i = 0; i < grid.n_owned_nodes(); ++i)
      {
        fields[0].local_element(i) =
          p2g.local_element(i * P::n_components + P::mass);
        for (unsigned int d = 0; d < dim; ++d)
          fields[1 + d].local_element(i) =
            kinematics.local_element(i * K::n_components + K::velocity + d);
      }
    const char  *axis[3] = {"x", "y", "z"};
    DataOut<dim> out;
    out.attach_dof_handler(grid.dof_handler());
    for (auto &f : fields)
      f.update_ghost_values();
    out.add_data_vector(fields[0], "nodal_mass");
    for (unsigned int d = 0; d < dim; ++d)
      out.add_data_vector(fields[1 + d],
                          std::string("nodal_velocity_") + axis[d]);
    if (contact_forces)
      for (unsigned int d = 0; d < dim; ++d)
        out.add_data_vector(fields[1 + dim + d],
                            std::string("contact_force_") + axis[d]);
    Vector<float> subdomain(grid.triangulation().n_active_cells());
    for (auto &s : subdomain)
      s = grid.triangulation().locally_owned_subdomain();
    out.add_data_vector(subdomain, "subdomain");
    out.build_patches();
    const std::string name = out.write_vtu_with_pvtu_record(
      directory + "/", "grid", n_outputs, comm, 5, 8);
    grid_records.emplace_back(time, name);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ostringstream pvd;
        DataOutBase::write_pvd_record(pvd, grid_records);
        write_file_atomically(directory + "/grid.pvd", pvd.str());
      }
  }

  template <int dim>
  void
  OutputWriter<dim>::write_particles_csv(
    Particles::ParticleHandler<dim> &particles,
    const double                     time)
  {
    // Rows of (id, x, properties), gathered on rank 0 and sorted by id.
    const unsigned int  np  = layout.n_properties();
    const unsigned int  row = 1 + dim + np;
    std::vector<double> local;
    local.reserve(particles.n_locally_owned_particles() * row);
    for (const auto &p : particles)
      {
        local.push_back(static_cast<double>(p.get_id()));
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(p.get_location()[d]);
        const auto prop = p.get_properties();
        local.insert(local.end(), prop.begin(), prop.end());
      }
    const GatheredRows table(comm, local, row, 1);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const auto &rows = table.rows;

    std::ostringstream out;
    const char        *axis[3] = {"x", "y", "z"};
    out << "id";
    for (unsigned int d = 0; d < dim; ++d)
      out << ',' << axis[d];
    for (const auto &h : layout.csv_headers(history_names))
      out << ',' << h;
    out << '\n' << std::setprecision(10);
    for (const double *r : rows)
      {
        out << static_cast<unsigned long long>(r[0]);
        for (unsigned int c = 1; c < row; ++c)
          out << ',' << r[c];
        out << '\n';
      }
    std::ostringstream name;
    name << directory << "/particles-" << std::setw(5) << std::setfill('0')
         << n_outputs << ".csv";
    write_file_atomically(name.str(), out.str());
    (void)time;
  }

  template <int dim>
  void
  OutputWriter<dim>::write_contact_csv(
    const contact::NodalContactForces<dim> &forces)
  {
    // Rows of (x, f), gathered on rank 0 and sorted by position.
    constexpr unsigned int row = 2 * dim;
    const GatheredRows     table(comm,
                             contact::contact_force_rows(forces),
                             row,
                             dim);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const auto &rows = table.rows;

    std::ostringstream out;
    const char        *axis[3] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      out << (d ? "," : "") << axis[d];
    for (unsigned int d = 0; d < dim; ++d)
      out << ",contact_force_" << axis[d];
    out << '\n' << std::setprecision(10);
    for (const double *r : rows)
      {
        for (unsigned int c = 0; c < row; ++c)
          out << (c ? "," : "") << r[c];
        out << '\n';
      }
    std::ostringstream name;
    name << directory << "/contact-" << std::setw(5) << std::setfill('0')
         << n_outputs << ".csv";
    write_file_atomically(name.str(), out.str());
  }

  template class OutputWriter<1>;
  template class OutputWriter<2>;
  template class OutputWriter<3>;
} // namespace mpm
