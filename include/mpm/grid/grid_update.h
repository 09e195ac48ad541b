#pragma once

#include <mpm/grid/active_nodes.h>
#include <mpm/grid/background_grid.h>
#include <mpm/grid/nodal_layout.h>

#include <string>

namespace mpm
{
  /**
   * Explicit update of the nodal momentum on owned nodes,
   *   (mv)_i^{n+1} = (mv)_i^n + dt (f_i - c (mv)_i),
   * with boundary constraints applied to momentum and force, and the
   * nodal velocity v_i^{n+1} = (mv)_i^{n+1}/m_i and its increment written
   * to @p kinematics (ghosts updated). Nodes lighter than @p min_mass get
   * zero velocity. Returns an empty string, or a description of the first
   * node with a non-finite value. With @p active, only its nodes() (the
   * rest of @p kinematics is zero).
   */
  template <int dim>
  std::string
  update_grid(const BackgroundGrid<dim> &grid,
              const NodalVector         &p2g,
              const double               dt,
              const double               damping,
              const double               min_mass,
              NodalVector               &kinematics,
              ActiveNodes               *active = nullptr);

  /**
   * Nodal velocity v_i = (mv)_i / m_i (constrained) from a mass vector
   * (P2G layout) and a momentum vector with dim components per node
   * (@p momentum_offset = 0) or the P2G vector itself (offset 1).
   * Written into the velocity slots of @p kinematics, ghosts updated.
   * With @p active, only at its nodes() (the rest of @p kinematics is
   * zero).
   */
  template <int dim>
  std::string
  nodal_velocity(const BackgroundGrid<dim> &grid,
                 const NodalVector         &p2g,
                 const NodalVector         &momentum,
                 const unsigned int         momentum_components,
                 const unsigned int         momentum_offset,
                 const double               min_mass,
                 NodalVector               &kinematics,
                 ActiveNodes               *active = nullptr);
} // namespace mpm
