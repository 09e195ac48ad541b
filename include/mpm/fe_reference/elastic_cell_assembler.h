#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <mpm/fe_reference/parameters.h>
#include <mpm/materials/lame_moduli.h>
#include <mpm/utilities/expression.h>

#include <memory>
#include <set>

namespace mpm
{
  namespace fe_reference
  {
    /**
     * What the parameters make of the element: the formulation, the Lame
     * moduli, Q_p (or Taylor-Hood Q_p/Q_(p-1) when mixed), and a MappingQ
     * of the element degree (it follows the curved manifolds a mesh may
     * carry; on the straight-sided meshes of the Geometry subsection it is
     * exact anyway). The mixed form needs 1/lambda: InputError at nu = 0.
     */
    template <int dim>
    struct ElasticElement
    {
      explicit ElasticElement(const AllParameters<dim> &parameters);

      const bool                             mixed;
      const materials::LameModuli            moduli;
      std::unique_ptr<dealii::FESystem<dim>> fe;
      dealii::MappingQ<dim>                  mapping;
    };

    /**
     * One cell's share of the linear elastic system: the stiffness (the
     * displacement form 2 mu eps:eps + lambda div div, or the mixed form
     * with -q div u - p div v - q p / lambda), the consistent mass, the
     * load from the body force and the tractions, and, for the mixed
     * form, the diagonal of the pressure mass matrix (the MINRES
     * preconditioner's pressure block). The serial and the distributed
     * system assemble with it, so they solve the same discrete problem.
     */
    template <int dim>
    class ElasticCellAssembler
    {
    public:
      struct CellSystem
      {
        dealii::FullMatrix<double> stiffness, mass;
        dealii::Vector<double>     load;
        /// int q_i q_i over the cell, for each pressure shape function i
        dealii::Vector<double> pressure_mass_diagonal;
      };

      ElasticCellAssembler(const AllParameters<dim>  &parameters,
                           const ElasticElement<dim> &element);

      /// Fill @p out for @p cell; the mass only when @p with_mass.
      void
      assemble(
        const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
        const bool                                                    with_mass,
        CellSystem                                                   &out);

      unsigned int
      dofs_per_cell() const
      {
        return n;
      }

    private:
      const double                                 density;
      const materials::LameModuli                 &moduli;
      const bool                                   mixed;
      const unsigned int                           n;
      const Expression<dim>                        body_force, traction;
      const std::set<dealii::types::boundary_id>   traction_ids;
      const dealii::QGauss<dim>                    quadrature;
      const dealii::QGauss<dim - 1>                face_quadrature;
      dealii::FEValues<dim>                        fe_values;
      dealii::FEFaceValues<dim>                    fe_face_values;
      std::vector<dealii::SymmetricTensor<2, dim>> eps;
      std::vector<double>                          div, q;
      std::vector<dealii::Tensor<1, dim>>          phi;
    };
  } // namespace fe_reference
} // namespace mpm
