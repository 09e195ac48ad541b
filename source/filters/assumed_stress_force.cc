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
      any                       = true;
      const double     g        = 1. / std::sqrt(3.);
      const double     w        = V / (1u << dim);
      constexpr unsigned int ng = 1u << dim;
      for (unsigned int gp = 0; gp < ng; ++gp)
        {
          double l[dim][3];
          for (unsigned int d = 0; d < dim; ++d)
            {
              double x = xi[d];
              for (unsigned int k = 0; k < dim; ++k)
                x += q[d][k] * (((gp >> k) & 1) ? g : -g);
              lagrange(x, l[d]);
            }
          if constexpr (dim == 2)
            {
              for (unsigned int j = 0; j < 3; ++j)
                for (unsigned int i = 0; i < 3; ++i)
                  weight[i + 3 * j] += w * l[0][i] * l[1][j];
            }
          else
            {
              for (unsigned int m = 0; m < 3; ++m)
                for (unsigned int j = 0; j < 3; ++j)
                  {
                    const double ljm = w * l[1][j] * l[2][m];
                    for (unsigned int i = 0; i < 3; ++i)
                      weight[i + 3 * j + 9 * m] += ljm * l[0][i];
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
