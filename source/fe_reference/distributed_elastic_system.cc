#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_minres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/numerics/data_out.h>

#include <mpm/fe_reference/boundary_constraints.h>
#include <mpm/fe_reference/distributed_elastic_system.h>
#include <mpm/fe_reference/elastic_cell_assembler.h>
#include <mpm/fe_reference/rigid_body_motion.h>
#include <mpm/utilities/input_error.h>

#include <sstream>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    namespace
    {
      /**
       * ML for the displacement block. Its near-null space is the
       * rigid-body modes evaluated at the dofs' support points (the
       * aggregates then carry the elastic energy's kernel, and the
       * iteration count stays nearly constant under refinement).
       */
      template <int dim>
      void
      initialize_amg(TrilinosWrappers::PreconditionAMG    &amg,
                     const TrilinosWrappers::SparseMatrix &A,
                     const DoFHandler<dim>                &dofs,
                     const Mapping<dim>                   &mapping,
                     const IndexSet                       &owned_u,
                     const MPI_Comm                        comm)
      {
        const auto        &fe      = dofs.get_fe();
        const unsigned int n_modes = dim == 2 ? 3 : 6;
        const auto        &map     = A.trilinos_matrix().OperatorDomainMap();
        Epetra_MultiVector modes(map, n_modes);

        // support point and component of every owned displacement dof
        std::vector<bool>                    done(owned_u.n_elements(), false);
        std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
        bool                                 interleaved = true;
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(indices);
              for (unsigned int i = 0; i < indices.size(); ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  if (c >= dim || !owned_u.is_element(indices[i]))
                    continue;
                  const auto k = owned_u.index_within_set(indices[i]);
                  if (done[k])
                    continue;
                  done[k] = true;
                  // ML groups PDE equations = dim consecutive rows as one
                  // node: right only if the numbering interleaves them
                  interleaved        = interleaved && (k % dim == c);
                  const Point<dim> x = mapping.transform_unit_to_real_cell(
                    cell, fe.unit_support_point(i));
                  modes[c][k] = 1.;
                  if constexpr (dim == 2)
                    modes[2][k] = c == 0 ? -x[1] : x[0];
                  if constexpr (dim == 3)
                    {
                      // rotations about x, y, z: e_a x x
                      modes[3][k] = c == 1 ? -x[2] : c == 2 ? x[1] : 0.;
                      modes[4][k] = c == 0 ? x[2] : c == 2 ? -x[0] : 0.;
                      modes[5][k] = c == 0 ? -x[1] : c == 1 ? x[0] : 0.;
                    }
                }
            }
        interleaved = Utilities::MPI::min(interleaved ? 1 : 0, comm) == 1;

        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = fe.degree > 1;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 1e-4;
        Teuchos::ParameterList              ml;
        std::unique_ptr<Epetra_MultiVector> unused;
        data.set_parameters(ml, unused, A);
        ml.set("PDE equations", interleaved ? int(dim) : 1);
        ml.set("null space: type", "pre-computed");
        ml.set("null space: dimension", int(n_modes));
        ml.set("null space: vectors", modes.Values());
        amg.initialize(A, ml);
      }

      /// diag(AMG(A), S^-1) with S a diagonal pressure matrix.
      class BlockDiagonalPreconditioner
      {
      public:
        BlockDiagonalPreconditioner(
          const TrilinosWrappers::PreconditionAMG &amg,
          const TrilinosWrappers::MPI::Vector     &schur_diagonal)
          : amg(amg)
          , schur_diagonal(schur_diagonal)
        {}

        void
        vmult(TrilinosWrappers::MPI::BlockVector       &dst,
              const TrilinosWrappers::MPI::BlockVector &src) const
        {
          amg.vmult(dst.block(0), src.block(0));
          dst.block(1) = src.block(1);
          dst.block(1).scale(inverse());
        }

      private:
        const TrilinosWrappers::MPI::Vector &
        inverse() const
        {
          if (inverse_diagonal.size() == 0)
            {
              inverse_diagonal = schur_diagonal;
              for (const auto i : inverse_diagonal.locally_owned_elements())
                inverse_diagonal[i] = 1. / schur_diagonal[i];
              inverse_diagonal.compress(VectorOperation::insert);
            }
          return inverse_diagonal;
        }

        const TrilinosWrappers::PreconditionAMG &amg;
        const TrilinosWrappers::MPI::Vector     &schur_diagonal;
        mutable TrilinosWrappers::MPI::Vector    inverse_diagonal;
      };
    } // namespace

    template <int dim>
    DistributedElasticSystem<dim>::DistributedElasticSystem(
      const AllParameters<dim>                        &parameters,
      const parallel::distributed::Triangulation<dim> &tria)
      : parameters(parameters)
      , comm(tria.get_communicator())
      , element(parameters)
      , dofs(tria)
    {}

    template <int dim>
    void
    DistributedElasticSystem<dim>::setup()
    {
      dofs.distribute_dofs(*element.fe);
      const unsigned int                   n_blocks = element.mixed ? 2 : 1;
      std::vector<types::global_dof_index> per_block(1, dofs.n_dofs());
      if (element.mixed)
        {
          // displacement first, then pressure; within the displacement
          // block the components stay interleaved node by node (for ML)
          std::vector<unsigned int> block_of_component(dim + 1, 0);
          block_of_component[dim] = 1;
          DoFRenumbering::component_wise(dofs, block_of_component);
          per_block =
            DoFTools::count_dofs_per_fe_block(dofs, block_of_component);
        }
      const IndexSet &owned = dofs.locally_owned_dofs();
      relevant              = DoFTools::extract_locally_relevant_dofs(dofs);
      owned_partitioning.clear();
      relevant_partitioning.clear();
      types::global_dof_index start = 0;
      for (unsigned int b = 0; b < n_blocks; ++b)
        {
          owned_partitioning.push_back(
            owned.get_view(start, start + per_block[b]));
          relevant_partitioning.push_back(
            relevant.get_view(start, start + per_block[b]));
          start += per_block[b];
        }

      constraints.clear();
      constraints.reinit(relevant);
      make_boundary_constraints(
        parameters, element.mapping, dofs, constraints, comm);

      BlockDynamicSparsityPattern dsp(relevant_partitioning);
      DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      stiffness.reinit(owned_partitioning, dsp, comm);
      load.reinit(owned_partitioning, comm);
      pressure_mass_diagonal.reinit(owned_partitioning, comm);
      solution.reinit(owned_partitioning, relevant_partitioning, comm);
    }

    template <int dim>
    typename DistributedElasticSystem<dim>::SolveStatistics
    DistributedElasticSystem<dim>::solve_static()
    {
      const auto &bc = parameters.boundary;
      if (bc.clamped.empty() && bc.prescribed.empty() &&
          constraints_admit_rigid_motion(
            element.mapping, dofs, constraints, load))
        throw InputError(free_body_message);

      SolveStatistics statistics;
      Timer           timer(comm, true);

      stiffness              = 0;
      load                   = 0;
      pressure_mass_diagonal = 0;
      ElasticCellAssembler<dim> assembler(parameters, element);
      typename ElasticCellAssembler<dim>::CellSystem cell_system;
      const unsigned int                   n = element.fe->n_dofs_per_cell();
      std::vector<types::global_dof_index> indices(n);
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            assembler.assemble(cell, false, cell_system);
            cell->get_dof_indices(indices);
            constraints.distribute_local_to_global(cell_system.stiffness,
                                                   cell_system.load,
                                                   indices,
                                                   stiffness,
                                                   load);
            if (element.mixed)
              constraints.distribute_local_to_global(
                cell_system.pressure_mass_diagonal,
                indices,
                pressure_mass_diagonal);
          }
      stiffness.compress(VectorOperation::add);
      load.compress(VectorOperation::add);
      if (element.mixed)
        {
          pressure_mass_diagonal.compress(VectorOperation::add);
          auto        &d = pressure_mass_diagonal.block(1);
          const double scale =
            1. / (2 * element.moduli.mu) + element.moduli.inverse_lambda;
          // a block's indices count from the block's first dof; a
          // constrained pressure (hanging node) has no mass of its own
          const types::global_dof_index first = owned_partitioning[0].size();
          for (const auto i : d.locally_owned_elements())
            d[i] = constraints.is_constrained(first + i) ? 1. : scale * d[i];
          d.compress(VectorOperation::insert);
        }
      statistics.assembly_seconds = timer.wall_time();

      timer.restart();
      TrilinosWrappers::PreconditionAMG amg;
      initialize_amg(amg,
                     stiffness.block(0, 0),
                     dofs,
                     element.mapping,
                     owned_partitioning[0],
                     comm);
      statistics.amg_setup_seconds = timer.wall_time();

      timer.restart();
      TrilinosWrappers::MPI::BlockVector x(owned_partitioning, comm);
      const auto                        &solver = parameters.solver;
      SolverControl                      control(solver.max_iterations,
                            solver.tolerance * load.l2_norm());
      try
        {
          if (element.mixed)
            {
              SolverMinRes<TrilinosWrappers::MPI::BlockVector> minres(control);
              minres.solve(stiffness,
                           x,
                           load,
                           BlockDiagonalPreconditioner(
                             amg, pressure_mass_diagonal.block(1)));
            }
          else
            {
              SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
              cg.solve(stiffness.block(0, 0), x.block(0), load.block(0), amg);
            }
        }
      catch (const SolverControl::NoConvergence &e)
        {
          std::ostringstream s;
          s << "in the linear solve: " << (element.mixed ? "MINRES" : "CG")
            << " did not reach Linear solver/Tolerance = " << solver.tolerance
            << " in " << e.last_step << " iterations (relative residual "
            << e.last_residual / std::max(load.l2_norm(), 1e-300)
            << "; raise Maximum iterations)";
          throw RuntimeError(s.str());
        }
      constraints.distribute(x);
      solution                 = x;
      statistics.iterations    = control.last_step();
      statistics.solve_seconds = timer.wall_time();
      return statistics;
    }

    template <int dim>
    Vector<double>
    DistributedElasticSystem<dim>::point_value(const Point<dim> &p) const
    {
      // the locally owned cells around p; the lowest rank that has one
      // reports (the field is continuous, so any owner would do)
      Vector<double> value(element.fe->n_components());
      bool           found = false;
      for (const auto &cell : dofs.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          auto box = cell->bounding_box();
          box.extend(1e-10 * box.side_length(0));
          if (!box.point_inside(p))
            continue;
          Point<dim> unit;
          try
            {
              unit = element.mapping.transform_real_to_unit_cell(cell, p);
            }
          catch (const typename Mapping<dim>::ExcTransformationFailed &)
            {
              continue;
            }
          if (!GeometryInfo<dim>::is_inside_unit_cell(unit, 1e-10))
            continue;
          const Quadrature<dim> q(
            GeometryInfo<dim>::project_to_unit_cell(unit));
          FEValues<dim> fe_values(element.mapping,
                                  *element.fe,
                                  q,
                                  update_values);
          fe_values.reinit(cell);
          std::vector<Vector<double>> v(
            1, Vector<double>(element.fe->n_components()));
          fe_values.get_function_values(solution, v);
          value = v[0];
          found = true;
          break;
        }
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      const unsigned int owner =
        Utilities::MPI::min(found ? rank : n_ranks, comm);
      if (owner == n_ranks)
        {
          std::ostringstream s;
          s << "Analysis/Points of interest: the point " << p
            << " is not inside the body";
          throw InputError(s.str());
        }
      if (rank != owner)
        value = 0;
      Utilities::MPI::sum(value, comm, value);
      return value;
    }

    template <int dim>
    void
    DistributedElasticSystem<dim>::write_vtu(const std::string &file_name) const
    {
      DataOut<dim> data_out;
      data_out.attach_dof_handler(dofs);
      std::vector<std::string> names(dim, "displacement");
      std::vector<DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          dim, DataComponentInterpretation::component_is_part_of_vector);
      if (element.mixed)
        {
          names.push_back("displacement_pressure");
          interpretation.push_back(
            DataComponentInterpretation::component_is_scalar);
        }
      data_out.add_data_vector(solution,
                               names,
                               DataOut<dim>::type_dof_data,
                               interpretation);
      data_out.build_patches(element.mapping, parameters.discretisation.degree);
      data_out.write_vtu_in_parallel(file_name, comm);
    }

    template class DistributedElasticSystem<2>;
    template class DistributedElasticSystem<3>;
  } // namespace fe_reference
} // namespace mpm
