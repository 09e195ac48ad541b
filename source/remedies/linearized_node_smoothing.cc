#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <mpm/remedies/linearized_node_smoothing.h>
#include <mpm/remedies/volumetric_smoothing.h>

DEAL_II_DISABLE_EXTRA_DIAGNOSTICS
#include <EpetraExt_MatrixMatrix.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_RowMatrixTransposer.h>
DEAL_II_ENABLE_EXTRA_DIAGNOSTICS

namespace mpm
{
  namespace remedies
  {
    using namespace dealii;

    template <int dim>
    LinearizedNodeSmoothing<dim>::LinearizedNodeSmoothing(
      const std::vector<Body<dim>> &bodies)
      : node_average(bodies.size())
    {
      const VolumetricSmoothing<dim> smoothing(bodies);
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          node_average[b] = smoothing.average(b) == VolumeAverage::node &&
                            !bodies[b].is_rigid();
          any_body = any_body || node_average[b];
        }
    }

    namespace
    {
      /// A Trilinos matrix of rows @p rows_owned (the entries of @p dsp,
      /// which may hold rows of other ranks, exchanged) and columns
      /// @p cols_owned.
      void
      make_matrix(TrilinosWrappers::SparseMatrix &matrix,
                  DynamicSparsityPattern         &dsp,
                  const IndexSet                 &rows_owned,
                  const IndexSet                 &rows_relevant,
                  const IndexSet                 &cols_owned,
                  const MPI_Comm                  comm)
      {
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   rows_owned,
                                                   comm,
                                                   rows_relevant);
        matrix.reinit(rows_owned, cols_owned, dsp, comm);
      }

      /// @p product = A^T B for A and B of the same rows, by an explicit
      /// transpose (EpetraExt's transposed product gives rows of wrong
      /// lengths on several ranks, deal.II 9.4's Tmmult and its wrapping
      /// of an Epetra matrix write out of bounds).
      void
      transpose_product(const TrilinosWrappers::SparseMatrix &A,
                        const TrilinosWrappers::SparseMatrix &B,
                        std::unique_ptr<Epetra_CrsMatrix>    &product)
      {
        Epetra_RowMatrixTransposer transposer(
          const_cast<Epetra_CrsMatrix *>(&A.trilinos_matrix()));
        Epetra_CrsMatrix *transposed = nullptr;
        Epetra_Map        rows(A.trilinos_matrix().DomainMap());
        int status = transposer.CreateTranspose(true, transposed, &rows);
        const std::unique_ptr<Epetra_CrsMatrix> A_T(transposed);
        if (status == 0)
          {
            product = std::make_unique<Epetra_CrsMatrix>(Copy, rows, 0);
            status  = EpetraExt::MatrixMatrix::Multiply(
              *A_T, false, B.trilinos_matrix(), false, *product);
          }
        AssertThrow(status == 0,
                    ExcMessage("the node average's matrix product failed "
                               "(Epetra error " +
                               std::to_string(status) + ")"));
      }
    } // namespace

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::begin_step(
      const BackgroundGrid<dim>       &grid,
      const MPI_Comm                   communicator,
      const std::vector<unsigned int> &vertices,
      const std::vector<unsigned int> &reach,
      const std::vector<unsigned int> &reach_start)
    {
      comm                  = communicator;
      const auto  partition = grid.node_partitioner();
      const Index n_nodes   = partition->size();
      const auto  range     = partition->local_range();
      n_owned               = grid.n_owned_nodes();
      node_to_global.resize(grid.n_local_nodes());
      IndexSet nodes_owned(n_nodes), nodes_relevant(n_nodes);
      nodes_owned.add_range(range.first, range.second);
      rows_owned = IndexSet(2 * n_nodes);
      rows_owned.add_range(2 * Index(range.first), 2 * Index(range.second));
      dofs_owned = IndexSet(dim * n_nodes);
      dofs_owned.add_range(dim * Index(range.first), dim * Index(range.second));
      IndexSet rows_relevant(2 * n_nodes);
      for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
        {
          node_to_global[i] = partition->local_to_global(i);
          nodes_relevant.add_index(node_to_global[i]);
          rows_relevant.add_range(row(i, 0), row(i, 0) + 2);
        }
      for (auto *set : {&nodes_owned,
                        &nodes_relevant,
                        &rows_owned,
                        &rows_relevant,
                        &dofs_owned})
        set->compress();

      // C and D share their sparsity: a cell's vertices (rows) with the
      // unknowns of the nodes its particles reach. The node-level pattern
      // B (ones) gives the product's nodes: B^T B.
      DynamicSparsityPattern rows_dsp(2 * n_nodes,
                                      dim * n_nodes,
                                      rows_relevant);
      DynamicSparsityPattern nodes_dsp(n_nodes, n_nodes, nodes_relevant);
      std::vector<Index>     dofs;
      const unsigned int     n_cells = reach_start.size() - 1;
      for (unsigned int c = 0; c < n_cells; ++c)
        {
          dofs.clear();
          for (unsigned int k = reach_start[c]; k < reach_start[c + 1]; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              dofs.push_back(dim * node_to_global[reach[k]] + d);
          std::sort(dofs.begin(), dofs.end());
          for (unsigned int v = 0; v < nv; ++v)
            {
              const unsigned int i = vertices[c * nv + v];
              for (unsigned int s = 0; s < 2; ++s)
                rows_dsp.add_entries(row(i, s), dofs.begin(), dofs.end());
              for (unsigned int k = reach_start[c]; k < reach_start[c + 1]; ++k)
                nodes_dsp.add(node_to_global[i], node_to_global[reach[k]]);
            }
        }
      make_matrix(C, rows_dsp, rows_owned, rows_relevant, dofs_owned, comm);
      D.reinit(C);
      TrilinosWrappers::SparseMatrix pattern;
      make_matrix(
        pattern, nodes_dsp, nodes_owned, nodes_relevant, nodes_owned, comm);
      for (unsigned int c = 0; c < n_cells; ++c)
        for (unsigned int v = 0; v < nv; ++v)
          for (unsigned int k = reach_start[c]; k < reach_start[c + 1]; ++k)
            pattern.add(node_to_global[vertices[c * nv + v]],
                        node_to_global[reach[k]],
                        1.);
      pattern.compress(VectorOperation::add);
      transpose_product(pattern, pattern, coupling);
      grid.initialize_vector(sums, 3);
      grid.initialize_vector(C_g, 2);
    }

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::begin_assembly(const bool with_matrix)
    {
      sums = 0.;
      if (!with_matrix)
        return;
      C   = 0.;
      D   = 0.;
      C_g = 0.;
    }

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::add_state(const unsigned int   *vertices,
                                            const double         *N,
                                            const double          m,
                                            const double          J,
                                            const double          tr_h,
                                            const bool            with_matrix,
                                            const Tensor<2, dim> &f_inv_T,
                                            const Tensor<1, dim> *G)
    {
      for (unsigned int v = 0; v < nv; ++v)
        {
          double *node = sums.begin() + vertices[v] * 3;
          node[0] += N[v] * m;
          node[1] += N[v] * m * J;
          node[2] += N[v] * m * tr_h;
        }
      if (!with_matrix)
        return;
      // d J / du_bk = J (f^-T G_b)_k, d tr h / du_bk = (G_b)_k
      for (unsigned int b = 0; b < n_list; ++b)
        {
          const Tensor<1, dim> dJ = J * (f_inv_T * G[b]);
          for (unsigned int v = 0; v < nv; ++v)
            for (unsigned int k = 0; k < dim; ++k)
              {
                cell_block(2 * v, b * dim + k) += N[v] * m * dJ[k];
                cell_block(2 * v + 1, b * dim + k) += N[v] * m * G[b][k];
              }
        }
    }

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::set_cell_rows(const unsigned int *vertices)
    {
      cell_rows.resize(2 * nv);
      for (unsigned int v = 0; v < nv; ++v)
        for (unsigned int s = 0; s < 2; ++s)
          cell_rows[2 * v + s] = row(vertices[v], s);
    }

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::finish_state_cell(
      const unsigned int              *vertices,
      const std::vector<Index>        &list_dofs,
      const AffineConstraints<double> &constraints)
    {
      set_cell_rows(vertices);
      // C g: the prescribed values' share, which condensing drops
      for (unsigned int c = 0; c < list_dofs.size(); ++c)
        if (constraints.is_inhomogeneously_constrained(list_dofs[c]))
          {
            const double g = constraints.get_inhomogeneity(list_dofs[c]);
            for (unsigned int v = 0; v < nv; ++v)
              for (unsigned int s = 0; s < 2; ++s)
                C_g.local_element(vertices[v] * 2 + s) +=
                  cell_block(2 * v + s, c) * g;
          }
      no_constraints.distribute_local_to_global(
        cell_block, cell_rows, constraints, list_dofs, C);
    }

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::finish_sums(const bool with_matrix)
    {
      sums.compress(VectorOperation::add);
      sums.update_ghost_values();
      if (!with_matrix)
        return;
      C.compress(VectorOperation::add);
      C_g.compress(VectorOperation::add);
    }

    template <int dim>
    bool
    LinearizedNodeSmoothing<dim>::averages(const unsigned int *vertices,
                                           const double       *N,
                                           double             &J_bar,
                                           double             &theta_bar,
                                           double             &S) const
    {
      // as the explicit update: N over the nodes with mass
      S = J_bar = theta_bar = 0;
      for (unsigned int v = 0; v < nv; ++v)
        {
          const double *node = sums.begin() + vertices[v] * 3;
          if (node[0] > 0)
            {
              S += N[v];
              J_bar += N[v] * node[1] / node[0];
              theta_bar += N[v] * node[2] / node[0];
            }
        }
      if (!(S > 0))
        return false;
      J_bar /= S;
      theta_bar /= S;
      return true;
    }

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::begin_cell(const unsigned int n)
    {
      n_list = n;
      cell_block.reinit(2 * nv, n * dim);
    }

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::add_force_derivative(
      const unsigned int        *vertices,
      const double              *N,
      const double               S,
      const bool                 total,
      const std::vector<double> &df)
    {
      // (the rows carry diag(1/M) of the product)
      const unsigned int s = total ? 0 : 1;
      for (unsigned int v = 0; v < nv; ++v)
        {
          const double M = sums.local_element(vertices[v] * 3);
          if (!(M > 0))
            continue;
          const double w = N[v] / (S * M);
          for (unsigned int c = 0; c < df.size(); ++c)
            cell_block(2 * v + s, c) += w * df[c];
        }
    }

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::finish_force_cell(
      const unsigned int              *vertices,
      const std::vector<Index>        &list_dofs,
      const AffineConstraints<double> &constraints)
    {
      set_cell_rows(vertices);
      no_constraints.distribute_local_to_global(
        cell_block, cell_rows, constraints, list_dofs, D);
    }

    template <int dim>
    void
    LinearizedNodeSmoothing<dim>::finish_matrix(
      std::unique_ptr<Epetra_CrsMatrix> &product,
      TrilinosWrappers::MPI::Vector     &rhs_change)
    {
      D.compress(VectorOperation::add);
      transpose_product(D, C, product);
      TrilinosWrappers::MPI::Vector C_g_rows(rows_owned, comm);
      for (unsigned int k = 0; k < 2 * n_owned; ++k)
        C_g_rows.begin()[k] = C_g.local_element(k);
      rhs_change.reinit(dofs_owned, comm);
      D.Tvmult(rhs_change, C_g_rows);
      rhs_change *= -1.;
    }

    template class LinearizedNodeSmoothing<1>;
    template class LinearizedNodeSmoothing<2>;
    template class LinearizedNodeSmoothing<3>;
  } // namespace remedies
} // namespace mpm
