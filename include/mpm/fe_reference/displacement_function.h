#pragma once

#include <deal.II/base/function.h>
#include <deal.II/lac/vector.h>

#include <mpm/utilities/expression.h>

namespace mpm
{
  namespace fe_reference
  {
    /**
     * A displacement expression as a function of all the components of an
     * FE system: the first dim components are the expression's, the rest
     * (the mixed formulation's pressure) are zero. For boundary values and
     * for interpolating exact solutions.
     */
    template <int dim>
    class DisplacementFunction : public dealii::Function<dim>
    {
    public:
      DisplacementFunction(const Expression<dim> &u,
                           const unsigned int     n_components)
        : dealii::Function<dim>(n_components)
        , u(u)
      {}

      void
      vector_value(const dealii::Point<dim> &p,
                   dealii::Vector<double>   &values) const override
      {
        values = 0;
        u.value(p, 0, values.data());
      }

      double
      value(const dealii::Point<dim> &p,
            const unsigned int        component) const override
      {
        dealii::Vector<double> v(this->n_components);
        vector_value(p, v);
        return v[component];
      }

    private:
      const Expression<dim> &u;
    };
  } // namespace fe_reference
} // namespace mpm
