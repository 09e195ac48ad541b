#include <deal.II/fe/fe_q.h>

#include <mpm/fe_reference/elastic_cell_assembler.h>
#include <mpm/utilities/input_error.h>

#include <cmath>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    namespace
    {
      std::string
      coordinate_names(const int dim)
      {
        return dim == 2 ? "x,y" : "x,y,z";
      }
    } // namespace

    template <int dim>
    ElasticElement<dim>::ElasticElement(const AllParameters<dim> &parameters)
      : mixed(parameters.discretisation.formulation ==
              Discretisation::Formulation::mixed)
      , moduli(parameters.material.youngs_modulus,
               parameters.material.poissons_ratio,
               parameters.kinematics)
      , mapping(parameters.discretisation.degree)
    {
      const unsigned int p = parameters.discretisation.degree;
      if (mixed)
        fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(p),
                                             dim,
                                             FE_Q<dim>(p - 1),
                                             1);
      else
        fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(p), dim);
      if (mixed && !std::isfinite(moduli.inverse_lambda))
        throw InputError("Formulation = mixed needs Poisson's ratio > 0 "
                         "(the pressure equation divides by lambda)");
    }

    template <int dim>
    ElasticCellAssembler<dim>::ElasticCellAssembler(
      const AllParameters<dim>  &parameters,
      const ElasticElement<dim> &element)
      : density(parameters.material.density)
      , moduli(element.moduli)
      , mixed(element.mixed)
      , n(element.fe->n_dofs_per_cell())
      , body_force(parameters.boundary.body_force,
                   dim,
                   coordinate_names(dim),
                   parameters.constants,
                   false,
                   "Body force")
      , traction(parameters.boundary.traction,
                 dim,
                 coordinate_names(dim),
                 parameters.constants,
                 false,
                 "Traction")
      , traction_ids(parameters.boundary.traction_ids.begin(),
                     parameters.boundary.traction_ids.end())
      , quadrature(parameters.discretisation.degree + 1)
      , face_quadrature(parameters.discretisation.degree + 1)
      , fe_values(element.mapping,
                  *element.fe,
                  quadrature,
                  update_values | update_gradients | update_quadrature_points |
                    update_JxW_values)
      , fe_face_values(element.mapping,
                       *element.fe,
                       face_quadrature,
                       update_values | update_quadrature_points |
                         update_JxW_values)
      , eps(n)
      , div(n)
      , q(n)
      , phi(n)
    {}

    template <int dim>
    void
    ElasticCellAssembler<dim>::assemble(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const bool                                            with_mass,
      CellSystem                                           &out)
    {
      out.stiffness.reinit(n, n);
      out.mass.reinit(with_mass ? n : 0, with_mass ? n : 0);
      out.load.reinit(n);
      out.pressure_mass_diagonal.reinit(mixed ? n : 0);

      const FEValuesExtractors::Vector u(0);
      const FEValuesExtractors::Scalar pressure(dim);
      const double                     mu = moduli.mu;
      // the displacement formulation's lambda; finite (nu < 0.5 there)
      const double lambda = mixed ? 0. : moduli.lambda;
      double       b[dim], t[dim];

      fe_values.reinit(cell);
      for (unsigned int qp = 0; qp < quadrature.size(); ++qp)
        {
          const double JxW = fe_values.JxW(qp);
          for (unsigned int i = 0; i < n; ++i)
            {
              eps[i] = fe_values[u].symmetric_gradient(i, qp);
              div[i] = fe_values[u].divergence(i, qp);
              phi[i] = fe_values[u].value(i, qp);
              q[i]   = mixed ? fe_values[pressure].value(i, qp) : 0.;
            }
          body_force.value(fe_values.quadrature_point(qp), 0, b);
          for (unsigned int i = 0; i < n; ++i)
            {
              for (unsigned int j = 0; j < n; ++j)
                {
                  // displacement: 2 mu eps:eps + lambda div div;
                  // mixed: 2 mu eps:eps - p div v - q div u - q p/lambda
                  double k =
                    2 * mu * (eps[i] * eps[j]) + lambda * div[i] * div[j];
                  if (mixed)
                    k -= q[i] * div[j] + div[i] * q[j] +
                         moduli.inverse_lambda * q[i] * q[j];
                  out.stiffness(i, j) += k * JxW;
                  if (with_mass)
                    out.mass(i, j) += density * (phi[i] * phi[j]) * JxW;
                }
              for (unsigned int d = 0; d < dim; ++d)
                out.load(i) += density * b[d] * phi[i][d] * JxW;
              if (mixed)
                out.pressure_mass_diagonal(i) += q[i] * q[i] * JxW;
            }
        }
      for (const auto f : cell->face_indices())
        if (cell->at_boundary(f) &&
            traction_ids.count(cell->face(f)->boundary_id()) > 0)
          {
            fe_face_values.reinit(cell, f);
            for (unsigned int qp = 0; qp < face_quadrature.size(); ++qp)
              {
                traction.value(fe_face_values.quadrature_point(qp), 0, t);
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const auto v = fe_face_values[u].value(i, qp);
                    for (unsigned int d = 0; d < dim; ++d)
                      out.load(i) += t[d] * v[d] * fe_face_values.JxW(qp);
                  }
              }
          }
    }

    template struct ElasticElement<2>;
    template struct ElasticElement<3>;
    template class ElasticCellAssembler<2>;
    template class ElasticCellAssembler<3>;
  } // namespace fe_reference
} // namespace mpm
