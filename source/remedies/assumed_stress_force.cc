#include <mpm/remedies/assumed_stress_force.h>

#include <algorithm>
#include <cmath>

namespace mpm
{
  namespace remedies
  {
    using namespace dealii;

    namespace
    {
      /// The quadratic Lagrange polynomials of the nodes r = -1, 0, 1 as
      /// coefficients of 1, r, r^2.
      constexpr double lagrange[3][3] = {{0, -0.5, 0.5},
                                         {1, 0, -1},
                                         {0, 0.5, 0.5}};
    } // namespace

    template <int dim>
    void
    AssumedStressForce<dim>::clear()
    {
      for (unsigned int k = 0; k < n_points; ++k)
        moment[k] = 0;
      any = false;
    }

    template <int dim>
    void
    AssumedStressForce<dim>::lattice_weights(double *weight) const
    {
      // W = (L x L (x L)) M, one direction at a time
      double a[n_points], b[n_points];
      std::copy(moment, moment + n_points, a);
      unsigned int stride = 1;
      for (unsigned int d = 0; d < dim; ++d, stride *= 3)
        {
          for (unsigned int k = 0; k < n_points; ++k)
            {
              const unsigned int i    = (k / stride) % 3;
              const unsigned int base = k - i * stride;
              b[k]                    = 0;
              for (unsigned int c = 0; c < 3; ++c)
                b[k] += lagrange[i][c] * a[base + c * stride];
            }
          std::copy(b, b + n_points, a);
        }
      std::copy(a, a + n_points, weight);
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
      add_internal_force(geo, field, beta, field.cartesian_field(beta), force);
    }

    template <int dim>
    void
    AssumedStressForce<dim>::add_internal_force(
      const shape_functions::Q1Cell<dim>                         &geo,
      const AssumedStressProjection<dim>                         &field,
      const double                                               *beta,
      const typename AssumedStressProjection<dim>::CartesianField &sigma,
      double                                                     *force) const
    {
      if constexpr (dim == 2)
        if (geo.is_box)
          {
            // sigma_c = c0 + c1 r0 + c2 r1 (c: xx yy xy); the integrals of
            // sigma_c, sigma_c r0 and sigma_c r1 over the particles
            const double M00 = moment[0], M10 = moment[1], M20 = moment[2],
                         M01 = moment[3], M11 = moment[4], M02 = moment[6];
            double I[3], X[3], Y[3];
            for (unsigned int c = 0; c < 3; ++c)
              {
                const double *k = sigma.c[c];
                I[c]            = k[0] * M00 + k[1] * M10 + k[2] * M01;
                X[c]            = k[0] * M10 + k[1] * M20 + k[2] * M11;
                Y[c]            = k[0] * M01 + k[1] * M11 + k[2] * M02;
              }
            // node v = i + 2 j: dN/dx0 = s_i (1 + s_j r1) / (2 h0),
            // dN/dx1 = s_j (1 + s_i r0) / (2 h1), s = -1, +1
            const double g0 = 0.5 / geo.extent[0], g1 = 0.5 / geo.extent[1];
            for (unsigned int v = 0; v < 4; ++v)
              {
                const double si = (v & 1) ? 1. : -1.;
                const double sj = (v & 2) ? 1. : -1.;
                force[2 * v] -= si * g0 * (I[0] + sj * Y[0]) +
                                sj * g1 * (I[2] + si * X[2]);
                force[2 * v + 1] -= si * g0 * (I[2] + sj * Y[2]) +
                                    sj * g1 * (I[1] + si * X[1]);
              }
            return;
          }
      double weight[n_points];
      lattice_weights(weight);
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
          const SymmetricTensor<2, dim> sigma_k = sigma.value(x);
          for (unsigned int v = 0; v < n_nodes; ++v)
            {
              const Tensor<1, dim> f = -weight[k] * (sigma_k * G[v]);
              for (unsigned int d = 0; d < dim; ++d)
                force[v * dim + d] += f[d];
            }
        }
    }

    template class AssumedStressForce<2>;
    template class AssumedStressForce<3>;
  } // namespace remedies
} // namespace mpm
