#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/remedies/assumed_stress.h>
#include <mpm/shape_functions/q1_cell.h>


namespace mpm
{
  namespace remedies
  {
    /**
     * The internal force of a cell's assumed-stress field, integrated
     * exactly over the domains of the particles that carry it:
     *   f_v = - sum_p int_{Omega_p} sigma(xi) grad N_v(xi) dV.
     * Summing V_p sigma(xi_p) grad N_v(xi_p) instead (the particle
     * midpoint rule) loses the second moment of the linear terms of sigma
     * inside each particle: in a bending beam with n particles through
     * the depth the bending stiffness falls to 1 - 1/n^2 of the exact one
     * (doc/theory/assumed_stress_filter.md).
     *
     * Each particle's domain is taken as a product measure: uniform over
     * [c_d - a_d, c_d + a_d] in each reference direction d, with a_d^2 the
     * domain's second moment (exact for axis-parallel domains; the
     * correlation of a sheared domain is neglected). The integrand is at
     * most tensor-quadratic in the natural coordinates r = 2 xi - 1, so
     * the cell needs only the moments
     *   M_ab(c) = sum_p V_p E_p[r_0^a] E_p[r_1^b] (E_p[r_2^c]),
     * a, b, c in {0, 1, 2}, with E_p[r] = r_c and E_p[r^2] = r_c^2 +
     * (2 a_d)^2 / 3: one outer product of two (three) 3-vectors per
     * particle. From them:
     * - boxes: the force in closed form (doc/theory/assumed_stress_filter.md):
     *   grad N_v is a product of linear factors, one per direction but
     *   the derivative's, and the field's monomials are at most linear in
     *   each direction, so each force component is a sum of the field's
     *   coefficients times moments (2D: M_00, M_10, M_01, M_20, M_02,
     *   M_11; 3D: about 500 products per cell);
     * - other cells: the weights of the lattice {-1, 0, 1}^dim,
     *   W_k = integral of its Lagrange polynomial l_k, so that
     *     int sigma grad N_v = sum_k W_k sigma(x_k) grad N_v(x_k),
     *   evaluated at the lattice points (a consistent quadrature of the
     *   smooth integrand).
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

      /// The same with the field's monomial coefficients already known
      /// (AssumedStressProjection::cartesian_field(beta)).
      void
      add_internal_force(
        const shape_functions::Q1Cell<dim>                         &geo,
        const typename AssumedStressProjection<dim>::CartesianField &sigma,
        double                                                     *force) const;

    private:
      /// The lattice weights W_k from the moments.
      void
      lattice_weights(double *weight) const;

      /// M_abc at index a + 3 b + 9 c.
      double moment[n_points];
      bool   any = false;
    };

    template <int dim>
    inline void
    AssumedStressForce<dim>::add_particle(const dealii::Point<dim>     &xi,
                                          const dealii::Tensor<2, dim> &q,
                                          const double                  V)
    {
      any = true;
      // E[1], E[r], E[r^2] of the domain in each natural direction; its
      // half-width in r is twice the one in xi.
      double e[dim][3];
      for (unsigned int d = 0; d < dim; ++d)
        {
          double a2 = 0;
          for (unsigned int k = 0; k < dim; ++k)
            a2 += q[d][k] * q[d][k];
          const double r = 2 * xi[d] - 1;
          e[d][0]        = 1;
          e[d][1]        = r;
          e[d][2]        = r * r + 4 * a2 / 3;
        }
      if constexpr (dim == 2)
        {
          for (unsigned int j = 0; j < 3; ++j)
            {
              const double vj = V * e[1][j];
              for (unsigned int i = 0; i < 3; ++i)
                moment[i + 3 * j] += vj * e[0][i];
            }
        }
      else
        {
          for (unsigned int m = 0; m < 3; ++m)
            for (unsigned int j = 0; j < 3; ++j)
              {
                const double vjm = V * e[1][j] * e[2][m];
                for (unsigned int i = 0; i < 3; ++i)
                  moment[i + 3 * j + 9 * m] += vjm * e[0][i];
              }
        }
    }
  } // namespace remedies
} // namespace mpm
