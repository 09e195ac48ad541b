#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <cmath>
#include <limits>

namespace mpm
{
  namespace shape_functions
  {
    using dealii::Point;
    using dealii::Tensor;

    /// Number of vertices (= Q1 shape functions) of a dim-cube.
    template <int dim>
    constexpr unsigned int n_q1 = 1u << dim;

    /**
     * Geometry of one Q1 background cell and direct evaluation of its
     * shape functions at reference coordinates xi in [0,1]^dim (deal.II's
     * convention and vertex order: vertex v has reference coordinate bit d
     * of v in direction d).
     *
     * Axis-parallel boxes take a fast path (gradients are the reference
     * gradients divided by the edge lengths). Every other cell uses the
     * Jacobian at xi: grad N = J^-T grad_xi N with J = sum_v x_v (x)
     * grad_xi N_v, which is exact for any non-degenerate Q1 cell.
     */
    template <int dim>
    struct Q1Cell
    {
      static constexpr unsigned int n_vertices = n_q1<dim>;

      std::array<Point<dim>, n_vertices> vertices;
      bool                               is_box = false;
      Tensor<1, dim>                     inverse_extent; // box only
      Tensor<1, dim>                     extent;         // box only

      /// Fill from vertex positions in deal.II order.
      void
      reinit(const std::array<Point<dim>, n_vertices> &v, const double tol)
      {
        vertices = v;
        is_box   = true;
        for (unsigned int d = 0; d < dim; ++d)
          {
            extent[d]         = v[n_vertices - 1][d] - v[0][d];
            inverse_extent[d] = 1. / extent[d];
          }
        for (unsigned int i = 0; i < n_vertices; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double expected =
                v[0][d] + (((i >> d) & 1) ? extent[d] : 0.);
              if (std::abs(v[i][d] - expected) > tol)
                is_box = false;
            }
      }

      /// Shape function values at xi.
      static inline __attribute__((always_inline)) void
      values(const Point<dim> &xi, double *N)
      {
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            double n = 1;
            for (unsigned int d = 0; d < dim; ++d)
              n *= ((v >> d) & 1) ? xi[d] : 1. - xi[d];
            N[v] = n;
          }
      }

      /// Gradients with respect to xi.
      static inline __attribute__((always_inline)) void
      reference_gradients(const Point<dim> &xi, Tensor<1, dim> *dN)
      {
        for (unsigned int v = 0; v < n_vertices; ++v)
          for (unsigned int d = 0; d < dim; ++d)
            {
              double g = ((v >> d) & 1) ? 1. : -1.;
              for (unsigned int e = 0; e < dim; ++e)
                if (e != d)
                  g *= ((v >> e) & 1) ? xi[e] : 1. - xi[e];
              dN[v][d] = g;
            }
      }

      /// Jacobian dx/dxi at xi.
      Tensor<2, dim>
      jacobian(const Point<dim> &xi) const
      {
        Tensor<1, dim> dN[n_vertices];
        reference_gradients(xi, dN);
        Tensor<2, dim> J;
        for (unsigned int v = 0; v < n_vertices; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              J[i][j] += vertices[v][i] * dN[v][j];
        return J;
      }

      /// Physical gradients of the 2^dim shape functions at xi. The box path
      /// (a few multiplications) is inlined into the particle loops; the
      /// Jacobian of a general cell is not.
      inline __attribute__((always_inline)) void
      gradients(const Point<dim> &xi, Tensor<1, dim> *grad) const
      {
        reference_gradients(xi, grad);
        if (is_box)
          {
            for (unsigned int v = 0; v < n_vertices; ++v)
              for (unsigned int d = 0; d < dim; ++d)
                grad[v][d] *= inverse_extent[d];
          }
        else
          map_reference_gradients(xi, grad);
      }

      /// Values and physical gradients at xi.
      inline __attribute__((always_inline)) void
      values_and_gradients(const Point<dim> &xi,
                           double           *N,
                           Tensor<1, dim>   *grad) const
      {
        values(xi, N);
        gradients(xi, grad);
      }

      /// grad N = J^-T grad_xi N of a general (not box) cell, in place.
      __attribute__((noinline)) void
      map_reference_gradients(const Point<dim> &xi, Tensor<1, dim> *grad) const
      {
        const Tensor<2, dim> JinvT =
          dealii::transpose(dealii::invert(jacobian(xi)));
        for (unsigned int v = 0; v < n_vertices; ++v)
          grad[v] = JinvT * grad[v];
      }

      /**
       * Reference coordinates of the physical point x: direct on boxes,
       * Newton iterations from @p start otherwise (a few for any
       * reasonable cell). Points far outside may not converge; the result
       * then lies outside [0,1]^dim, which is all callers need to know.
       */
      Point<dim>
      inverse_map(const Point<dim> &x, const Point<dim> &start) const
      {
        Point<dim> xi;
        if (is_box)
          {
            for (unsigned int d = 0; d < dim; ++d)
              xi[d] = (x[d] - vertices[0][d]) * inverse_extent[d];
            return xi;
          }
        xi = start;
        for (unsigned int it = 0; it < 20; ++it)
          {
            const Tensor<1, dim> r    = map(xi) - x;
            const Tensor<1, dim> step = dealii::invert(jacobian(xi)) * r;
            xi -= step;
            if (step.norm_square() < 1e-28)
              break;
          }
        // Not converged (x far outside, or a fold of the extended map):
        // say "outside" rather than return a point that does not map to x.
        const double size = vertices[0].distance(vertices[n_vertices - 1]);
        if (!(map(xi).distance(x) <= 1e-10 * size))
          xi[0] = std::numeric_limits<double>::infinity();
        return xi;
      }

      /// Whether xi lies in the closed unit cell (up to round-off).
      static bool
      is_inside(const Point<dim> &xi)
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (!(xi[d] >= -1e-12 && xi[d] <= 1. + 1e-12))
            return false;
        return true;
      }

      /**
       * The face (deal.II numbering, 2 d + side) across which xi lies
       * furthest outside [0,1]^dim, or numbers::invalid_unsigned_int if
       * it lies inside: where a walk towards the point goes next.
       */
      static unsigned int
      most_violated_face(const Point<dim> &xi)
      {
        unsigned int face  = dealii::numbers::invalid_unsigned_int;
        double       worst = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (-xi[d] > worst)
              worst = -xi[d], face = 2 * d;
            if (xi[d] - 1 > worst)
              worst = xi[d] - 1, face = 2 * d + 1;
          }
        return face;
      }

      /// Position of the reference point xi.
      Point<dim>
      map(const Point<dim> &xi) const
      {
        double N[n_vertices];
        values(xi, N);
        Point<dim> x;
        for (unsigned int v = 0; v < n_vertices; ++v)
          x += N[v] * vertices[v];
        return x;
      }
    };
  } // namespace shape_functions
} // namespace mpm
