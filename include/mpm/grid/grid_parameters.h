#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

/**
 * The subsections of the parameter file that the background grid reads:
 * its geometry, its boundary conditions and its load balancing. Part of
 * the parameter file of parameters/parameters.h, kept apart so that the
 * grid depends on its own parameters only.
 */
namespace mpm
{
  namespace Parameters
  {
    /// Background grid: a subdivided box or a mesh file.
    template <int dim>
    struct Grid
    {
      enum class Type
      {
        hyper_rectangle,
        mesh_file
      };
      Type                      type = Type::hyper_rectangle;
      dealii::Point<dim>        lower, upper;
      std::vector<unsigned int> subdivisions;
      std::string               mesh_file;
      unsigned int              global_refinements = 0;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// What happens at the grid boundary and to particles that leave it.
    struct BoundaryConditions
    {
      std::vector<dealii::types::boundary_id> fixed, slip;
      /// Ids whose nodes move with `moving_velocity` (the implicit steps).
      std::vector<dealii::types::boundary_id> moving;
      std::string                             moving_velocity;
      bool                                    remove_lost_particles = false;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// subsection Load balancing: repartition the grid by particle count
    /// (grid/load_balancer.h; parsed in source/grid/load_balancer.cc).
    struct LoadBalancing
    {
      /// Repartition by weight at set-up (by the planned particle counts,
      /// or by the particles read from a checkpoint), if more than one
      /// rank shares a 2D/3D grid.
      bool at_setup = true;
      /// Steps between repartitions; 0: never after set-up.
      unsigned int interval = 0;
      /// Work of a cell without particles (node loops, the cell loop).
      unsigned int cell_weight = 1;
      /// Work of one particle, in the same units.
      unsigned int particle_weight = 10;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace mpm
