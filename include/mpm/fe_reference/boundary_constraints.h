#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <mpm/fe_reference/parameters.h>

namespace mpm
{
  namespace fe_reference
  {
    /**
     * The Boundary conditions subsection as constraints on the
     * displacement: hanging nodes, clamped and prescribed boundaries
     * (interpolated), then slip (no normal displacement; dofs already
     * constrained are left alone, so clamped corners win). A boundary id
     * that does not occur on the mesh (on any process of @p comm) is an
     * InputError naming it. @p constraints must be empty (serial) or
     * reinit'ed with the locally relevant dofs (distributed); it is closed
     * on return.
     */
    template <int dim>
    void
    make_boundary_constraints(const AllParameters<dim>          &parameters,
                              const dealii::Mapping<dim>        &mapping,
                              const dealii::DoFHandler<dim>     &dofs,
                              dealii::AffineConstraints<double> &constraints,
                              const MPI_Comm                     comm);
  } // namespace fe_reference
} // namespace mpm
