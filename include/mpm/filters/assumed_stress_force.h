#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/filters/assumed_stress.h>
#include <mpm/shape_functions/q1_cell.h>

#include <vector>

namespace mpm
{
  namespace filters
  {
    /**
     * The internal force of a cell's assumed-stress field, integrated
     * exactly over the domains of the particles that carry it:
     *   f_v = - sum_p int_{Omega_p} sigma(xi) grad N_v(xi) dV.
     * Summing V_p sigma(xi_p) grad N_v(xi_p) instead (the particle
     * midpoint rule) loses the second moment of the linear terms of sigma
     * inside each particle: in a bending beam with n particles through
     * the depth the bending stiffness falls to 1 - 1/n^2 of the exact one
     * (theory.md, section 4.8).
     *
     * On an axis-parallel box, grad N and the Pian-Sumihara field are
     * polynomials of degree at most 2 in each reference coordinate, so
     * the integrand lies in the tensor-quadratic space spanned by the
     * Lagrange polynomials l_k of the lattice {0, 1/2, 1}^dim. Hence
     *   int sigma grad N_v = sum_k W_k sigma(x_k) grad N_v(x_k),
     *   W_k = sum_p int_{Omega_p} l_k dV,
     * exact for every particle layout. Each particle adds the averages
     * of the l_k over its domain: products of the 1D averages
     * l(c) + l'' a^2/6 over the domain's extent a in each direction
     * (a^2 = the domain's second moment, exact for axis-parallel domains;
     * the correlation of a sheared domain is neglected). The force is
     * then linear in the weights and in beta: on boxes a sparse operator
     * cached per cell size, on other cells the integrand evaluated at the
     * lattice points (a consistent quadrature of the smooth integrand).
     * Only in cells the particles fill (fills()): in sparse cells the
     * second moments are large against the particles' spread, the force
     * departs from the particle quadrature of the projection and nearly
     * incompressible bodies went unstable; there the caller passes zero
     * half-vectors, which gives the weights of the particle sum.
     */
    template <int dim>
    class AssumedStressForce
    {
    public:
      static constexpr unsigned int n_points = dim == 2 ? 9 : 27;
      static constexpr unsigned int n_nodes  = shape_functions::n_q1<dim>;

      /// Whether @p n particles of total volume @p V fill a cell of volume
      /// @p cell_volume enough for the domain integration: at least 2^dim
      /// of them, covering 3/4 of the cell.
      static bool
      fills(const unsigned int n, const double V, const double cell_volume)
      {
        return n >= (1u << dim) && V >= 0.75 * cell_volume;
      }

      /// Start a new cell.
      void
      clear();

      /// Add the domain of one particle: centre @p xi, the half-vectors
      /// of the domain in reference coordinates (the columns of @p q),
      /// volume @p V.
      void
      add_particle(const dealii::Point<dim>     &xi,
                   const dealii::Tensor<2, dim> &q,
                   const double                  V);

      bool
      empty() const
      {
        return !any;
      }

      /// force[v * dim + d] += f_v[d] for the field with coefficients
      /// @p beta of @p field on cell @p geo.
      void
      add_internal_force(const shape_functions::Q1Cell<dim> &geo,
                         const AssumedStressProjection<dim> &field,
                         const double                       *beta,
                         double                             *force) const;

    private:
      /// The force operator of a box: f[vd] += c W[k] beta[b].
      struct Term
      {
        unsigned short kb; ///< k * (field size) + b: index into weight x beta
        unsigned short vd;
        double         c;
      };
      void
      build_box_operator(const shape_functions::Q1Cell<dim> &geo,
                         const AssumedStressProjection<dim> &field) const;

      double weight[n_points];
      bool   any = false;

      mutable std::vector<Term>      box_operator;
      mutable dealii::Tensor<1, dim> box_extent;
    };
  } // namespace filters
} // namespace mpm
