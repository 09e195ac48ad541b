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
    AssumedStressForce<dim>::add_internal_force(
      const shape_functions::Q1Cell<dim> &geo,
      const AssumedStressProjection<dim> &field,
      const double                       *beta,
      double                             *force) const
    {
      add_internal_force(geo, field.cartesian_field(beta), force);
    }

    template <int dim>
    void
    AssumedStressForce<dim>::add_internal_force(
      const shape_functions::Q1Cell<dim>                         &geo,
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
      if constexpr (dim == 3)
        if (geo.is_box)
          {
            // dN_v/dx_j = s_j / (4 h_j) (1 + s_a r_a)(1 + s_b r_b), a and
            // b the other two directions, s = -1, +1 the node's side. So
            // f_vi = - sum_j s_j / (4 h_j) (Q_ij1 + s_a Q_ija + s_b Q_ijb +
            // s_a s_b Q_ijab) with Q_ije = int sigma_ij e, e = 1, r_a,
            // r_b, r_a r_b: moments of the field's monomials times e.
            constexpr unsigned int voigt[3][3] = {{0, 5, 4},
                                                  {5, 1, 3},
                                                  {4, 3, 2}};
            // index a + 3 b + 9 c of the monomials 1, r0, r1, r2, r1 r2,
            // r0 r2, r0 r1 (internal::BasisColumns<3>) among the moments
            constexpr unsigned int mono[7] = {0, 1, 3, 9, 12, 10, 4};
            constexpr unsigned int stride[3] = {1, 3, 9};
            // the two directions other than j
            constexpr unsigned int other[3][2] = {{1, 2}, {0, 2}, {0, 1}};
            double                 Q[3][3][4];
            for (unsigned int j = 0; j < 3; ++j)
              {
                const unsigned int a = other[j][0], b = other[j][1];
                const unsigned int e[4] = {0,
                                           stride[a],
                                           stride[b],
                                           stride[a] + stride[b]};
                for (unsigned int i = 0; i < 3; ++i)
                  {
                    const double *c = sigma.c[voigt[i][j]];
                    for (unsigned int k = 0; k < 4; ++k)
                      {
                        double q = 0;
                        for (unsigned int m = 0; m < 7; ++m)
                          q += c[m] * moment[mono[m] + e[k]];
                        Q[i][j][k] = q;
                      }
                  }
              }
            for (unsigned int v = 0; v < 8; ++v)
              {
                double s[3];
                for (unsigned int d = 0; d < 3; ++d)
                  s[d] = ((v >> d) & 1) ? 1. : -1.;
                for (unsigned int i = 0; i < 3; ++i)
                  {
                    double f = 0;
                    for (unsigned int j = 0; j < 3; ++j)
                      {
                        const unsigned int a = other[j][0], b = other[j][1];
                        const double      *q = Q[i][j];
                        f += s[j] * 0.25 / geo.extent[j] *
                             (q[0] + s[a] * q[1] + s[b] * q[2] +
                              s[a] * s[b] * q[3]);
                      }
                    force[3 * v + i] -= f;
                  }
              }
            return;
          }
      double weight[n_points];
      lattice_weights(weight);
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
