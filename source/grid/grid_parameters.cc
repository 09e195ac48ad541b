#include <deal.II/base/patterns.h>

#include <mpm/grid/grid_parameters.h>
#include <mpm/parameters/parsing.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  namespace Parameters
  {
    using namespace dealii;

    // ------------------------------------------------------------------ Grid
    template <int dim>
    void
    Grid<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Grid");
      prm.declare_entry("Type",
                        "hyper rectangle",
                        Patterns::Selection("hyper rectangle|mesh file"),
                        "Background grid: a subdivided box, or a Gmsh (.msh) "
                        "or UCD (.inp/.ucd) file. Box boundary ids are "
                        "0/1 (x min/max), 2/3 (y), 4/5 (z).");
      prm.declare_entry("Lower corner",
                        default_point(dim, 0.),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Lower corner of the box [m].");
      prm.declare_entry("Upper corner",
                        default_point(dim, 1.),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Upper corner of the box [m].");
      prm.declare_entry("Subdivisions",
                        "10",
                        Patterns::List(Patterns::Integer(1), 1, dim),
                        "Cells per direction: one number for all directions "
                        "or one per direction.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::FileName(),
                        "Mesh file for Type = mesh file, relative to the "
                        "parameter file's folder or absolute.");
      prm.declare_entry("Global refinements",
                        "0",
                        Patterns::Integer(0, 12),
                        "Uniform refinements applied after creation.");
      prm.leave_subsection();
    }

    template <int dim>
    void
    Grid<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Grid");
      type  = prm.get("Type") == "mesh file" ? Type::mesh_file :
                                               Type::hyper_rectangle;
      lower = parse_point<dim>(prm.get("Lower corner"), "Grid/Lower corner");
      upper = parse_point<dim>(prm.get("Upper corner"), "Grid/Upper corner");
      subdivisions =
        parse_unsigned_list(prm.get("Subdivisions"), dim, "Grid/Subdivisions");
      mesh_file          = prm.get("Mesh file");
      global_refinements = prm.get_integer("Global refinements");
      prm.leave_subsection();
      if (type == Type::hyper_rectangle)
        for (unsigned int d = 0; d < dim; ++d)
          if (!(upper[d] > lower[d]))
            throw InputError("Grid/Upper corner must exceed Grid/Lower "
                             "corner in every direction");
      if (type == Type::mesh_file && mesh_file.empty())
        throw InputError(
          "Grid/Type = mesh file needs Grid/Mesh file to be set");
    }

    // ---------------------------------------------------- BoundaryConditions
    void
    BoundaryConditions::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Fixed boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
                        "Grid boundary ids whose nodes are held fixed.");
      prm.declare_entry("Slip boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
                        "Grid boundary ids with zero normal velocity; other "
                        "boundaries are free.");
      prm.declare_entry("Particles leaving the grid",
                        "error",
                        Patterns::Selection("error|remove"),
                        "error: stop with a message naming the particle; "
                        "remove: delete it and report the removed mass in "
                        "the statistics.");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      fixed                 = parse_id_list(prm.get("Fixed boundary ids"));
      slip                  = parse_id_list(prm.get("Slip boundary ids"));
      remove_lost_particles = prm.get("Particles leaving the grid") == "remove";
      prm.leave_subsection();
      for (const auto f : fixed)
        for (const auto s : slip)
          if (f == s)
            throw InputError("Boundary conditions: boundary id " +
                             std::to_string(f) +
                             " is listed as both fixed and slip");
    }

    template struct Grid<1>;
    template struct Grid<2>;
    template struct Grid<3>;
  } // namespace Parameters
} // namespace mpm
