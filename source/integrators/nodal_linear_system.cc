#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <mpm/integrators/nodal_linear_system.h>
#include <mpm/utilities/elasticity_amg.h>

DEAL_II_DISABLE_EXTRA_DIAGNOSTICS
#include <Amesos.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>
DEAL_II_ENABLE_EXTRA_DIAGNOSTICS

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

namespace mpm
{
  using namespace dealii;

  template <int dim>
  void
  NodalLinearSystem<dim>::reinit(const BackgroundGrid<dim> &grid,
                                 const MPI_Comm             communicator,
                                 const NodeGroups          &extra)
  {
    comm                  = communicator;
    const auto  partition = grid.node_partitioner();
    const Index n         = Index(partition->size()) * dim;
    const auto  range     = partition->local_range();
    owned                 = IndexSet(n);
    owned.add_range(Index(dim) * range.first, Index(dim) * range.second);
    owned.compress();
    relevant = IndexSet(n);
    relevant.add_indices(owned);
    node_to_global.resize(grid.n_local_nodes());
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      {
        node_to_global[i] = Index(dim) * partition->local_to_global(i);
        relevant.add_range(node_to_global[i], node_to_global[i] + dim);
      }
    relevant.compress();

    NodeGroups cells;
    for (const auto &cell : grid.owned_cells())
      {
        cells.nodes.insert(cells.nodes.end(),
                           grid.nodes(cell),
                           grid.nodes(cell) + BackgroundGrid<dim>::n_vertices);
        cells.close_group();
      }
    cells.append(extra);
    grid_groups = cells;
    couple(cells);
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::couple(const NodeGroups       &groups,
                                 const Epetra_CrsMatrix *node_coupling)
  {
    DynamicSparsityPattern dsp(relevant);
    std::vector<Index>     indices;
    for (unsigned int g = 0; g + 1 < groups.start.size(); ++g)
      {
        node_indices(groups.nodes.data() + groups.start[g],
                     groups.start[g + 1] - groups.start[g],
                     indices);
        for (const Index row : indices)
          dsp.add_entries(row, indices.begin(), indices.end());
      }
    if (node_coupling)
      for (int r = 0; r < node_coupling->NumMyRows(); ++r)
        {
          const Index a = node_coupling->RowMap().GID64(r);
          int         n;
          double     *values;
          int        *columns;
          node_coupling->ExtractMyRowView(r, n, values, columns);
          for (int e = 0; e < n; ++e)
            {
              const Index b = node_coupling->ColMap().GID64(columns[e]);
              for (unsigned int c = 0; c < dim; ++c)
                for (unsigned int k = 0; k < dim; ++k)
                  dsp.add(dim * a + c, dim * b + k);
            }
        }
    // Rows that no group reaches (constrained) get their diagonal in
    // finish_assembly().
    for (const Index k : owned)
      dsp.add(k, k);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    matrix.reinit(owned, owned, dsp, comm);
    rhs.reinit(owned, comm);
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::node_indices(const unsigned int *nodes,
                                       const unsigned int  n,
                                       std::vector<Index> &indices) const
  {
    indices.resize(n * dim);
    for (unsigned int v = 0; v < n; ++v)
      for (unsigned int c = 0; c < dim; ++c)
        indices[v * dim + c] = node_to_global[nodes[v]] + c;
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::build_constraints(
    const BackgroundGrid<dim>         &grid,
    const std::vector<char>           &active,
    std::vector<unsigned char>        &prescribed,
    const std::vector<Tensor<1, dim>> &values)
  {
    // Two sets of the same lines: homogeneous for Newton's corrections,
    // and with the rigid bodies' motion for its predictor.
    for (auto *c : {&node_constraints, &prescribed_motion})
      {
        c->clear();
        c->reinit(relevant);
      }
    const auto add_line = [&](const Index k, const double value) {
      node_constraints.add_line(k);
      prescribed_motion.add_line(k);
      prescribed_motion.set_inhomogeneity(k, value);
    };
    const auto add_entry = [&](const Index k, const Index l, const double w) {
      node_constraints.add_entry(k, l, w);
      prescribed_motion.add_entry(k, l, w);
    };
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      {
        const Index        first = node_to_global[i];
        const unsigned int m     = grid.n_constrained_directions(i);
        if (!active[i] || m == dim)
          {
            prescribed[i] = 0;
            for (unsigned int c = 0; c < dim; ++c)
              add_line(first + c, 0.);
            continue;
          }
        // A wall's direction wins over a rigid body's: the body's bit
        // is cleared, the wall's constraint written instead.
        const auto take = [&](const unsigned int c) {
          prescribed[i] &= ~(1u << c);
          add_line(first + c, 0.);
        };
        // The node moves in the walls' tangent plane. One wall of normal
        // n: the component along n's largest entry follows the others,
        // n_k u_k = -sum_{d != k} n_d u_d. Two walls (3D): the node moves
        // along t = n0 x n1, the other components follow the one along
        // t's largest entry.
        if (m == 1)
          {
            const Tensor<1, dim> &n = grid.constrained_direction(i, 0);
            unsigned int          k = 0;
            for (unsigned int d = 1; d < dim; ++d)
              if (std::abs(n[d]) > std::abs(n[k]))
                k = d;
            take(k);
            for (unsigned int d = 0; d < dim; ++d)
              if (d != k && n[d] != 0.)
                add_entry(first + k, first + d, -n[d] / n[k]);
          }
        else if constexpr (dim == 3)
          if (m == 2)
            {
              const Tensor<1, dim> t =
                cross_product_3d(grid.constrained_direction(i, 0),
                                 grid.constrained_direction(i, 1));
              unsigned int k = 0;
              for (unsigned int d = 1; d < dim; ++d)
                if (std::abs(t[d]) > std::abs(t[k]))
                  k = d;
              for (unsigned int d = 0; d < dim; ++d)
                if (d != k)
                  {
                    take(d);
                    if (t[d] != 0.)
                      add_entry(first + d, first + k, t[d] / t[k]);
                  }
            }
        for (unsigned int c = 0; c < dim; ++c)
          if (prescribed[i] & (1u << c))
            add_line(first + c, values[i][c]);
      }
    node_constraints.close();
    prescribed_motion.close();
    bool any = false;
    for (const unsigned char b : prescribed)
      any = any || b != 0;
    moves_prescribed = Utilities::MPI::max(any ? 1 : 0, comm) == 1;
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::apply_homogeneous_constraints(
    const BackgroundGrid<dim> &grid,
    NodalVector               &v) const
  {
    // A node's lines refer to its own directions only (walls and nodes
    // without mass; build_constraints()).
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      {
        const Index first = node_to_global[i];
        for (unsigned int c = 0; c < dim; ++c)
          {
            if (!node_constraints.is_constrained(first + c))
              continue;
            double value = 0;
            for (const auto &[l, w] :
                 *node_constraints.get_constraint_entries(first + c))
              value += w * v.local_element(i * dim + (l - first));
            v.local_element(i * dim + c) = value;
          }
      }
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::begin_assembly(const bool with_matrix)
  {
    if (with_matrix)
      {
        matrix = 0.;
        row_columns.clear();
        row_values.clear();
        row_force_values.clear();
        row_start.assign(1, 0);
        row_moduli.clear();
      }
    rhs = 0.;
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::add_cell(const FullMatrix<double> &cell_matrix,
                                   const Vector<double>     &cell_rhs,
                                   const std::vector<Index> &indices)
  {
    constraints().distribute_local_to_global(
      cell_matrix, cell_rhs, indices, matrix, rhs);
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::add_cell(const FullMatrix<double>        &cell_matrix,
                                   const Vector<double>            &cell_rhs,
                                   const std::vector<Index>        &indices,
                                   const std::vector<CellPressure> &pressures)
  {
    if (!split || pressures.empty())
      {
        add_cell(cell_matrix, cell_rhs, indices);
        return;
      }
    const auto        &c = constraints();
    const unsigned int n = indices.size();
    rest_matrix          = cell_matrix;
    for (const CellPressure &q : pressures)
      {
        // the rows b^T C and g^T C of the condensed unknowns: a
        // constrained direction's share goes to the directions its line
        // names
        const std::vector<double> &g = q.g.empty() ? q.b : q.g;
        std::vector<std::tuple<Index, double, double>> row;
        for (unsigned int j = 0; j < n; ++j)
          {
            if (q.b[j] == 0. && g[j] == 0.)
              continue;
            if (!c.is_constrained(indices[j]))
              row.emplace_back(indices[j], q.b[j], g[j]);
            else
              for (const auto &[l, w] : *c.get_constraint_entries(indices[j]))
                row.emplace_back(l, w * q.b[j], w * g[j]);
          }
        std::sort(row.begin(), row.end());
        double     norm  = 0;
        const auto first = row_columns.size();
        for (const auto &[l, v, f] : row)
          if (row_columns.size() > first && row_columns.back() == l)
            {
              row_values.back() += v;
              row_force_values.back() += f;
            }
          else
            {
              row_columns.push_back(l);
              row_values.push_back(v);
              row_force_values.push_back(f);
            }
        for (auto k = first; k < row_values.size(); ++k)
          norm += row_values[k] * row_values[k];
        if (!(norm > 0))
          {
            // nothing of it is free: the condensed part is zero anyway
            row_columns.resize(first);
            row_values.resize(first);
            row_force_values.resize(first);
            continue;
          }
        row_start.push_back(row_columns.size());
        row_moduli.push_back({{q.lambda, q.rest_modulus, q.volume}});
        const double k = q.lambda / q.volume;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            rest_matrix(i, j) -= k * g[i] * q.b[j];
      }
    c.distribute_local_to_global(cell_rhs, indices, rhs, cell_matrix);
    c.distribute_local_to_global(rest_matrix, indices, matrix);
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::add_cell_rhs(const Vector<double>     &cell_rhs,
                                       const std::vector<Index> &indices)
  {
    constraints().distribute_local_to_global(cell_rhs, indices, rhs);
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::finish_assembly(
    const bool                           with_matrix,
    const Epetra_CrsMatrix              *coupling,
    const TrilinosWrappers::MPI::Vector *rhs_change)
  {
    rhs.compress(VectorOperation::add);
    if (rhs_change)
      rhs.add(1., *rhs_change);
    if (!with_matrix)
      return;
    matrix.compress(VectorOperation::add);
    if (coupling)
      {
        std::vector<Index> columns;
        for (int r = 0; r < coupling->NumMyRows(); ++r)
          {
            int     n;
            double *values;
            int    *local;
            coupling->ExtractMyRowView(r, n, values, local);
            columns.resize(n);
            for (int e = 0; e < n; ++e)
              columns[e] = coupling->ColMap().GID64(local[e]);
            matrix.add(
              coupling->RowMap().GID64(r), n, columns.data(), values, false);
          }
        matrix.compress(VectorOperation::add);
      }
    // A constrained row that no cell with particles reached is empty: it
    // gets the mean diagonal of the free rows (its solution is set by the
    // constraint anyway).
    double sum = 0, count = 0;
    for (const Index k : owned)
      if (!constraints().is_constrained(k))
        {
          sum += std::abs(matrix.diag_element(k));
          ++count;
        }
    sum            = Utilities::MPI::sum(sum, comm);
    count          = Utilities::MPI::sum(count, comm);
    diagonal_scale = count > 0 && sum > 0 ? sum / count : 1.;
    for (const Index k : owned)
      if (constraints().is_constrained(k) && matrix.diag_element(k) == 0.)
        matrix.set(k, k, diagonal_scale);
    matrix.compress(VectorOperation::insert);
    if (split)
      build_cell_pressure();
  }

  template <int dim>
  void
  NodalLinearSystem<dim>::build_cell_pressure()
  {
    const Index n_rows = row_moduli.size();
    Index       first  = 0; // the rows of the lower ranks
    MPI_Exscan(&n_rows,
               &first,
               1,
               Utilities::MPI::mpi_type_id_for_type<Index>,
               MPI_SUM,
               comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      first = 0;
    const Index n_all = Utilities::MPI::sum(n_rows, comm);
    pressure_owned    = IndexSet(n_all);
    pressure_owned.add_range(first, first + n_rows);
    pressure_owned.compress();
    if (n_all == 0)
      return;
    TrilinosWrappers::SparsityPattern pattern(pressure_owned, owned, comm);
    for (Index r = 0; r < n_rows; ++r)
      pattern.add_entries(first + r,
                          row_columns.begin() + row_start[r],
                          row_columns.begin() + row_start[r + 1]);
    pattern.compress();
    volume_gradient.reinit(pattern);
    force_gradient.reinit(pattern);
    for (Index r = 0; r < n_rows; ++r)
      {
        const auto n = row_start[r + 1] - row_start[r];
        volume_gradient.set(first + r,
                            n,
                            row_columns.data() + row_start[r],
                            row_values.data() + row_start[r]);
        force_gradient.set(first + r,
                           n,
                           row_columns.data() + row_start[r],
                           row_force_values.data() + row_start[r]);
      }
    volume_gradient.compress(VectorOperation::insert);
    force_gradient.compress(VectorOperation::insert);

    // Per row: l = |b|, W = l lambda_s / V, and the Schur complement's
    // estimate (the augmented-Lagrangian one: K_rest keeps gamma mu of
    // the volumetric stiffness, so B K_rest^-1 C^T ~ V / ((gamma + 1) mu)
    // on the cell's pressure). The row and column sums of |g| / l bound
    // the map C^T diag(1/l) from the pressure rows' residual to the
    // tangent's (solve_with_cell_pressure()).
    row_scale.reinit(pressure_owned, comm);
    row_weight.reinit(pressure_owned, comm);
    schur_inverse.reinit(pressure_owned, comm);
    TrilinosWrappers::MPI::Vector column_sums;
    column_sums.reinit(owned, relevant, comm, true);
    double row_sum_max = 0;
    for (Index r = 0; r < n_rows; ++r)
      {
        double b_b = 0, g_sum = 0;
        for (auto e = row_start[r]; e < row_start[r + 1]; ++e)
          {
            b_b += row_values[e] * row_values[e];
            g_sum += std::abs(row_force_values[e]);
          }
        const auto &[lambda, rest_modulus, volume] = row_moduli[r];
        const double l                             = std::sqrt(b_b);
        const double w                             = l * lambda / volume;
        row_scale[first + r]                       = l;
        row_weight[first + r]                      = w;
        schur_inverse[first + r] = 1. / (l + w * volume / rest_modulus);
        row_sum_max              = std::max(row_sum_max, g_sum / l);
        for (auto e = row_start[r]; e < row_start[r + 1]; ++e)
          column_sums[row_columns[e]] += std::abs(row_force_values[e]) / l;
      }
    column_sums.compress(VectorOperation::add);
    // |C^T diag(1/l)|_2 <= sqrt(|.|_1 |.|_inf)
    residual_bound = 1. + std::sqrt(Utilities::MPI::max(row_sum_max, comm) *
                                    column_sums.linfty_norm());
    row_scale.compress(VectorOperation::insert);
    row_weight.compress(VectorOperation::insert);
    schur_inverse.compress(VectorOperation::insert);
  }

  namespace
  {
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    /// [K_rest, C^T; W B, -l] (NodalLinearSystem::solve_with_cell_pressure)
    struct CellPressureOperator
    {
      const TrilinosWrappers::SparseMatrix &K_rest, &B, &C;
      const TrilinosWrappers::MPI::Vector  &scale, &weight;
      /// l p, kept between the solver's calls (no allocation per call)
      mutable TrilinosWrappers::MPI::Vector lp;

      void
      vmult(BlockVector &dst, const BlockVector &src) const
      {
        K_rest.vmult(dst.block(0), src.block(0));
        C.Tvmult_add(dst.block(0), src.block(1));
        B.vmult(dst.block(1), src.block(0));
        dst.block(1).scale(weight);
        lp = src.block(1);
        lp.scale(scale);
        dst.block(1) -= lp;
      }
    };

    /// [AMG(K_rest), C^T; 0, -S]^-1
    struct CellPressurePreconditioner
    {
      const TrilinosWrappers::PreconditionAMG &amg;
      const TrilinosWrappers::SparseMatrix    &C;
      const TrilinosWrappers::MPI::Vector     &schur_inverse;
      /// r_x - C^T p, kept between the solver's calls
      mutable TrilinosWrappers::MPI::Vector r;

      void
      vmult(BlockVector &dst, const BlockVector &src) const
      {
        // p = -S^-1 r_p, x = AMG (r_x - C^T p)
        dst.block(1) = src.block(1);
        dst.block(1).scale(schur_inverse);
        r = src.block(0);
        C.Tvmult_add(r, dst.block(1));
        amg.vmult(dst.block(0), r);
        dst.block(1) *= -1.;
      }
    };
  } // namespace

  template <int dim>
  unsigned int
  NodalLinearSystem<dim>::solve_with_cell_pressure(
    const TrilinosWrappers::PreconditionAMG &amg,
    const Parameters::ImplicitSolver        &p,
    TrilinosWrappers::MPI::Vector           &x)
  {
    const CellPressureOperator K{
      matrix, volume_gradient, force_gradient, row_scale, row_weight, {}};
    const CellPressurePreconditioner P{amg, force_gradient, schur_inverse, {}};
    BlockVector                      y({owned, pressure_owned}, comm);
    BlockVector                      f({owned, pressure_owned}, comm);
    f.block(0) = rhs;
    // The tangent's residual is r_x + C^T diag(1/l) r_p (the pressure
    // rows' residual r_p has force units): below the tolerance when the
    // block residual is below it divided by 1 + |C^T diag(1/l)|.
    SolverControl            control(p.max_linear_iterations,
                          p.linear_tolerance * rhs.l2_norm() / residual_bound);
    SolverGMRES<BlockVector> gmres(
      control, SolverGMRES<BlockVector>::AdditionalData(100, true));
    gmres.solve(K, y, f, P);
    x = y.block(0);
    return control.last_step();
  }

  namespace
  {
    /// x = A^-1 b by Amesos' @p package on the processes of A's map: ""
    /// or what failed.
    std::string
    factorise_and_solve(const bool          klu,
                        Epetra_CrsMatrix   &A,
                        Epetra_MultiVector &x,
                        Epetra_MultiVector &b)
    {
      Epetra_LinearProblem                     problem(&A, &x, &b);
      Amesos                                   factory;
      const std::unique_ptr<Amesos_BaseSolver> direct(
        factory.Create(klu ? "Amesos_Klu" : "Amesos_Mumps", problem));
      if (!direct)
        return std::string("Trilinos Amesos has no solver ") +
               (klu ? "KLU" : "MUMPS");
      const auto failed = [](const int status, const char *phase) {
        return std::string("the direct solver's ") + phase +
               " failed (Amesos status " + std::to_string(status) + ")";
      };
      if (const int status = direct->SymbolicFactorization())
        return failed(status, "symbolic factorization");
      if (const int status = direct->NumericFactorization())
        return failed(status, "factorization");
      if (const int status = direct->Solve())
        return failed(status, "solve");
      return "";
    }
  } // namespace

  template <int dim>
  void
  NodalLinearSystem<dim>::solve_direct(
    const Parameters::ImplicitSolver::DirectSolver package,
    TrilinosWrappers::MPI::Vector                 &x)
  {
    const bool klu = package == Parameters::ImplicitSolver::DirectSolver::klu;
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      {
        const std::string error =
          factorise_and_solve(klu,
                              const_cast<Epetra_CrsMatrix &>(A),
                              x.trilinos_vector(),
                              rhs.trilinos_vector());
        if (!error.empty())
          throw std::runtime_error(error);
        return;
      }
    // On several ranks the matrix and the right-hand side are gathered on
    // rank 0 and factorised there by a solver that sees one process only.
    // Amesos' own distributed entry (even with MUMPS on one process of
    // it) gives solutions that differ in their last bits from run to run:
    // a run would neither repeat itself nor resume from a checkpoint bit
    // for bit.
    const bool          root = Utilities::MPI::this_mpi_process(comm) == 0;
    const int           n    = A.NumGlobalRows();
    const Epetra_Map    on_root(n, root ? n : 0, 0, A.Comm());
    const Epetra_Import gather(on_root, A.RowMap());
    Epetra_CrsMatrix    A_root(Copy, on_root, 0);
    Epetra_Vector       b_root(on_root), x_root(on_root);
    // Epetra's negative codes are errors, its positive ones warnings.
    // Every rank makes each of these collective calls, whatever an
    // earlier one returned.
    const int import_status = A_root.Import(A, gather, Insert);
    const int fill_status   = A_root.FillComplete();
    const int rhs_status = b_root.Import(rhs.trilinos_vector(), gather, Insert);
    const bool gathered =
      Utilities::MPI::min(std::min({import_status, fill_status, rhs_status}),
                          comm) >= 0;
    std::string error =
      gathered ? "" : "gathering the matrix on one process failed";
    if (gathered && root)
      {
        const Epetra_MpiComm self(MPI_COMM_SELF);
        const Epetra_Map     serial(n, n, 0, self);
        Epetra_CrsMatrix     A_serial(Copy, serial, 0);
        std::vector<int>     columns;
        bool                 copied = true;
        for (int r = 0; r < n; ++r)
          {
            int     entries;
            double *values;
            int    *local;
            A_root.ExtractMyRowView(r, entries, values, local);
            columns.resize(entries);
            for (int e = 0; e < entries; ++e)
              columns[e] = A_root.ColMap().GID(local[e]);
            copied =
              copied &&
              A_serial.InsertGlobalValues(r, entries, values, columns.data()) >=
                0;
          }
        copied = copied && A_serial.FillComplete() >= 0;
        Epetra_Vector b_serial(View, serial, b_root.Values());
        Epetra_Vector x_serial(View, serial, x_root.Values());
        error = copied ?
                  factorise_and_solve(klu, A_serial, x_serial, b_serial) :
                  "copying the gathered matrix failed";
      }
    // every rank learns the outcome before any of them throws
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw std::runtime_error(error);
    x.trilinos_vector().Export(x_root, gather, Insert);
  }

  template <int dim>
  typename NodalLinearSystem<dim>::SolveResult
  NodalLinearSystem<dim>::solve(
    const BackgroundGrid<dim>                     &grid,
    const Parameters::ImplicitSolver              &p,
    const Parameters::ImplicitSolver::LinearSolver solver,
    TrilinosWrappers::MPI::Vector                 &x)
  {
    using LinearSolver = Parameters::ImplicitSolver::LinearSolver;
    SolveResult result;
    x.reinit(owned, comm);
    try
      {
        if (solver == LinearSolver::direct)
          {
            solve_direct(p.direct_solver, x);
            result.iterations = 1;
          }
        else
          {
            // the rigid-body modes of the nodes, rotations about the nodes'
            // mean position
            const auto &map = matrix.trilinos_matrix().OperatorDomainMap();
            Epetra_MultiVector modes(map, n_rigid_body_modes<dim>);
            const unsigned int n_owned = grid.n_owned_nodes();
            Point<dim>         centre;
            for (unsigned int i = 0; i < n_owned; ++i)
              centre += grid.node_position(i);
            const double n_all = Utilities::MPI::sum(double(n_owned), comm);
            for (unsigned int d = 0; d < dim; ++d)
              centre[d] = Utilities::MPI::sum(centre[d], comm) / n_all;
            for (unsigned int i = 0; i < n_owned; ++i)
              {
                const Tensor<1, dim> r = grid.node_position(i) - centre;
                for (unsigned int k = 0; k < n_rigid_body_modes<dim>; ++k)
                  for (unsigned int c = 0; c < dim; ++c)
                    modes[k][i * dim + c] = rigid_body_mode<dim>(k, c, r);
              }
            TrilinosWrappers::PreconditionAMG amg;
            initialize_elasticity_amg(amg, matrix, modes, dim, false);

            if (split && pressure_owned.size() > 0)
              {
                result.iterations = solve_with_cell_pressure(amg, p, x);
                constraints().distribute(x);
                return result;
              }
            SolverControl control(p.max_linear_iterations,
                                  p.linear_tolerance * rhs.l2_norm());
            if (solver == LinearSolver::cg)
              {
                SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
                cg.solve(matrix, x, rhs, amg);
              }
            else
              {
                // Right preconditioning: the tolerance applies to the
                // true residual (a force), not to the preconditioned one,
                // which AMG scales by the inverse stiffness.
                SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
                  control,
                  SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                    100, true));
                gmres.solve(matrix, x, rhs, amg);
              }
            result.iterations = control.last_step();
          }
      }
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream s;
        s << "the linear solver did not converge in " << e.last_step
          << " iterations (residual " << e.last_residual << ")";
        result.error      = s.str();
        result.iterations = e.last_step;
      }
    catch (const std::exception &e)
      {
        result.error = std::string("the linear solver failed: ") + e.what();
      }
    constraints().distribute(x);
    return result;
  }

  template class NodalLinearSystem<1>;
  template class NodalLinearSystem<2>;
  template class NodalLinearSystem<3>;
} // namespace mpm
