#pragma once

#include <deal.II/base/partitioner.h>

#include <mpm/grid/background_grid.h>

#include <map>
#include <vector>

namespace mpm
{
  /**
   * The nodes that carry values in the current step, so that the explicit
   * step's passes over the nodes (zeroing the sums, the grid update, the
   * re-map's velocities) cost what the particles reach, not the whole
   * grid.
   *
   * A P2G pass marks every local node it adds to; collect() turns the
   * marks into the ascending list of active owned nodes, with the owned
   * nodes that other ranks add to (compress() brings their sums, which no
   * local mark shows). For each vector it serves it records where that
   * vector may be non-zero, so that zeroing it touches those nodes only;
   * every other entry is zero. reset() forgets: the next zeroing of each
   * vector then clears it whole.
   */
  class ActiveNodes
  {
  public:
    /// Start over on the node layout @p nodes (after the nodal vectors
    /// were initialized, at set-up and after a repartition).
    void
    reset(const dealii::Utilities::MPI::Partitioner &nodes);

    /// One byte per local node (owned, then ghost), set by the passes
    /// for the nodes they add to.
    unsigned char *
    marks()
    {
      return mark.data();
    }

    /// A new set of marks: before a pass that sums the mass from zero.
    void
    clear_marks();

    /// The marked owned nodes and those other ranks add to, ascending,
    /// into nodes().
    void
    collect();

    /// The active owned nodes of the last collect().
    const std::vector<unsigned int> &
    nodes() const
    {
      return active;
    }

    /// Zero @p v (@p nc components per node) where it may be non-zero:
    /// before a pass sums into it.
    void
    zero(NodalVector &v, const unsigned int nc);

    /// Zero @p v at the nodes where it may be non-zero that are no longer
    /// active: before a pass over nodes() writes it there.
    void
    zero_inactive(NodalVector &v, const unsigned int nc);

    /// After a pass: @p v is non-zero at most at nodes().
    void
    record(const NodalVector &v);

  private:
    std::vector<unsigned char> mark;
    std::vector<unsigned int>  imports, active;
    unsigned int               n_owned = 0;
    /// Per vector served, the owned nodes where it may be non-zero; a
    /// vector not listed may be non-zero anywhere.
    std::map<const NodalVector *, std::vector<unsigned int>> nonzero;
  };
} // namespace mpm
