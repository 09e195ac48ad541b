#pragma once

#include <deal.II/base/mpi.h>

#include <mpm/parameters/parameters.h>

#include <sstream>
#include <string>

/**
 * What a case needs before anything is allocated: the grid cells, the
 * particles and a lower bound on the memory they take, from the
 * parameters alone (a mesh file is read, not refined). A case that cannot
 * fit is refused before it allocates for minutes and then aborts.
 */
namespace mpm
{
  struct ResourceEstimate
  {
    /// active grid cells after every refinement
    double grid_cells = 0;
    /// cells of the coarse grid, which p4est keeps on every rank
    double coarse_grid_cells = 0;
    /// body cells and particles, summed over the bodies
    double body_cells = 0;
    double particles  = 0;
    /// lower bound on the memory of all ranks together [bytes]
    double bytes = 0;
    /// the entries that set the counts, for messages
    std::string grid_entries, largest_body;

    /// "at least 1.2 GB (1.0e+06 grid cells, 4.2e+06 particles)"
    std::string
    summary() const;
  };

  /// "1.2 GB", "0.016 GB"
  std::string
  gigabytes(const double bytes);

  /// The cells of a body's mesh from its parameters (a mesh file is read,
  /// nothing is refined or built); 0 for Geometry = none. The body starts
  /// with that many times Particles per direction^dim particles.
  /// @p where: "Bodies/Body 0/"; @p entries, if given, receives the
  /// entries that set the count ("Bodies/Body 0/Subdivisions = 4, 4").
  template <int dim>
  double
  body_mesh_cells(const Parameters::Body<dim> &body,
                  const std::string           &input_folder,
                  const std::string           &where,
                  std::ostringstream          *entries = nullptr);

  /// Count cells and particles and bound the memory of a case run on
  /// @p n_ranks ranks. Body and grid mesh files are read (not refined).
  template <int dim>
  ResourceEstimate
  estimate_resources(const Parameters::AllParameters<dim> &parameters,
                     const std::string                    &input_folder,
                     const unsigned int                    n_ranks);

  /// Memory the ranks of @p comm can use [bytes]: per machine the smaller
  /// of MemAvailable and the container's limit, summed over the machines;
  /// 0 if no rank can tell.
  double
  available_memory(const MPI_Comm comm);

  /// Refuse (InputError) a case whose estimate exceeds @p limit_bytes, or
  /// whose cell count exceeds what a 32-bit cell index can number.
  /// @p limit_is_parameter says whether the limit is `Memory limit` or the
  /// machines' memory.
  void
  check_resources(const ResourceEstimate &estimate,
                  const double            limit_bytes,
                  const bool              limit_is_parameter);
} // namespace mpm
