#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/vector.h>

#include <mpm/fe_reference/elastic_cell_assembler.h>
#include <mpm/fe_reference/parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  namespace fe_reference
  {
    /**
     * The static problem of ElasticSystem (the same elements, boundary
     * conditions and cell matrices) on a mesh distributed with p4est: the
     * stiffness matrix and vectors in Trilinos, each process assembling its
     * own cells, and an iterative solve. The displacement formulation is
     * symmetric positive definite: CG preconditioned by ML algebraic
     * multigrid whose near-null space is the rigid-body modes of the
     * displacement dofs. The mixed formulation [A B^T; B -M_p/lambda] is
     * symmetric indefinite: MINRES with the block-diagonal preconditioner
     * diag(AMG(A), S^-1), where S = (1/(2 mu) + 1/lambda) diag(M_p) stands
     * for the Schur complement B A^-1 B^T + M_p/lambda (spectrally
     * equivalent to the scaled pressure mass matrix, so the iteration count
     * does not grow with nu -> 0.5 or with refinement). Every member
     * function is collective.
     */
    template <int dim>
    class DistributedElasticSystem
    {
    public:
      /// The triangulation must outlive this object.
      DistributedElasticSystem(
        const AllParameters<dim>                                &parameters,
        const dealii::parallel::distributed::Triangulation<dim> &tria);

      /// Distribute and (mixed: block-wise) renumber the dofs, build the
      /// constraints and the distributed sparsity pattern.
      void
      setup();

      struct SolveStatistics
      {
        unsigned int iterations        = 0;
        double       assembly_seconds  = 0;
        double       amg_setup_seconds = 0;
        double       solve_seconds     = 0;
      };

      /// Assemble K and f, solve K u = f to the Linear solver tolerance.
      /// A free body is an InputError; no convergence a RuntimeError.
      SolveStatistics
      solve_static();

      /// Displacement (and pressure) at a point, from the process that
      /// owns a cell around it; InputError outside the body.
      dealii::Vector<double>
      point_value(const dealii::Point<dim> &p) const;

      /// One ParaView file of the solution, written by all processes.
      void
      write_vtu(const std::string &file_name) const;

      bool
      mixed() const
      {
        return element.mixed;
      }

      dealii::types::global_dof_index
      n_dofs() const
      {
        return dofs.n_dofs();
      }

    private:
      const AllParameters<dim>                   &parameters;
      const MPI_Comm                              comm;
      const ElasticElement<dim>                   element;
      dealii::DoFHandler<dim>                     dofs;
      std::vector<dealii::IndexSet>               owned_partitioning;
      std::vector<dealii::IndexSet>               relevant_partitioning;
      dealii::IndexSet                            relevant;
      dealii::AffineConstraints<double>           constraints;
      dealii::TrilinosWrappers::BlockSparseMatrix stiffness;
      dealii::TrilinosWrappers::MPI::BlockVector  load;
      /// mixed only: diag(M_p) while assembling, then the inverse of the
      /// preconditioner's pressure block (1/(2 mu) + 1/lambda) diag(M_p)
      dealii::TrilinosWrappers::MPI::BlockVector inverse_schur_diagonal;
      /// with ghosts, for point values and output
      dealii::TrilinosWrappers::MPI::BlockVector solution;
    };
  } // namespace fe_reference
} // namespace mpm
