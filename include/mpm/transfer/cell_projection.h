#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/grid/background_grid.h>
#include <mpm/remedies/stress_filter.h>
#include <mpm/transfer/particle_to_grid.h>

namespace mpm
{
  namespace transfer
  {
    /// What the filtered stresses of a P2G pass (IntegratedFieldForce,
    /// ProjectedStressForce) start each cell from: the filter, and the
    /// Jacobian at the cell's centre that its projection is set up with.
    template <int dim>
    class CellProjection
    {
    protected:
      explicit CellProjection(const P2GContext<dim> &c)
        : grid(c.grid)
        , filter(c.filter)
      {
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = 0.5;
      }

      template <typename CellIterator>
      dealii::Tensor<2, dim>
      centre_jacobian(const CellIterator &cell) const
      {
        return grid.geometry(cell).jacobian(centre);
      }

      const BackgroundGrid<dim>   &grid;
      remedies::StressFilter<dim> &filter;

    private:
      dealii::Point<dim> centre;
    };
  } // namespace transfer
} // namespace mpm
