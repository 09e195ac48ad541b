#pragma once

#include <deal.II/base/mpi.h>

#include <mpm/contact/nodal_contact_force.h>

#include <algorithm>
#include <vector>

namespace mpm
{
  namespace contact
  {
    /// The forces as rows of 2 dim numbers, (x, f), one after the other:
    /// what travels between ranks and what the contact table lists.
    template <int dim>
    std::vector<double>
    contact_force_rows(const NodalContactForces<dim> &forces)
    {
      std::vector<double> rows;
      rows.reserve(forces.size() * 2 * dim);
      for (const auto &f : forces)
        {
          for (unsigned int d = 0; d < dim; ++d)
            rows.push_back(f.position[d]);
          for (unsigned int d = 0; d < dim; ++d)
            rows.push_back(f.force[d]);
        }
      return rows;
    }

    /// Collective: the contact forces of every rank, on every rank,
    /// sorted by position (what a measure over the whole contact reads;
    /// the node indices are left at 0, they mean nothing off their rank).
    template <int dim>
    NodalContactForces<dim>
    gather_contact_forces(const NodalContactForces<dim> &forces,
                          const MPI_Comm                 comm)
    {
      constexpr unsigned int  row = 2 * dim;
      NodalContactForces<dim> all;
      for (const auto &part :
           dealii::Utilities::MPI::all_gather(comm, contact_force_rows(forces)))
        for (std::size_t i = 0; i + row <= part.size(); i += row)
          {
            NodalContactForce<dim> f;
            for (unsigned int d = 0; d < dim; ++d)
              {
                f.position[d] = part[i + d];
                f.force[d]    = part[i + dim + d];
              }
            all.push_back(f);
          }
      std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
        return std::lexicographical_compare(a.position.begin_raw(),
                                            a.position.end_raw(),
                                            b.position.begin_raw(),
                                            b.position.end_raw());
      });
      return all;
    }
  } // namespace contact
} // namespace mpm
