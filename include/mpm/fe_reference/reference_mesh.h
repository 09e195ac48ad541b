#pragma once

#include <deal.II/grid/tria.h>

#include <mpm/fe_reference/parameters.h>

#include <string>

namespace mpm
{
  namespace fe_reference
  {
    /**
     * The coarse mesh of the Geometry subsection (a refinement study refines
     * it globally): a subdivided box, the subdivided unit box mapped
     * multilinearly onto 2^dim corners (Cook's membrane), or a mesh file
     * looked up next to the parameter file (@p input_folder) first.
     */
    template <int dim>
    void
    create_coarse_mesh(dealii::Triangulation<dim> &tria,
                       const Geometry<dim>        &geometry,
                       const std::string          &input_folder);
  } // namespace fe_reference
} // namespace mpm
