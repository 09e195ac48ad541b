#pragma once

#include <deal.II/base/tensor.h>

#include <mpm/grid/background_grid.h>
#include <mpm/grid/nodal_layout.h>
#include <mpm/shape_functions/stencil.h>

namespace mpm
{
  namespace transfer
  {
    /// sum_i v_i (x) grad N_ip over the Q1 nodes of a particle's cell:
    /// the grid velocity's gradient at the particle (@p in: KinematicsLayout
    /// values, @p G: the cell's Q1 gradients there).
    template <int dim>
    inline __attribute__((always_inline)) dealii::Tensor<2, dim>
    velocity_gradient(const double                 *in,
                      const unsigned int           *nodes,
                      const dealii::Tensor<1, dim> *G)
    {
      using K = KinematicsLayout<dim>;
      dealii::Tensor<2, dim> grad_v;
      for (unsigned int v = 0; v < shape_functions::n_q1<dim>; ++v)
        {
          const double *k = in + nodes[v] * K::n_components;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              grad_v[i][j] += k[K::velocity + i] * G[v][j];
        }
      return grad_v;
    }

    /// The same with a particle-domain family's stencil: sum_i v_i (x)
    /// grad S_ip.
    template <int dim>
    inline __attribute__((always_inline)) dealii::Tensor<2, dim>
    velocity_gradient(const double                        *in,
                      const shape_functions::Stencil<dim> &stencil)
    {
      using K = KinematicsLayout<dim>;
      dealii::Tensor<2, dim> grad_v;
      for (unsigned int e = 0; e < stencil.n; ++e)
        {
          const double *k = in + stencil.node[e] * K::n_components;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              grad_v[i][j] += k[K::velocity + i] * stencil.gradient[e][j];
        }
      return grad_v;
    }

    /// The centroid sum_i S_ip x_i of a particle's domain as the stencil
    /// sees it: the point APIC's affine velocity is taken about, so that
    /// sum_i S_ip C_p (x_i - centroid) = 0 (doc/theory/apic.md).
    template <int dim>
    inline dealii::Point<dim>
    stencil_centroid(const shape_functions::Stencil<dim> &stencil,
                     const BackgroundGrid<dim>           &grid)
    {
      dealii::Point<dim> x;
      for (unsigned int e = 0; e < stencil.n; ++e)
        x += stencil.value[e] * grid.node_position(stencil.node[e]);
      return x;
    }
  } // namespace transfer
} // namespace mpm
