#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <limits>

namespace mpm
{
  /**
   * A body's inlet (subsection Bodies/Body i/Inflow): particles of the
   * body enter through a disk (3D), a segment (2D) or a point (1D) at
   * Center, normal to Direction, at Speed, from Start time until End time
   * or until Volume has entered. The entries are read and checked here;
   * Inflow (particles/inflow.h) lays the particles out.
   */
  template <int dim>
  struct InflowParameters
  {
    bool                   enabled = false;
    dealii::Point<dim>     center;
    dealii::Tensor<1, dim> direction; ///< unit vector
    double                 radius     = 0;
    double                 speed      = 0;
    double                 start_time = 0;
    /// infinity: until the end of the run (or Volume)
    double end_time = std::numeric_limits<double>::infinity();
    /// 0: not limited by volume
    double volume  = 0;
    double spacing = 0;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Read and check the entries; an InputError names the entry
    /// ("Inflow/Speed = 0 must be positive").
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The inlet's area: pi R^2 in 3D, 2R per unit thickness in 2D, 1
    /// (unit cross-section) in 1D.
    double
    area() const;
  };
} // namespace mpm
