#pragma once

#include <deal.II/base/tensor.h>

#include <mpm/particles/body.h>
#include <mpm/shape_functions/q1_cell.h>
#include <mpm/transfer/velocity_gradient.h>

#include <cmath>
#include <vector>

namespace mpm
{
  namespace remedies
  {
    /**
     * int_c grad N_v dx of the cell @p geo's 2^dim Q1 functions into
     * @p integral; returns the cell's measure. A box has them in closed
     * form; any other cell by the 2^dim-point Gauss rule, exact for any
     * bilinear (trilinear) cell: grad N_v det(dx/dxi) is at most cubic in
     * each reference coordinate.
     */
    template <int dim>
    inline double
    cell_gradient_integrals(const shape_functions::Q1Cell<dim> &geo,
                            dealii::Tensor<1, dim>             *integral)
    {
      constexpr unsigned int nv = shape_functions::n_q1<dim>;
      if (geo.is_box)
        {
          // int_c dN_v/dx_d = +-|c| / (2^(dim-1) h_d), + on the far side
          double measure = 1;
          for (unsigned int d = 0; d < dim; ++d)
            measure *= geo.extent[d];
          const double face = measure / (1u << (dim - 1));
          for (unsigned int v = 0; v < nv; ++v)
            for (unsigned int d = 0; d < dim; ++d)
              integral[v][d] =
                (((v >> d) & 1) ? face : -face) * geo.inverse_extent[d];
          return measure;
        }
      const double a       = 0.5 / std::sqrt(3.);
      double       measure = 0;
      for (unsigned int v = 0; v < nv; ++v)
        integral[v] = dealii::Tensor<1, dim>();
      for (unsigned int q = 0; q < nv; ++q)
        {
          dealii::Point<dim> xi;
          for (unsigned int d = 0; d < dim; ++d)
            xi[d] = 0.5 + (((q >> d) & 1) ? a : -a);
          dealii::Tensor<1, dim> grad[nv];
          geo.gradients(xi, grad);
          const double w = dealii::determinant(geo.jacobian(xi)) / nv;
          measure += w;
          for (unsigned int v = 0; v < nv; ++v)
            integral[v] += w * grad[v];
        }
      return measure;
    }

    /**
     * The mean velocity gradient over the cell @p geo (nodes @p nodes) of
     * the nodal velocities in @p kinematics (KinematicsLayout):
     * (1/|c|) int_c grad v dx, exact for the grid's Q1 field.
     */
    template <int dim>
    inline dealii::Tensor<2, dim>
    cell_mean_velocity_gradient(const shape_functions::Q1Cell<dim> &geo,
                                const unsigned int                 *nodes,
                                const double                       *kinematics)
    {
      dealii::Tensor<1, dim> integral[shape_functions::n_q1<dim>];
      const double           measure = cell_gradient_integrals(geo, integral);
      return transfer::velocity_gradient<dim>(kinematics, nodes, integral) /
             measure;
    }

    /**
     * The pressure of a fluid with `Volumetric smoothing = cell` acts over
     * its cell (explicit integrator), as the element pressure of the
     * Q1-P0 mixed element does, not at the particles. The cell already
     * has one pressure; integrated at the particles, its nodal forces
     * would still depend on where the particles sit in the cell, and a
     * fluid, with no shear stiffness, lets them move there freely:
     * particle motion and quadrature then feed each other, and water at
     * rest under gravity does not stay at rest
     * (doc/theory/volumetric_smoothing.md, "A fluid at rest under
     * gravity"). The volume change that matches this force is the cell's
     * exact mean of grad v (VolumetricSmoothing::update_cell).
     *
     * In the P2G force pass: begin_cell() sets up the cell,
     * take_pressure() moves the in-plane mean stress of each such particle
     * out of its -V_p sigma_p, and add_to_nodes() adds (sum_p V_p p_p) /
     * |c| int_c grad N_v dx to the cell's nodes. Bodies with the
     * assumed-stress filter keep their particles' quadrature.
     */
    template <int dim>
    class CellPressureForce
    {
    public:
      explicit CellPressureForce(const std::vector<Body<dim>> &bodies);

      /// Whether some body's pressure acts over the cell.
      bool
      any() const
      {
        return any_body;
      }

      /// Start the cell @p geo.
      void
      begin_cell(const shape_functions::Q1Cell<dim> &geo)
      {
        cell            = &geo;
        pressure_volume = 0;
      }

      /// Move the in-plane mean of the weighted stress @p W = -V_p sigma_p
      /// (V_p p_p) of a particle of body @p b into the cell's sum.
      void
      take_pressure(const unsigned int b, dealii::Tensor<2, dim> &W)
      {
        if (!over_cell[b])
          return;
        const double pV = dealii::trace(W) / dim;
        pressure_volume += pV;
        for (unsigned int d = 0; d < dim; ++d)
          W[d][d] -= pV;
      }

      /// Add the cell's pressure force to the force components (offset
      /// @p force, stride @p stride) of its nodes @p nodes in @p nodal.
      void
      add_to_nodes(const unsigned int *nodes,
                   double             *nodal,
                   const unsigned int  stride,
                   const unsigned int  force) const
      {
        if (pressure_volume == 0)
          return;
        constexpr unsigned int nv = shape_functions::n_q1<dim>;
        dealii::Tensor<1, dim> integral[nv];
        const double           p_over_measure =
          pressure_volume / cell_gradient_integrals(*cell, integral);
        for (unsigned int v = 0; v < nv; ++v)
          {
            double *node = nodal + nodes[v] * stride + force;
            for (unsigned int d = 0; d < dim; ++d)
              node[d] += p_over_measure * integral[v][d];
          }
      }

    private:
      std::vector<char>                   over_cell;
      bool                                any_body        = false;
      const shape_functions::Q1Cell<dim> *cell            = nullptr;
      double                              pressure_volume = 0; ///< sum V_p p_p
    };
  } // namespace remedies
} // namespace mpm
