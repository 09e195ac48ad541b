#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
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
     * Small-strain linear elasticity on one mesh: the Q_p displacement
     * formulation or the Taylor-Hood Q_p/Q_(p-1) displacement-pressure
     * formulation (doc/fe_reference.md, "The equations"), the
     * boundary conditions of the parameter file as constraints, the
     * stiffness matrix, load vector and, for modal analysis, the
     * consistent mass matrix. Serial; solved with UMFPACK.
     */
    template <int dim>
    class ElasticSystem
    {
    public:
      /// The triangulation must outlive this object.
      ElasticSystem(const AllParameters<dim>         &parameters,
                    const dealii::Triangulation<dim> &tria);

      /// Distribute dofs, build constraints and the sparsity pattern.
      void
      setup();

      /// Assemble K and f (with the inhomogeneous constraints), solve
      /// K u = f directly.
      void
      solve_static();

      /**
       * Assemble K and the consistent mass matrix M. Rows and columns of
       * constrained dofs are decoupled; their M diagonal is zero, so they
       * belong to infinite eigenvalues and never show up in the lowest
       * modes.
       */
      void
      assemble_stiffness_and_mass();

      /// Displacement (and pressure) at a point; InputError outside the body.
      dealii::Vector<double>
      point_value(const dealii::Point<dim> &p) const;

      /// The in-plane Cauchy stress at every quadrature point of every cell.
      std::vector<dealii::SymmetricTensor<2, dim>>
      quadrature_point_stresses() const;

      /// ParaView file of fields of this system's dof layout.
      void
      write_vtu(const std::string                                 &file_name,
                const std::vector<const dealii::Vector<double> *> &fields,
                const std::vector<std::string>                    &names) const;

      bool
      mixed() const
      {
        return element.mixed;
      }

      const dealii::DoFHandler<dim> &
      dof_handler() const
      {
        return dofs;
      }

      const dealii::AffineConstraints<double> &
      constraints() const
      {
        return affine_constraints;
      }

      const dealii::Vector<double> &
      solution() const
      {
        return displacement;
      }

      const dealii::SparseMatrix<double> &
      stiffness_matrix() const
      {
        return stiffness;
      }

      const dealii::SparseMatrix<double> &
      mass_matrix() const
      {
        return mass;
      }

      /// How many independent rigid-body motions satisfy every constraint:
      /// K's kernel (statics needs none; modal analysis skips as many
      /// near-zero modes). Zero with a clamped or prescribed boundary.
      unsigned int
      n_rigid_body_motions() const;

    private:
      void
      assemble(const bool with_mass);

      const AllParameters<dim>         &parameters;
      const ElasticElement<dim>         element;
      dealii::DoFHandler<dim>           dofs;
      dealii::AffineConstraints<double> affine_constraints;
      dealii::SparsityPattern           sparsity;
      dealii::SparseMatrix<double>      stiffness, mass;
      dealii::Vector<double>            load, displacement;
    };
  } // namespace fe_reference
} // namespace mpm
