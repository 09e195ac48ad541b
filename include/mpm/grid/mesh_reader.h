#pragma once

#include <deal.II/grid/tria.h>

#include <string>

namespace mpm
{
  /**
   * Read a Gmsh (.msh) or UCD (.inp, .ucd) mesh into @p tria. A relative
   * @p file_name is looked up next to the parameter file (@p input_folder)
   * first, then in the working directory. Every failure (missing file,
   * unknown format, broken content) is an InputError naming @p entry and
   * the file.
   */
  template <int dim>
  void
  read_mesh(dealii::Triangulation<dim> &tria,
            const std::string          &file_name,
            const std::string          &input_folder,
            const std::string          &entry);
} // namespace mpm
