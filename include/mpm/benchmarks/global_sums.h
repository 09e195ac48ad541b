#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <array>
#include <cstddef>

namespace mpm
{
  namespace benchmarks
  {
    /// Collective: the sums over all ranks of the rank's @p local totals,
    /// entry by entry (the reduction every measure ends with).
    template <std::size_t n>
    std::array<double, n>
    global_sums(const double (&local)[n], const MPI_Comm comm)
    {
      std::array<double, n> sums;
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(local, n),
                                  comm,
                                  dealii::ArrayView<double>(sums.data(), n));
      return sums;
    }
  } // namespace benchmarks
} // namespace mpm
