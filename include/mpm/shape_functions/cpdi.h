#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/shape_functions/q1_cell.h>

#include <array>
#include <cmath>

namespace mpm
{
  namespace shape_functions
  {
    /**
     * A particle domain given by its 2^dim corners x_c (deal.II vertex
     * order: bit d of c is the side in direction d) and the weights that
     * turn grid functions at the corners into the domain averages of CPDI:
     *
     *   S_ip = sum_c w_c N_i(x_c),   grad S_ip = sum_c g_c N_i(x_c),
     *
     * with w_c = (1/V) int M_c dx and g_c = (1/V) int grad M_c dx, M_c the
     * multilinear corner functions of the domain
     * (doc/theory/particle_domain_families.md, "CPDI2"). sum_c w_c = 1 and
     * sum_c g_c = 0 make S a partition of unity with gradients summing to zero;
     * sum_c g_c (x) x_c = I reproduces linear gradients exactly.
     */
    template <int dim>
    struct CornerWeights
    {
      static constexpr unsigned int n_corners = 1u << dim;

      std::array<dealii::Point<dim>, n_corners>     x;
      std::array<double, n_corners>                 w;
      std::array<dealii::Tensor<1, dim>, n_corners> g;
      double                                        volume = 0;
      /// Smallest det J / (product of edge lengths) over the corners: the
      /// sine of the flattest corner angle, 1 for a box, <= 0 if inverted.
      double quality = 1;
    };

    /// Below this corner quality a domain counts as collapsed.
    constexpr double min_domain_quality = 1e-4;

    namespace internal
    {
      template <int dim>
      inline double
      column_product(const dealii::Tensor<2, dim> &A)
      {
        double p = 1;
        for (unsigned int k = 0; k < dim; ++k)
          {
            double n2 = 0;
            for (unsigned int i = 0; i < dim; ++i)
              n2 += A[i][k] * A[i][k];
            p *= std::sqrt(n2);
          }
        return p;
      }
    } // namespace internal

    /**
     * CPDI1: the parallelogram (parallelepiped) x_p + A s, s in
     * [-1,1]^dim, whose columns are the current half-vectors r_i = F r_i^0.
     * Corners x_p + A s_c; w_c = 2^-dim; g_c = A^-T s_c / 2^dim.
     */
    template <int dim>
    inline void
    cpdi1_corners(const dealii::Point<dim>     &centre,
                  const dealii::Tensor<2, dim> &A,
                  CornerWeights<dim>           &cw)
    {
      constexpr unsigned int nc    = CornerWeights<dim>::n_corners;
      const double           det   = dealii::determinant(A);
      const double           edges = internal::column_product(A);
      cw.volume                    = nc * det;
      cw.quality                   = edges > 0 ? det / edges : 0.;
      if (!(cw.quality > min_domain_quality))
        return;
      const dealii::Tensor<2, dim> AinvT = dealii::transpose(dealii::invert(A));
      for (unsigned int c = 0; c < nc; ++c)
        {
          dealii::Tensor<1, dim> s;
          for (unsigned int d = 0; d < dim; ++d)
            s[d] = ((c >> d) & 1) ? 1. : -1.;
          cw.x[c] = centre + A * s;
          cw.w[c] = 1. / nc;
          cw.g[c] = (AinvT * s) / double(nc);
        }
    }

    /**
     * CPDI2: the multilinear domain of the tracked corners cw.x (set
     * before the call). The integrals are polynomial of degree at most 3
     * per direction in the reference coordinates (det J, and the cofactor
     * of J times grad M_c), so the 2-point Gauss rule is exact.
     */
    template <int dim>
    inline void
    cpdi2_weights(CornerWeights<dim> &cw)
    {
      constexpr unsigned int nc = CornerWeights<dim>::n_corners;
      using dealii::Point;
      using dealii::Tensor;
      // The corner functions M_c are the Q1 functions of the domain's
      // reference cube (same vertex order).
      Tensor<1, dim> dM[nc];
      auto           jacobian = [&](const Point<dim> &xi) {
        Q1Cell<dim>::reference_gradients(xi, dM);
        Tensor<2, dim> J;
        for (unsigned int c = 0; c < nc; ++c)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              J[i][j] += cw.x[c][i] * dM[c][j];
        return J;
      };

      // Quality at the corners (convex and not flat): J there has the
      // two (three) edges leaving the corner as columns.
      cw.quality = 1;
      for (unsigned int c = 0; c < nc; ++c)
        {
          Tensor<2, dim> J;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int other = c ^ (1u << d);
              const double       sign  = ((c >> d) & 1) ? -1. : 1.;
              for (unsigned int i = 0; i < dim; ++i)
                J[i][d] = sign * (cw.x[other][i] - cw.x[c][i]);
            }
          const double edges = internal::column_product(J);
          cw.quality =
            std::min(cw.quality,
                     edges > 0 ? dealii::determinant(J) / edges : 0.);
        }
      if (!(cw.quality > min_domain_quality))
        return;
      if constexpr (dim == 2)
        {
          // Closed form (the Gauss loop below was 28% of a CPDI2 run).
          // With x = x0 + a xi + b eta + c xi eta, det J = D0 + D1 xi +
          // D2 eta is linear, so int M_c det J has a short formula; and
          // int grad M_c dx = int_boundary M_c n ds = 1/2 of the outward
          // normals of the two edges at c, i.e. 1/2 rot(x_next - x_prev)
          // around the counter-clockwise cycle 0, 1, 3, 2.
          const Tensor<1, dim> a = cw.x[1] - cw.x[0], b = cw.x[2] - cw.x[0],
                               c = cw.x[3] - cw.x[2] - a;
          auto cross = [](const Tensor<1, dim> &u, const Tensor<1, dim> &v) {
            return u[0] * v[1] - u[1] * v[0];
          };
          const double D0 = cross(a, b), D1 = cross(a, c), D2 = cross(c, b);
          cw.volume                   = D0 + 0.5 * (D1 + D2);
          const double inverse_volume = 1. / cw.volume;
          // neighbours of corner k along the cycle 0, 1, 3, 2
          constexpr unsigned int next[4] = {1, 3, 0, 2}, prev[4] = {2, 0, 3, 1};
          for (unsigned int k = 0; k < nc; ++k)
            {
              // int xi M_k, int eta M_k over the reference square
              const double m1 = (k & 1) ? 1. / 6 : 1. / 12,
                           m2 = (k & 2) ? 1. / 6 : 1. / 12;
              cw.w[k] = (0.25 * D0 + m1 * D1 + m2 * D2) * inverse_volume;
              const Tensor<1, dim> e = cw.x[next[k]] - cw.x[prev[k]];
              cw.g[k][0]             = 0.5 * inverse_volume * e[1];
              cw.g[k][1]             = -0.5 * inverse_volume * e[0];
            }
          return;
        }

      const double a = 0.5 - 0.5 / std::sqrt(3.), b = 0.5 + 0.5 / std::sqrt(3.);
      const double weight = 1. / nc; // Gauss weights on [0,1]^dim
      cw.volume           = 0;
      for (unsigned int c = 0; c < nc; ++c)
        {
          cw.w[c] = 0;
          cw.g[c] = Tensor<1, dim>();
        }
      for (unsigned int q = 0; q < nc; ++q)
        {
          Point<dim> xi;
          for (unsigned int d = 0; d < dim; ++d)
            xi[d] = ((q >> d) & 1) ? b : a;
          const Tensor<2, dim> J   = jacobian(xi); // fills dM at xi
          const double         det = dealii::determinant(J);
          // cofactor = det J^-T: grad_x M dV = cof(J) grad_xi M dxi
          const Tensor<2, dim> cof = det * dealii::transpose(dealii::invert(J));
          double               M[nc];
          Q1Cell<dim>::values(xi, M);
          cw.volume += weight * det;
          for (unsigned int c = 0; c < nc; ++c)
            {
              cw.w[c] += weight * det * M[c];
              cw.g[c] += weight * (cof * dM[c]);
            }
        }
      for (unsigned int c = 0; c < nc; ++c)
        {
          cw.w[c] /= cw.volume;
          cw.g[c] /= cw.volume;
        }
    }
  } // namespace shape_functions
} // namespace mpm
