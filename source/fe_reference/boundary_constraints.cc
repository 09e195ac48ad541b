#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/numerics/vector_tools.h>

#include <mpm/fe_reference/boundary_constraints.h>
#include <mpm/fe_reference/displacement_function.h>
#include <mpm/utilities/expression.h>
#include <mpm/utilities/input_error.h>

#include <set>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    template <int dim>
    void
    make_boundary_constraints(const AllParameters<dim>  &parameters,
                              const Mapping<dim>        &mapping,
                              const DoFHandler<dim>     &dofs,
                              AffineConstraints<double> &constraints,
                              const MPI_Comm             comm)
    {
      const auto                      &fe = dofs.get_fe();
      const FEValuesExtractors::Vector u(0);
      const ComponentMask              u_mask = fe.component_mask(u);
      const auto                      &bc     = parameters.boundary;

      // which ids the mesh has, so that a misspelled id is reported; a
      // distributed mesh holds only part of the boundary on each process
      std::set<types::boundary_id> local_ids;
      for (const auto &face : dofs.get_triangulation().active_face_iterators())
        if (face->at_boundary())
          local_ids.insert(face->boundary_id());
      const std::set<types::boundary_id> mesh_ids =
        Utilities::MPI::compute_set_union(local_ids, comm);
      for (const auto *list :
           {&bc.clamped, &bc.slip, &bc.prescribed, &bc.traction_ids})
        for (const auto id : *list)
          if (mesh_ids.count(id) == 0)
            {
              std::string present;
              for (const auto m : mesh_ids)
                present += (present.empty() ? "" : ", ") + std::to_string(m);
              throw InputError("Boundary conditions: boundary id " +
                               std::to_string(id) +
                               " does not occur on the mesh (its boundary "
                               "ids: " +
                               present + "; see Geometry/Type)");
            }

      DoFTools::make_hanging_node_constraints(dofs, constraints);
      const Functions::ZeroFunction<dim> zero(fe.n_components());
      for (const auto id : bc.clamped)
        VectorTools::interpolate_boundary_values(
          mapping, dofs, id, zero, constraints, u_mask);
      const Expression<dim>           prescribed(bc.prescribed_displacement,
                                       dim,
                                       dim == 2 ? "x,y" : "x,y,z",
                                       parameters.constants,
                                       false,
                                       "Prescribed displacement");
      const DisplacementFunction<dim> g(prescribed, fe.n_components());
      for (const auto id : bc.prescribed)
        VectorTools::interpolate_boundary_values(
          mapping, dofs, id, g, constraints, u_mask);
      if (!bc.slip.empty())
        VectorTools::compute_no_normal_flux_constraints(
          dofs,
          0,
          std::set<types::boundary_id>(bc.slip.begin(), bc.slip.end()),
          constraints,
          mapping);
      constraints.close();
    }

    template void
    make_boundary_constraints(const AllParameters<2> &,
                              const Mapping<2> &,
                              const DoFHandler<2> &,
                              AffineConstraints<double> &,
                              const MPI_Comm);
    template void
    make_boundary_constraints(const AllParameters<3> &,
                              const Mapping<3> &,
                              const DoFHandler<3> &,
                              AffineConstraints<double> &,
                              const MPI_Comm);
  } // namespace fe_reference
} // namespace mpm
