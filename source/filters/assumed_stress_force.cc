#include <mpm/filters/assumed_stress_force.h>

#include <cmath>

namespace mpm
{
  namespace filters
  {
    using namespace dealii;

    namespace
    {
      /// The quadratic Lagrange polynomials of the nodes 0, 1/2, 1.
      inline void
      lagrange(const double t, double *l)
      {
        l[0] = (2 * t - 1) * (t - 1);
        l[1] = 4 * t * (1 - t);
        l[2] = t * (2 * t - 1);
      }
    } // namespace

    template <int dim>
    void
    AssumedStressForce<dim>::clear()
    {
      for (unsigned int k = 0; k < n_points; ++k)
        weight[k] = 0;
      any = false;
    }

    template <int dim>
    void
    AssumedStressForce<dim>::add_particle(const Point<dim>     &xi,
                                          const Tensor<2, dim> &q,
                                          const double          V)
    {
      any = true;
      // 1D averages of l_0, l_1, l_2 over [c - a, c + a]: l(c) + l'' a^2/6
      // with l'' = 4, -8, 4.
      double l[dim][3];
      for (unsigned int d = 0; d < dim; ++d)
        {
          double a2 = 0;
          for (unsigned int k = 0; k < dim; ++k)
            a2 += q[d][k] * q[d][k];
          lagrange(xi[d], l[d]);
          const double c = 4 * a2 / 6;
          l[d][0] += c;
          l[d][1] -= 2 * c;
          l[d][2] += c;
        }
      if constexpr (dim == 2)
        {
          for (unsigned int j = 0; j < 3; ++j)
            {
              const double lj = V * l[1][j];
              for (unsigned int i = 0; i < 3; ++i)
                weight[i + 3 * j] += lj * l[0][i];
            }
        }
      else
        {
          for (unsigned int m = 0; m < 3; ++m)
            for (unsigned int j = 0; j < 3; ++j)
              {
                const double ljm = V * l[1][j] * l[2][m];
                for (unsigned int i = 0; i < 3; ++i)
                  weight[i + 3 * j + 9 * m] += ljm * l[0][i];
              }
        }
    }

    template <int dim>
    void
    AssumedStressForce<dim>::build_box_operator(
      const shape_functions::Q1Cell<dim> &geo,
      const AssumedStressProjection<dim> &field) const
    {
      box_operator.clear();
      box_extent = geo.extent;
      double                 N[n_nodes];
      Tensor<1, dim>         G[n_nodes];
      constexpr unsigned int n_beta = AssumedStressProjection<dim>::n_beta;
      for (unsigned int k = 0; k < n_points; ++k)
        {
          Point<dim>   x;
          unsigned int r = k;
          for (unsigned int d = 0; d < dim; ++d, r /= 3)
            x[d] = 0.5 * (r % 3);
          geo.values_and_gradients(x, N, G);
          for (unsigned int b = 0; b < field.size(); ++b)
            {
              double unit[n_beta]                 = {};
              unit[b]                             = 1;
              const SymmetricTensor<2, dim> sigma = field.field(x, unit);
              for (unsigned int v = 0; v < n_nodes; ++v)
                {
                  const Tensor<1, dim> f = -(sigma * G[v]);
                  for (unsigned int d = 0; d < dim; ++d)
                    if (f[d] != 0.)
                      box_operator.push_back(
                        {static_cast<unsigned short>(k * field.size() + b),
                         static_cast<unsigned short>(v * dim + d),
                         f[d]});
                }
            }
        }
    }

    template <int dim>
    void
    AssumedStressForce<dim>::add_internal_force(
      const shape_functions::Q1Cell<dim> &geo,
      const AssumedStressProjection<dim> &field,
      const double                       *beta,
      double                             *force) const
    {
      if (geo.is_box)
        {
          // Cells of one size share the operator (the field is fixed by
          // the cell's Jacobian, i.e. its extent).
          if (box_operator.empty() || !(geo.extent == box_extent))
            build_box_operator(geo, field);
          // the field's own size: the Pian-Sumihara field leaves the
          // enriched coefficients out (zero, and without operator terms)
          const unsigned int nb = field.size();
          double wb[n_points * AssumedStressProjection<dim>::n_beta];
          for (unsigned int k = 0; k < n_points; ++k)
            for (unsigned int b = 0; b < nb; ++b)
              wb[k * nb + b] = weight[k] * beta[b];
          for (const Term &t : box_operator)
            force[t.vd] += t.c * wb[t.kb];
          return;
        }
      double         N[n_nodes];
      Tensor<1, dim> G[n_nodes];
      for (unsigned int k = 0; k < n_points; ++k)
        {
          if (weight[k] == 0.)
            continue;
          Point<dim>   x;
          unsigned int r = k;
          for (unsigned int d = 0; d < dim; ++d, r /= 3)
            x[d] = 0.5 * (r % 3);
          geo.values_and_gradients(x, N, G);
          const SymmetricTensor<2, dim> sigma = field.field(x, beta);
          for (unsigned int v = 0; v < n_nodes; ++v)
            {
              const Tensor<1, dim> f = -weight[k] * (sigma * G[v]);
              for (unsigned int d = 0; d < dim; ++d)
                force[v * dim + d] += f[d];
            }
        }
    }

    template class AssumedStressForce<2>;
    template class AssumedStressForce<3>;
  } // namespace filters
} // namespace mpm
