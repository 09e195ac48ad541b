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
#include <mpm/utilities/elasticity_amg.h>
#include <mpm/utilities/input_error.h>

#include <sstream>

#include <Epetra_MultiVector.h>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    namespace
    {
      /**
       * ML for the displacement block, with the rigid-body modes at the
       * displacement dofs' support points as near-null space.
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
        const auto        &fe = dofs.get_fe();
        Epetra_MultiVector modes(A.trilinos_matrix().OperatorDomainMap(),
                                 n_rigid_body_modes<dim>);

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
                  for (unsigned int m = 0; m < n_rigid_body_modes<dim>; ++m)
                    modes[m][k] = rigid_body_mode<dim>(m, c, x);
                }
            }
        interleaved = Utilities::MPI::min(interleaved ? 1 : 0, comm) == 1;
        initialize_elasticity_amg(
          amg, A, modes, interleaved ? dim : 1, fe.degree > 1);
      }

      /// diag(AMG(A), S^-1) with S a diagonal pressure matrix, given by
      /// its inverse.
      class BlockDiagonalPreconditioner
      {
      public:
        BlockDiagonalPreconditioner(
          const TrilinosWrappers::PreconditionAMG &amg,
          const TrilinosWrappers::MPI::Vector     &inverse_schur_diagonal)
          : amg(amg)
          , inverse_schur_diagonal(inverse_schur_diagonal)
        {}

        void
        vmult(TrilinosWrappers::MPI::BlockVector       &dst,
              const TrilinosWrappers::MPI::BlockVector &src) const
        {
          amg.vmult(dst.block(0), src.block(0));
          dst.block(1) = src.block(1);
          dst.block(1).scale(inverse_schur_diagonal);
        }

      private:
        const TrilinosWrappers::PreconditionAMG &amg;
        const TrilinosWrappers::MPI::Vector     &inverse_schur_diagonal;
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
      inverse_schur_diagonal.reinit(owned_partitioning, comm);
      solution.reinit(owned_partitioning, relevant_partitioning, comm);
    }

    template <int dim>
    typename DistributedElasticSystem<dim>::SolveStatistics
    DistributedElasticSystem<dim>::solve_static()
    {
      if (!parameters.boundary.has_dirichlet() &&
          n_admissible_rigid_motions(element.mapping, dofs, constraints, load) >
            0)
        throw InputError(free_body_message);

      SolveStatistics statistics;
      Timer           timer(comm, true);

      stiffness              = 0;
      load                   = 0;
      inverse_schur_diagonal = 0;
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
                inverse_schur_diagonal);
          }
      stiffness.compress(VectorOperation::add);
      load.compress(VectorOperation::add);
      if (element.mixed)
        {
          inverse_schur_diagonal.compress(VectorOperation::add);
          auto        &d = inverse_schur_diagonal.block(1);
          const double scale =
            1. / (2 * element.moduli.mu) + element.moduli.inverse_lambda;
          // a block's indices count from the block's first dof; a
          // constrained pressure (hanging node) has no mass of its own
          const types::global_dof_index first = owned_partitioning[0].size();
          for (const auto i : d.locally_owned_elements())
            d[i] =
              constraints.is_constrained(first + i) ? 1. : 1. / (scale * d[i]);
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
      // CG measures the true residual against the load. MINRES measures
      // the residual in the preconditioner's norm, whose scale follows the
      // inverse moduli: it is reduced by the same fraction instead, so
      // that the accuracy does not depend on the units.
      const double     load_norm = load.l2_norm();
      SolverControl    cg_control(solver.max_iterations,
                               solver.tolerance * load_norm);
      ReductionControl minres_control(solver.max_iterations,
                                      0.,
                                      solver.tolerance);
      SolverControl   &control = element.mixed ? minres_control : cg_control;
      try
        {
          if (element.mixed)
            {
              SolverMinRes<TrilinosWrappers::MPI::BlockVector> minres(
                minres_control);
              minres.solve(stiffness,
                           x,
                           load,
                           BlockDiagonalPreconditioner(
                             amg, inverse_schur_diagonal.block(1)));
            }
          else
            {
              SolverCG<TrilinosWrappers::MPI::Vector> cg(cg_control);
              cg.solve(stiffness.block(0, 0), x.block(0), load.block(0), amg);
            }
        }
      catch (const SolverControl::NoConvergence &e)
        {
          std::ostringstream s;
          s << "in the linear solve: " << (element.mixed ? "MINRES" : "CG")
            << " did not reach Linear solver/Tolerance = " << solver.tolerance
            << " in " << e.last_step << " iterations (relative residual "
            << e.last_residual / std::max(element.mixed ?
                                            minres_control.initial_value() :
                                            load_norm,
                                          1e-300)
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
