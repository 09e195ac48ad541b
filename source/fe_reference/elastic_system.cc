#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <mpm/fe_reference/boundary_constraints.h>
#include <mpm/fe_reference/elastic_cell_assembler.h>
#include <mpm/fe_reference/elastic_system.h>
#include <mpm/fe_reference/rigid_body_motion.h>
#include <mpm/utilities/expression.h>
#include <mpm/utilities/input_error.h>

#include <fstream>
#include <limits>
#include <set>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    template <int dim>
    ElasticSystem<dim>::ElasticSystem(const AllParameters<dim> &parameters,
                                      const Triangulation<dim> &tria)
      : parameters(parameters)
      , element(parameters)
      , dofs(tria)
    {}

    template <int dim>
    void
    ElasticSystem<dim>::setup()
    {
      dofs.distribute_dofs(*element.fe);
      affine_constraints.clear();
      make_boundary_constraints(
        parameters, element.mapping, dofs, affine_constraints, MPI_COMM_SELF);

      DynamicSparsityPattern dsp(dofs.n_dofs());
      DoFTools::make_sparsity_pattern(dofs, dsp, affine_constraints, false);
      sparsity.copy_from(dsp);
      stiffness.reinit(sparsity);
      mass.reinit(sparsity);
      load.reinit(dofs.n_dofs());
      displacement.reinit(dofs.n_dofs());
    }

    template <int dim>
    void
    ElasticSystem<dim>::assemble(const bool with_mass)
    {
      stiffness = 0;
      mass      = 0;
      load      = 0;

      ElasticCellAssembler<dim> assembler(parameters, element);
      typename ElasticCellAssembler<dim>::CellSystem cell_system;
      std::vector<types::global_dof_index>           indices(
        element.fe->n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        {
          assembler.assemble(cell, with_mass, cell_system);
          cell->get_dof_indices(indices);
          affine_constraints.distribute_local_to_global(
            cell_system.stiffness, cell_system.load, indices, stiffness, load);
          if (with_mass)
            affine_constraints.distribute_local_to_global(cell_system.mass,
                                                          indices,
                                                          mass);
        }
    }

    template <int dim>
    unsigned int
    ElasticSystem<dim>::n_rigid_body_motions() const
    {
      if (parameters.boundary.has_dirichlet())
        return 0;
      // the constraints (slip, hanging nodes) are homogeneous here
      return n_admissible_rigid_motions(element.mapping,
                                        dofs,
                                        affine_constraints,
                                        Vector<double>(dofs.n_dofs()));
    }

    template <int dim>
    void
    ElasticSystem<dim>::solve_static()
    {
      if (n_rigid_body_motions() > 0)
        throw InputError(free_body_message);
      assemble(false);
      SparseDirectUMFPACK direct;
      try
        {
          direct.initialize(stiffness);
        }
      catch (const std::exception &e)
        {
          throw InputError(
            "the stiffness matrix is singular: the boundary conditions do "
            "not remove every rigid-body motion (add clamped or slip "
            "boundaries). UMFPACK: " +
            clean_dealii_message(e.what()));
        }
      direct.vmult(displacement, load);
      affine_constraints.distribute(displacement);
    }

    template <int dim>
    void
    ElasticSystem<dim>::assemble_stiffness_and_mass()
    {
      assemble(true);
      for (types::global_dof_index i = 0; i < dofs.n_dofs(); ++i)
        if (affine_constraints.is_constrained(i))
          mass.set(i, i, 0.);
    }

    template <int dim>
    Vector<double>
    ElasticSystem<dim>::point_value(const Point<dim> &p) const
    {
      Vector<double> value(element.fe->n_components());
      try
        {
          VectorTools::point_value(
            element.mapping, dofs, displacement, p, value);
        }
      catch (...)
        {
          std::ostringstream s;
          s << "Analysis/Points of interest: the point " << p
            << " is not inside the body";
          throw InputError(s.str());
        }
      return value;
    }

    template <int dim>
    std::vector<SymmetricTensor<2, dim>>
    ElasticSystem<dim>::quadrature_point_stresses() const
    {
      const QGauss<dim> quadrature(parameters.discretisation.degree + 1);
      FEValues<dim>     fe_values(element.mapping,
                              *element.fe,
                              quadrature,
                              update_values | update_gradients);
      const FEValuesExtractors::Vector     u(0);
      const FEValuesExtractors::Scalar     pressure(dim);
      std::vector<SymmetricTensor<2, dim>> eps(quadrature.size());
      std::vector<double>                  p(quadrature.size());
      std::vector<SymmetricTensor<2, dim>> out;
      for (const auto &cell : dofs.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_symmetric_gradients(displacement, eps);
          if (element.mixed)
            fe_values[pressure].get_function_values(displacement, p);
          for (unsigned int qp = 0; qp < quadrature.size(); ++qp)
            {
              const double hydrostatic =
                element.mixed ? -p[qp] : element.moduli.lambda * trace(eps[qp]);
              out.push_back(2 * element.moduli.mu * eps[qp] +
                            hydrostatic * unit_symmetric_tensor<dim>());
            }
        }
      return out;
    }

    template <int dim>
    void
    ElasticSystem<dim>::write_vtu(
      const std::string                         &file_name,
      const std::vector<const Vector<double> *> &fields,
      const std::vector<std::string>            &names) const
    {
      DataOut<dim> data_out;
      data_out.attach_dof_handler(dofs);
      for (unsigned int f = 0; f < fields.size(); ++f)
        {
          std::vector<std::string> component_names(dim, names[f]);
          std::vector<DataComponentInterpretation::DataComponentInterpretation>
            interpretation(
              dim, DataComponentInterpretation::component_is_part_of_vector);
          if (element.mixed)
            {
              component_names.push_back(names[f] + "_pressure");
              interpretation.push_back(
                DataComponentInterpretation::component_is_scalar);
            }
          data_out.add_data_vector(*fields[f],
                                   component_names,
                                   DataOut<dim>::type_dof_data,
                                   interpretation);
        }
      data_out.build_patches(element.mapping, parameters.discretisation.degree);
      std::ofstream out(file_name);
      if (!out)
        throw InputError("cannot write '" + file_name + "'");
      data_out.write_vtu(out);
    }

    template class ElasticSystem<2>;
    template class ElasticSystem<3>;
  } // namespace fe_reference
} // namespace mpm
