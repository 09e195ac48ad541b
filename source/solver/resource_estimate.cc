#include <deal.II/grid/tria.h>

#include <mpm/grid/mesh_reader.h>
#include <mpm/particles/inflow.h>
#include <mpm/shape_functions/family_registry.h>
#include <mpm/solver/resource_estimate.h>
#include <mpm/utilities/input_error.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace mpm
{
  namespace
  {
    /// Memory per item, allocated after the first step on one rank
    /// (doc/performance.md, "Memory estimate"; scripts/memory_figures.sh
    /// measures them), rounded down: the estimate is a lower bound.
    struct BytesPer
    {
      double grid_cell, particle, domain_particle, implicit_body_cell;
    };
    constexpr BytesPer bytes_per[3] = {{380, 240, 290, 850},
                                       {620, 290, 420, 2800},
                                       {1100, 410, 730, 11500}};
    /// the program, libraries' data and buffers of one rank
    constexpr double bytes_per_rank = 15e6;

    /// the parameters hold one count per direction
    double
    product(const std::vector<unsigned int> &n)
    {
      double p = 1;
      for (const unsigned int k : n)
        p *= k;
      return p;
    }

    std::string
    list(const std::vector<unsigned int> &n)
    {
      std::ostringstream s;
      for (std::size_t i = 0; i < n.size(); ++i)
        s << (i ? ", " : "") << n[i];
      return s.str();
    }

    template <int dim>
    double
    mesh_file_cells(const std::string &file,
                    const std::string &input_folder,
                    const std::string &entry)
    {
      dealii::Triangulation<dim> mesh;
      read_mesh(mesh, file, input_folder, entry);
      return mesh.n_active_cells();
    }

  } // namespace

  template <int dim>
  double
  body_mesh_cells(const Parameters::Body<dim> &body,
                  const std::string           &input_folder,
                  const std::string           &where,
                  std::ostringstream          *entries)
  {
    using G                   = typename Parameters::Body<dim>::Geometry;
    double              cells = 0;
    std::ostringstream  unused;
    std::ostringstream &origin = entries ? *entries : unused;
    switch (body.geometry)
      {
        case G::box:
        case G::quadrilateral:
          cells = product(body.subdivisions);
          origin << where << "Subdivisions = " << list(body.subdivisions);
          break;
        case G::ball:
          // the coarse ball: 2 segments in 1D, 12 cells in 2D, 32 in 3D
          cells = (dim == 1 ? 2 :
                   dim == 2 ? 12 :
                              32) *
                  std::pow(2., double(dim) * body.refinements);
          origin << where << "Refinements = " << body.refinements;
          break;
        case G::mesh_file:
          cells = mesh_file_cells<dim>(body.mesh_file,
                                       input_folder,
                                       where + "Mesh file");
          origin << where << "Mesh file = " << body.mesh_file;
          break;
        case G::none:
          break;
      }
    return cells;
  }

  std::string
  gigabytes(const double bytes)
  {
    std::ostringstream s;
    if (bytes < 1e9)
      s.precision(2);
    else
      s << std::fixed << std::setprecision(1);
    s << bytes / 1e9 << " GB";
    return s.str();
  }

  std::string
  ResourceEstimate::summary() const
  {
    std::ostringstream s;
    s.precision(3);
    s << "at least " << gigabytes(bytes) << " (" << grid_cells
      << " grid cells, " << particles << " particles)";
    return s.str();
  }

  template <int dim>
  ResourceEstimate
  estimate_resources(const Parameters::AllParameters<dim> &parameters,
                     const std::string                    &input_folder,
                     const unsigned int                    n_ranks)
  {
    ResourceEstimate e;
    const auto      &grid = parameters.grid;
    const double refined  = std::pow(2., double(dim) * grid.global_refinements);
    std::ostringstream entries;
    if (grid.type == Parameters::Grid<dim>::Type::hyper_rectangle)
      {
        e.grid_cells = product(grid.subdivisions);
        // built from its coarsest grid with the same proportions, then
        // refined (grid/box_mesh.h)
        unsigned int k         = 0;
        auto         divisible = [&](const unsigned int k) {
          for (const unsigned int n : grid.subdivisions)
            if (n % (2u << k) != 0)
              return false;
          return true;
        };
        while (k < 30 && divisible(k))
          ++k;
        e.coarse_grid_cells = e.grid_cells / std::pow(2., double(dim) * k);
        entries << "Grid/Subdivisions = " << list(grid.subdivisions);
      }
    else
      {
        e.grid_cells =
          mesh_file_cells<dim>(grid.mesh_file, input_folder, "Grid/Mesh file");
        e.coarse_grid_cells = e.grid_cells;
        entries << "Grid/Mesh file = " << grid.mesh_file << " (" << e.grid_cells
                << " cells)";
      }
    if (grid.global_refinements > 0)
      entries << " and Grid/Global refinements = " << grid.global_refinements;
    e.grid_cells *= refined;
    e.grid_entries = entries.str();

    const bool domains =
      shape_functions::family_traits(parameters.shape_functions.family)
        .has_domains;
    double largest = -1;
    for (unsigned int b = 0; b < parameters.bodies.size(); ++b)
      {
        const auto       &body  = parameters.bodies[b];
        const std::string where = "Bodies/" + Parameters::body_section(b) + "/";
        using G                 = typename Parameters::Body<dim>::Geometry;
        std::ostringstream origin;
        const double       cells =
          body_mesh_cells(body, input_folder, where, &origin);
        if (body.geometry != G::none)
          origin << " and " << where << "Particles per direction = "
                 << body.particles_per_direction;
        // an inflow's particles over the whole run
        const double inflowing = static_cast<double>(
          Inflow<dim>::planned_particles(body.inflow,
                                         parameters.time.end_time));
        if (inflowing > 0)
          origin << (body.geometry != G::none ? " and " : "") << where
                 << "Inflow (" << inflowing
                 << " particles from Radius, Speed, Particle spacing and End "
                    "time or Volume)";
        const double particles =
          cells * std::pow(double(body.particles_per_direction), dim) +
          inflowing;
        e.body_cells += cells;
        e.particles += particles;
        if (particles > largest)
          {
            largest        = particles;
            e.largest_body = origin.str();
          }
      }

    const BytesPer &per = bytes_per[dim - 1];
    const bool      implicit =
      parameters.time.integrator !=
      Parameters::TimeStepping::Integrator::explicit_dynamics;
    // 1D grids are whole on every rank; p4est keeps the coarse grid on
    // every rank and shares the refined cells out
    const double grid_cells_held =
      dim == 1 ? e.grid_cells * n_ranks :
                 std::max(e.grid_cells, e.coarse_grid_cells * n_ranks);
    e.bytes = n_ranks * bytes_per_rank + grid_cells_held * per.grid_cell +
              e.particles * (domains ? per.domain_particle : per.particle) +
              (implicit ? e.body_cells * per.implicit_body_cell : 0.);
    return e;
  }

  namespace
  {
    /// a number from a text file, or a negative value
    double
    read_number(const std::string &file, const std::string &key = "")
    {
      std::ifstream in(file);
      std::string   word;
      while (in >> word)
        if (key.empty() || word == key)
          {
            if (!key.empty() && !(in >> word))
              return -1;
            try
              {
                return std::stod(word);
              }
            catch (...)
              {
                return -1; // "max": no limit
              }
          }
      return -1;
    }

    /// this machine's usable memory [bytes], or a negative value
    double
    machine_memory()
    {
      double available = read_number("/proc/meminfo", "MemAvailable:");
      if (available > 0)
        available *= 1024.;
      // a container's limit (cgroup v2, then v1), less what it uses
      for (const auto &[limit_file, usage_file] :
           {std::pair<std::string, std::string>{
              "/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current"},
            {"/sys/fs/cgroup/memory/memory.limit_in_bytes",
             "/sys/fs/cgroup/memory/memory.usage_in_bytes"}})
        {
          const double limit = read_number(limit_file);
          // v1 reports "no limit" as a number near 2^63
          if (limit > 0 && limit < 1e18)
            {
              const double left = limit - std::max(0., read_number(usage_file));
              available = available > 0 ? std::min(available, left) : left;
              break;
            }
        }
      return available;
    }
  } // namespace

  double
  available_memory(const MPI_Comm comm)
  {
    // one rank per machine reports its machine
    MPI_Comm machine;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &machine);
    int machine_rank = 0;
    MPI_Comm_rank(machine, &machine_rank);
    MPI_Comm_free(&machine);
    const double mine = machine_rank == 0 ? machine_memory() : 0.;
    if (dealii::Utilities::MPI::min(machine_rank == 0 ? mine : 1., comm) <= 0)
      return 0;
    return dealii::Utilities::MPI::sum(mine, comm);
  }

  void
  check_resources(const ResourceEstimate &e,
                  const double            limit_bytes,
                  const bool              limit_is_parameter)
  {
    // deal.II numbers the active cells of a triangulation with 32 bits
    const double       max_cells = std::numeric_limits<unsigned int>::max();
    std::ostringstream s;
    s.precision(3);
    if (e.grid_cells > max_cells)
      s << e.grid_entries << " give " << e.grid_cells
        << " grid cells, more than the " << max_cells
        << " a 32-bit cell index can number.";
    else if (e.body_cells > max_cells)
      s << e.largest_body << ": " << e.body_cells
        << " body cells, more than the " << max_cells
        << " a 32-bit cell index can number.";
    else if (limit_bytes > 0 && e.bytes > limit_bytes)
      {
        s << "the case needs " << e.summary() << ": more than the "
          << gigabytes(limit_bytes)
          << (limit_is_parameter ? " of Memory limit" :
                                   " of memory available on the machines") +
               std::string(". The grid comes from ")
          << e.grid_entries << "; the most particles from " << e.largest_body
          << ". Use fewer cells or particles, more machines, or"
          << (limit_is_parameter ? " a larger" : " set") << " Memory limit "
          << "(in GB) if the machines can hold it.";
      }
    else if (e.particles > max_cells)
      s << "the bodies give " << e.particles << " particles, more than the "
        << max_cells << " a 32-bit particle id can number; the most from "
        << e.largest_body << ".";
    if (!s.str().empty())
      throw InputError(s.str());
  }

  template double
  body_mesh_cells<1>(const Parameters::Body<1> &,
                     const std::string &,
                     const std::string &,
                     std::ostringstream *);
  template double
  body_mesh_cells<2>(const Parameters::Body<2> &,
                     const std::string &,
                     const std::string &,
                     std::ostringstream *);
  template double
  body_mesh_cells<3>(const Parameters::Body<3> &,
                     const std::string &,
                     const std::string &,
                     std::ostringstream *);

  template ResourceEstimate
  estimate_resources<1>(const Parameters::AllParameters<1> &,
                        const std::string &,
                        unsigned int);
  template ResourceEstimate
  estimate_resources<2>(const Parameters::AllParameters<2> &,
                        const std::string &,
                        unsigned int);
  template ResourceEstimate
  estimate_resources<3>(const Parameters::AllParameters<3> &,
                        const std::string &,
                        unsigned int);
} // namespace mpm
