#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <mpm/grid/background_grid.h>
#include <mpm/particles/body.h>
#include <mpm/shape_functions/q1_cell.h>

#include <memory>
#include <vector>

class Epetra_CrsMatrix;

namespace mpm
{
  namespace remedies
  {
    /**
     * `Volumetric smoothing = node` in the implicit step: the node
     * average of the explicit stress update (VolumetricSmoothing) as a
     * function of the trial increment, and its derivative
     * (doc/theory/implicit.md, "The node average"). With N the Q1 values
     * of a particle's cell at the particle and M_v = sum_q N_qv m_q the
     * node-smoothed mass at node v,
     *   J_bar_p = sum_v N_pv (sum_q N_qv m_q J_q / M_v) / S_p,
     * S_p = sum of N_pv over the nodes with mass, and theta_bar_p (the
     * average of tr h, the rate form) likewise. Their derivatives couple
     * every particle at a node with every other, across cells, so the
     * tangent's coupling part is a product of two rectangular matrices
     * with two rows per node (s = 0: J, s = 1: tr h):
     *   K_nl = (diag(1/M) D)^T C,
     *   C_(v,s),bk = sum_q N_qv m_q d(J_q or tr h_q) / du_bk,
     *   D_(v,s),ai = sum_p N_pv / S_p d(force of p on a_i) / d(J_bar_p or
     *                theta_bar_p),
     * both with their columns condensed like the tangent (so the product
     * is the condensed coupling), multiplied by Trilinos.
     *
     * Per step: begin_step() with the cells' reach (the sparsity). Per
     * assembly: begin_assembly(); add_state() for every cell in a first
     * pass, finish_sums(); then the integrator's cell loop reads
     * averages() and adds add_force_derivative() rows; finish_matrix()
     * gives the product and its inhomogeneous right-hand side.
     */
    template <int dim>
    class LinearizedNodeSmoothing
    {
    public:
      using Index                      = dealii::types::global_dof_index;
      static constexpr unsigned int nv = shape_functions::n_q1<dim>;

      explicit LinearizedNodeSmoothing(const std::vector<Body<dim>> &bodies);

      /// Whether the body with index @p b averages through the nodes.
      bool
      smooths(const unsigned int b) const
      {
        return node_average[b];
      }

      /// Whether some body averages through the nodes.
      bool
      any() const
      {
        return any_body;
      }

      /// The couplings of one step: for each cell whose particles are
      /// node-smoothed, its vertices (@p vertices, nv per cell, node-local)
      /// and the nodes its particles reach (group g of @p reach, start
      /// @p reach_start). Sets the matrices' sparsity and node_coupling().
      /// Collective.
      void
      begin_step(const BackgroundGrid<dim>       &grid,
                 const MPI_Comm                   comm,
                 const std::vector<unsigned int> &vertices,
                 const std::vector<unsigned int> &reach,
                 const std::vector<unsigned int> &reach_start);

      /// The nodes whose unknowns the coupling part joins: entry (a, b)
      /// of this node-by-node matrix (owned rows) for nodes a, b.
      const Epetra_CrsMatrix &
      node_coupling() const
      {
        return *coupling;
      }

      /// Zero the nodal sums (and C, D with @p with_matrix).
      void
      begin_assembly(const bool with_matrix);

      /// Start a cell (of either pass) whose list has @p n_list nodes.
      void
      begin_cell(const unsigned int n_list);

      /**
       * The first pass: a node-smoothed particle's trial state, mass @p m,
       * J = det F and tr h, on the vertices @p vertices (node-local) of its
       * cell with Q1 values @p N; with a matrix, its row of C: @p G the
       * gradients on the cell's list (begin_cell()) and @p f_inv_T the
       * transposed inverse of its step's f.
       */
      void
      add_state(const unsigned int           *vertices,
                const double                 *N,
                const double                  m,
                const double                  J,
                const double                  tr_h,
                const bool                    with_matrix,
                const dealii::Tensor<2, dim> &f_inv_T,
                const dealii::Tensor<1, dim> *G);

      /// End the first pass's cell: its rows of C, columns (the unknowns
      /// @p list_dofs of the cell's list, node-major) condensed by
      /// @p constraints, whose inhomogeneities give C g.
      void
      finish_state_cell(const unsigned int                      *vertices,
                        const std::vector<Index>                &list_dofs,
                        const dealii::AffineConstraints<double> &constraints);

      /// Exchange the sums (and C). Collective.
      void
      finish_sums(const bool with_matrix);

      /**
       * The averages at a particle with Q1 values @p N on its cell's
       * vertices @p vertices: J_bar and theta_bar (of tr h); @p S the sum
       * of N over the nodes with mass. False if no node has mass.
       */
      bool
      averages(const unsigned int *vertices,
               const double       *N,
               double             &J_bar,
               double             &theta_bar,
               double             &S) const;

      /**
       * Particle p's row of D: @p df (dim entries per node of the cell's
       * list) the derivative of its internal force by J_bar (@p total) or
       * theta_bar, spread on its cell's vertices @p vertices by N / (S
       * M), M the node's mass (diag(1/M) of the product).
       */
      void
      add_force_derivative(const unsigned int        *vertices,
                           const double              *N,
                           const double               S,
                           const bool                 total,
                           const std::vector<double> &df);

      /// End the cell: its rows of D, columns condensed by @p constraints.
      void
      finish_force_cell(const unsigned int                      *vertices,
                        const std::vector<Index>                &list_dofs,
                        const dealii::AffineConstraints<double> &constraints);

      /**
       * The coupling part K_nl = (diag(1/M) D)^T C into @p product, and
       * into @p rhs_change (owned unknowns) its share -(diag(1/M) D)^T C g
       * of the right-hand side of inhomogeneous constraints. Collective.
       */
      void
      finish_matrix(std::unique_ptr<Epetra_CrsMatrix>     &product,
                    dealii::TrilinosWrappers::MPI::Vector &rhs_change);

    private:
      /// Global row of node-local node @p i, part @p s.
      Index
      row(const unsigned int i, const unsigned int s) const
      {
        return 2 * node_to_global[i] + s;
      }

      /// cell_rows: the rows of the vertices @p vertices (node-local).
      void
      set_cell_rows(const unsigned int *vertices);

      std::vector<char>  node_average; ///< per body
      bool               any_body = false;
      MPI_Comm           comm     = MPI_COMM_SELF;
      std::vector<Index> node_to_global;
      unsigned int       n_owned = 0;
      dealii::IndexSet   rows_owned, dofs_owned;

      /// m, m J, m tr h per node
      NodalVector sums;
      /// C g per row (two per node)
      NodalVector                            C_g;
      dealii::TrilinosWrappers::SparseMatrix C, D;
      std::unique_ptr<Epetra_CrsMatrix>      coupling;
      dealii::AffineConstraints<double>      no_constraints;
      dealii::FullMatrix<double>             cell_block;
      std::vector<Index>                     cell_rows;
      unsigned int                           n_list = 0;
    };
  } // namespace remedies
} // namespace mpm
