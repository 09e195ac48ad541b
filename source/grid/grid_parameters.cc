#include <deal.II/base/patterns.h>

#include <mpm/grid/grid_parameters.h>
#include <mpm/parameters/parsing.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <utility>

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
                        "The background grid of Q1 cells on which the "
                        "equations of motion are solved: a subdivided box "
                        "(hyper rectangle), or a Gmsh (.msh) or UCD "
                        "(.inp/.ucd) file (mesh file). Box boundary ids are "
                        "0/1 (x min/max), 2/3 (y), 4/5 (z); a mesh file "
                        "brings its own. Every particle must stay inside "
                        "the grid.");
      prm.declare_entry("Lower corner",
                        default_point(dim, 0.),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Lower corner of the box [m] (Type = hyper "
                        "rectangle).");
      prm.declare_entry("Upper corner",
                        default_point(dim, 1.),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Upper corner of the box [m] (Type = hyper "
                        "rectangle); must exceed Lower corner in every "
                        "direction.");
      prm.declare_entry("Subdivisions",
                        "10",
                        Patterns::List(Patterns::Integer(1), 1, dim),
                        "Cells of the box per direction (Type = hyper "
                        "rectangle): one number for all directions or one "
                        "per direction.");
      prm.declare_entry(
        "Mesh file",
        "",
        Patterns::FileName(),
        "The grid for Type = mesh file (required there): Gmsh .msh or UCD "
        ".inp/.ucd; any other extension is refused. A relative path is "
        "looked up first in the folder of the parameter file, then in the "
        "working directory. A file that cannot be read, and a cell whose "
        "(bi/tri)linear map has a zero or negative Jacobian at a vertex "
        "(inverted, flat, vertices in the wrong order), are input errors.");
      prm.declare_entry("Global refinements",
                        "0",
                        Patterns::Integer(0, 12),
                        "Uniform refinements applied after the grid is "
                        "created, for both types; each halves the cell "
                        "size.");
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
                        "Grid boundary ids whose nodes are held fixed "
                        "(every velocity component zero). An id listed both "
                        "here and in Slip boundary ids is refused; a node "
                        "that touches a fixed and a slip face is fixed. Ids "
                        "that do not occur in the grid are ignored.");
      prm.declare_entry("Slip boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
                        "Grid boundary ids with zero normal velocity and "
                        "free tangential velocity. A node on several slip "
                        "faces with different normals is held in all their "
                        "directions (a corner of a 2D box is then fixed). "
                        "Boundaries not listed here or in Fixed boundary "
                        "ids are free: particles may leave the grid there.");
      prm.declare_entry(
        "Moving boundary ids",
        "",
        Patterns::List(Patterns::Integer(0, 255)),
        "Grid boundary ids whose nodes move with the Moving boundary "
        "velocity: a prescribed displacement of the grid boundary, ramped "
        "in pseudo-time. Time stepping/Integrator = quasi-static or "
        "Newmark (the explicit integrator refuses it). A node that also "
        "touches a fixed face is fixed; one that touches a slip face keeps "
        "the wall's normal direction at zero and moves in the others. The "
        "force the moving nodes exert on the bodies is written to the "
        "statistics file (boundary_reaction_x, ...). The grid does not "
        "move: use it for displacements small against a cell across the "
        "boundary, or along it (a shear box); a rigid body of particles "
        "(Bodies/Body n/Prescribed velocity) pushes a body through the "
        "grid. An id listed here and in Fixed or Slip boundary ids is "
        "refused.");
      prm.declare_entry(
        "Moving boundary velocity",
        "",
        Patterns::Anything(),
        "The velocity [m/s] of the nodes on the Moving boundary ids: dim "
        "expressions of the node's position x, y, z and t, separated by "
        "';' (Constants may be used). Over a step from t to t + dt a node "
        "moves by its value at t + dt/2 times dt.");
      prm.declare_entry("Particles leaving the grid",
                        "error",
                        Patterns::Selection("error|remove"),
                        "error: the run stops (status 2) with a message "
                        "naming the particle, its body, the step and its "
                        "position; remove: the particle is deleted and its "
                        "mass added to the removed_mass column of the "
                        "statistics file.");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      fixed                 = parse_id_list(prm.get("Fixed boundary ids"));
      slip                  = parse_id_list(prm.get("Slip boundary ids"));
      remove_lost_particles = prm.get("Particles leaving the grid") == "remove";
      moving                = parse_id_list(prm.get("Moving boundary ids"));
      moving_velocity       = prm.get("Moving boundary velocity");
      prm.leave_subsection();
      for (const auto m : moving)
        for (const auto &[list, name] :
             {std::make_pair(&fixed, "fixed"), std::make_pair(&slip, "slip")})
          if (std::find(list->begin(), list->end(), m) != list->end())
            throw InputError("Boundary conditions: boundary id " +
                             std::to_string(m) + " is listed as both " + name +
                             " and moving");
      if (!moving.empty() && moving_velocity.empty())
        throw InputError("Boundary conditions/Moving boundary ids is set, "
                         "but Moving boundary velocity is empty");
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
