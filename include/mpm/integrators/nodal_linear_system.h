#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <mpm/grid/background_grid.h>
#include <mpm/integrators/implicit_parameters.h>

#include <array>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * The linear system of an implicit step on the background grid, on
   * Trilinos: one unknown per node and direction, numbered as the grid's
   * packed nodal vectors with dim components (global index dim g + c for
   * node g), so that a nodal vector and a Trilinos vector share their
   * locally owned entries in the same order. The sparsity couples the
   * nodes of every owned cell (built once per partition), or the groups
   * of nodes that couple() is given (the stencils of a domain family,
   * which reach beyond the particle's cell); the constraints (fixed and
   * slip walls, nodes without mass) are rebuilt every step.
   */
  template <int dim>
  class NodalLinearSystem
  {
  public:
    using Index = dealii::types::global_dof_index;

    /// Lists of nodes (node-local indices) whose unknowns couple all to
    /// all: group g is nodes[start[g]], ..., nodes[start[g + 1] - 1].
    struct NodeGroups
    {
      std::vector<unsigned int> nodes;
      std::vector<unsigned int> start = {0};

      void
      clear()
      {
        nodes.clear();
        start.assign(1, 0);
      }
      /// The nodes added since the last group form a group.
      void
      close_group()
      {
        start.push_back(nodes.size());
      }
      /// The groups of @p other, added after these.
      void
      append(const NodeGroups &other)
      {
        const unsigned int offset = nodes.size();
        nodes.insert(nodes.end(), other.nodes.begin(), other.nodes.end());
        for (unsigned int g = 1; g < other.start.size(); ++g)
          start.push_back(offset + other.start[g]);
      }
    };

    /// Index sets of the grid's current partition, and the sparsity of
    /// its owned cells and of the groups @p extra (the ghost penalty's
    /// faces).
    void
    reinit(const BackgroundGrid<dim> &grid,
           const MPI_Comm             comm,
           const NodeGroups          &extra = NodeGroups());

    /// The sparsity (and a zero matrix) of @p groups instead, and of the
    /// owned rows of @p node_coupling (node-by-node entries: every
    /// direction of the two nodes couples). Collective.
    void
    couple(const NodeGroups       &groups,
           const Epetra_CrsMatrix *node_coupling = nullptr);

    /// The groups of reinit(): the owned cells' vertices and the extra
    /// groups.
    const NodeGroups &
    cell_groups() const
    {
      return grid_groups;
    }

    /**
     * Constraints of this step: every direction of a node whose @p active
     * entry (per node-local index) is 0, the walls' normal directions of
     * the others, and the directions (bits) of @p prescribed, the motion
     * of a rigid body, with the values @p values in the predictor's set.
     * A wall that constrains a direction takes it from @p prescribed (bit
     * cleared). Every node this rank knows (owned and ghost) is
     * constrained: a domain's stencil may reach any of them.
     */
    void
    build_constraints(const BackgroundGrid<dim>                 &grid,
                      const std::vector<char>                   &active,
                      std::vector<unsigned char>                &prescribed,
                      const std::vector<dealii::Tensor<1, dim>> &values);

    /// Make the directions that the homogeneous constraints hold in @p v
    /// (dim components per node-local node, owned and ghost) follow them:
    /// a nodal velocity or acceleration that the walls admit.
    void
    apply_homogeneous_constraints(const BackgroundGrid<dim> &grid,
                                  NodalVector               &v) const;

    /// Whether some node of some rank follows a rigid body.
    bool
    has_prescribed_motion() const
    {
      return moves_prescribed;
    }

    /// Assemble and solve with the prescribed values (Newton's predictor
    /// from a zero increment) or homogeneous constraints (its
    /// corrections).
    void
    prescribe_motion(const bool on)
    {
      predictor = on;
    }

    /// The global indices of the unknowns of @p n nodes (node-local
    /// indices @p nodes), node-major.
    void
    node_indices(const unsigned int *nodes,
                 const unsigned int  n,
                 std::vector<Index> &indices) const;

    /**
     * One body's stiff volumetric part in one cell, for `Preconditioner =
     * AMG with cell pressure`: (lambda / V) g b^T, with b (dim entries
     * per node of the cell's list, node-major) the derivative of the
     * cell's volume change by the nodal increment, g the direction the
     * pressure's force takes (the current volume's gradient; in a fixed
     * geometry sum V G; empty: g = b), lambda the split's lambda_s = lambda -
     * gamma mu (`Cell pressure gamma`), and rest_modulus = (gamma + 1) mu the
     * volumetric stiffness the rest keeps, for the Schur estimate.
     */
    struct CellPressure
    {
      std::vector<double> b, g;
      double              lambda = 0, rest_modulus = 0, volume = 0;
    };



    /// Whether add_cell() with cell pressures splits them off (set-up:
    /// the preconditioner is AMG with cell pressure).
    void
    split_cell_pressure(const bool on)
    {
      split = on;
    }
    bool
    splits_cell_pressure() const
    {
      return split;
    }

    /// Start an assembly: matrix (if @p with_matrix) and right-hand side
    /// zero.
    void
    begin_assembly(const bool with_matrix);

    /// Add a cell's matrix and right-hand side (the negative residual),
    /// condensing the constraints.
    void
    add_cell(const dealii::FullMatrix<double> &cell_matrix,
             const dealii::Vector<double>     &cell_rhs,
             const std::vector<Index>         &indices);
    /**
     * The same for a cell whose tangent @p cell_matrix holds the stiff
     * parts @p pressures: the matrix receives the tangent without them,
     * and each becomes a row of B and of C (from b and g, condensed like
     * the matrix), so that the tangent is matrix + C^T diag(lambda/V) B.
     * The right-hand side's inhomogeneities come from the whole tangent.
     */
    void
    add_cell(const dealii::FullMatrix<double> &cell_matrix,
             const dealii::Vector<double>     &cell_rhs,
             const std::vector<Index>         &indices,
             const std::vector<CellPressure>  &pressures);
    void
    add_cell_rhs(const dealii::Vector<double> &cell_rhs,
                 const std::vector<Index>     &indices);

    /// Exchange the sums and add @p coupling (if given; its sparsity
    /// was given to couple()) to the matrix and @p rhs_change (owned
    /// unknowns, condensed) to the right-hand side; constrained rows that
    /// no cell reached get a diagonal so that the matrix is regular.
    void
    finish_assembly(
      const bool                                   with_matrix,
      const Epetra_CrsMatrix                      *coupling   = nullptr,
      const dealii::TrilinosWrappers::MPI::Vector *rhs_change = nullptr);

    /// The norm of the assembled right-hand side (free unknowns only).
    double
    rhs_norm() const
    {
      return rhs.l2_norm();
    }

    struct SolveResult
    {
      unsigned int iterations = 0;
      std::string  error; ///< empty: solved
    };

    /// Solve K x = rhs with the method of @p p (CG, GMRES, or p's
    /// Direct solver when @p solver asks so); x satisfies the constraints. The
    /// near-null space of the AMG preconditioner is the rigid-body motion of
    /// the nodes at @p grid's node positions. With cell pressures split off,
    /// GMRES solves the displacement-pressure system instead
    /// (solve_with_cell_pressure()).
    SolveResult
    solve(const BackgroundGrid<dim>                     &grid,
          const Parameters::ImplicitSolver              &p,
          const Parameters::ImplicitSolver::LinearSolver solver,
          dealii::TrilinosWrappers::MPI::Vector         &x);

    /// The unknowns of the system, over all ranks.
    Index
    n_unknowns() const
    {
      return owned.size();
    }

    /// A vector of the owned unknowns.
    void
    initialize_vector(dealii::TrilinosWrappers::MPI::Vector &v) const
    {
      v.reinit(owned, comm);
    }

    /// The constraints in use (prescribe_motion()).
    const dealii::AffineConstraints<double> &
    constraints() const
    {
      return predictor ? prescribed_motion : node_constraints;
    }

    const dealii::TrilinosWrappers::MPI::Vector &
    right_hand_side() const
    {
      return rhs;
    }

  private:
    /// The rows of B and the Schur complement's diagonal, from this
    /// assembly's cell pressures (finish_assembly()).
    void
    build_cell_pressure();

    /// GMRES on [K_rest, C^T; W B, -l] [x; p] = [rhs; 0], which has the
    /// x of K x = rhs for K = K_rest + C^T diag(lambda_s/V) B (W = l
    /// lambda_s/V, l = |b| to give the pressure rows force units),
    /// preconditioned by [AMG(K_rest), C^T; 0, -S] with S the diagonal
    /// estimate l (1 + lambda_s / rest_modulus) of the Schur complement
    /// (doc/theory/implicit.md, "Nearly incompressible").
    unsigned int
    solve_with_cell_pressure(
      const dealii::TrilinosWrappers::PreconditionAMG &amg,
      const Parameters::ImplicitSolver                &p,
      dealii::TrilinosWrappers::MPI::Vector           &x);

    /// x = K^-1 rhs by the sparse direct solver @p package, the
    /// factorisation on one process.
    void
    solve_direct(const Parameters::ImplicitSolver::DirectSolver package,
                 dealii::TrilinosWrappers::MPI::Vector         &x);

    MPI_Comm                               comm = MPI_COMM_SELF;
    NodeGroups                             grid_groups;
    std::vector<Index>                     node_to_global; ///< per local node
    dealii::IndexSet                       owned, relevant;
    dealii::AffineConstraints<double>      node_constraints;
    dealii::AffineConstraints<double>      prescribed_motion;
    bool                                   predictor        = false;
    bool                                   moves_prescribed = false;
    dealii::TrilinosWrappers::SparseMatrix matrix;
    dealii::TrilinosWrappers::MPI::Vector  rhs;
    double diagonal_scale = 1; ///< of the constrained rows' diagonal

    bool                       split = false;
    dealii::FullMatrix<double> rest_matrix; ///< scratch of add_cell()
    /// this assembly's rows of B and C: columns and values of row r from
    /// row_start[r], and lambda_s, rest_modulus, V of its cell and body
    std::vector<Index>                     row_columns;
    std::vector<double>                    row_values, row_force_values;
    std::vector<unsigned int>              row_start = {0};
    std::vector<std::array<double, 3>>     row_moduli;
    dealii::IndexSet                       pressure_owned;
    dealii::TrilinosWrappers::SparseMatrix volume_gradient; ///< B
    dealii::TrilinosWrappers::SparseMatrix force_gradient;  ///< C
    /// per pressure row: l = |b|, W = l lambda_s / V, and 1/S
    dealii::TrilinosWrappers::MPI::Vector row_scale, row_weight, schur_inverse;
    /// 1 + |C^T diag(1/l)|_2 (bound): the tangent's residual over the
    /// block system's
    double residual_bound = 1;
  };
} // namespace mpm
