#include <deal.II/base/geometry_info.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <mpm/fe_reference/parameters.h>
#include <mpm/grid/quadrilateral_mesh.h>
#include <mpm/materials/elasticity.h>
#include <mpm/materials/material.h>
#include <mpm/parameters/parsing.h>
#include <mpm/utilities/expression.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <cmath>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    namespace
    {
      /// "0,0; 48,44; ..." in the counter-clockwise order the user writes
      /// (2D; in 3D the bottom face, then the top face), returned in
      /// deal.II's lexicographic vertex order.
      template <int dim>
      std::vector<Point<dim>>
      parse_corners(const std::string &text)
      {
        const auto parts = Utilities::split_string_list(text, ';');
        if (parts.size() != GeometryInfo<dim>::vertices_per_cell)
          throw InputError(
            "Geometry/Corners = '" + text + "': expected " +
            std::to_string(GeometryInfo<dim>::vertices_per_cell) +
            " points separated by ';'");
        std::vector<Point<dim>> ccw;
        for (const auto &p : parts)
          ccw.push_back(Parameters::parse_point<dim>(p, "Geometry/Corners"));
        return lexicographic_corners(ccw, "Geometry/Corners");
      }
    } // namespace

    // -------------------------------------------------------------- Geometry
    template <int dim>
    void
    Geometry<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry(
        "Type",
        "box",
        Patterns::Selection("box|quadrilateral|mesh file"),
        "box: a subdivided box, boundary ids 0/1 x min/max, 2/3 y, 4/5 z. "
        "quadrilateral: the subdivided unit box mapped (bi/trilinearly) onto "
        "the Corners, boundary ids as for the box in the corners' own "
        "directions (2D: 0 the edge from corner 3 to corner 0, 1 from corner "
        "1 to corner 2, 2 from corner 0 to corner 1, 3 from corner 2 to "
        "corner 3). mesh file: a Gmsh or UCD file with its boundary ids. "
        "The Boundary conditions refer to these ids.");
      prm.declare_entry("Lower corner",
                        Parameters::default_point(dim, 0.),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: lower corner (Type = box).");
      prm.declare_entry("Upper corner",
                        Parameters::default_point(dim, 1.),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: upper corner (Type = box); must exceed Lower "
                        "corner in every direction.");
      prm.declare_entry("Corners",
                        "",
                        Patterns::Anything(),
                        "Quadrilateral (required there, refused for the "
                        "other types): the 2^dim corners separated by ';', "
                        "counter-clockwise in 2D (Cook's membrane: 0,0; "
                        "48,44; 48,60; 0,44); in 3D the bottom face "
                        "counter-clockwise, then the top face. Corners that "
                        "give an inverted or degenerate cell are refused.");
      prm.declare_entry("Subdivisions",
                        "1",
                        Patterns::List(Patterns::Integer(1), 1, dim),
                        "Box and quadrilateral: coarse cells per direction "
                        "(one number for all directions, or one each).");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::FileName(),
                        "Mesh file (required there): Gmsh .msh or UCD "
                        ".inp/.ucd. A relative path is looked up first in "
                        "the folder of the parameter file, then in the "
                        "working directory. Inverted or degenerate cells are "
                        "refused.");
      prm.leave_subsection();
    }

    template <int dim>
    void
    Geometry<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      const std::string t = prm.get("Type");
      type                = t == "box"           ? Type::box :
                            t == "quadrilateral" ? Type::quadrilateral :
                                                   Type::mesh_file;
      lower            = Parameters::parse_point<dim>(prm.get("Lower corner"),
                                           "Geometry/Lower corner");
      upper            = Parameters::parse_point<dim>(prm.get("Upper corner"),
                                           "Geometry/Upper corner");
      const auto parts = Utilities::string_to_int(
        Utilities::split_string_list(prm.get("Subdivisions"), ','));
      subdivisions.assign(dim, parts[0]);
      if (parts.size() == dim)
        subdivisions.assign(parts.begin(), parts.end());
      else if (parts.size() != 1)
        throw InputError("Geometry/Subdivisions = '" + prm.get("Subdivisions") +
                         "': expected 1 or " + std::to_string(dim) +
                         " numbers");
      mesh_file                      = prm.get("Mesh file");
      const std::string corners_text = prm.get("Corners");
      prm.leave_subsection();

      if (type == Type::box)
        for (unsigned int d = 0; d < dim; ++d)
          if (!(upper[d] > lower[d]))
            throw InputError("Geometry/Upper corner must exceed "
                             "Geometry/Lower corner in every direction");
      if (type == Type::quadrilateral)
        {
          if (corners_text.empty())
            throw InputError(
              "Geometry/Type = quadrilateral needs Geometry/Corners");
          corners = parse_corners<dim>(corners_text);
        }
      else if (!corners_text.empty())
        throw InputError("Geometry/Corners is set but Geometry/Type = " + t +
                         " does not use it");
      if (type == Type::mesh_file && mesh_file.empty())
        throw InputError(
          "Geometry/Type = mesh file needs Geometry/Mesh file to be set");
    }

    // -------------------------------------------------------------- Material
    void
    Material::parse_parameters(ParameterHandler &prm,
                               const bool        incompressible_allowed)
    {
      prm.enter_subsection("Material");
      if (prm.get("Model") != "linear elastic")
        throw InputError("Material/Model = '" + prm.get("Model") +
                         "': mpm-fe solves small-strain linear elasticity; "
                         "set Model = linear elastic");
      density = get_number(prm, "Density");
      if (!(density > 0) || !std::isfinite(density))
        throw InputError("Material/Density = " + prm.get("Density") +
                         " must be positive");
      prm.enter_subsection(materials::subsection_name("linear elastic"));
      try
        {
          if (incompressible_allowed)
            {
              // the mixed formulation needs only 1/lambda: nu = 0.5 is fine
              youngs_modulus = get_number(prm, "Young's modulus");
              poissons_ratio = get_number(prm, "Poisson's ratio");
              if (!(youngs_modulus > 0) || !std::isfinite(youngs_modulus))
                throw InputError(
                  "Young's modulus = " + prm.get("Young's modulus") +
                  " must be positive");
              if (!(poissons_ratio >= 0 && poissons_ratio <= 0.5))
                throw InputError(
                  "Poisson's ratio = " + prm.get("Poisson's ratio") +
                  " is out of range [0, 0.5] (Formulation = "
                  "mixed)");
            }
          else
            {
              const auto c   = materials::elasticity::parse_parameters(prm);
              youngs_modulus = c.youngs_modulus();
              poissons_ratio = c.poissons_ratio();
            }
        }
      catch (const InputError &e)
        {
          prm.leave_subsection();
          prm.leave_subsection();
          throw InputError(std::string("Material/Linear elastic: ") + e.what() +
                           (incompressible_allowed ?
                              "" :
                              " (nu = 0.5 needs Discretisation/Formulation "
                              "= mixed)"));
        }
      prm.leave_subsection();
      prm.leave_subsection();
    }

    // --------------------------------------------------- BoundaryConditions
    void
    BoundaryConditions::declare_parameters(ParameterHandler &prm, const int dim)
    {
      const std::string xyz = dim == 1 ? "x" : dim == 2 ? "x, y" : "x, y, z";
      const auto        ids = Patterns::List(Patterns::Integer(0, 255));
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Clamped boundary ids",
                        "",
                        ids,
                        "Boundary ids (of Geometry) where every "
                        "displacement component is zero. Each id may appear "
                        "in one of the four id lists only, and must occur "
                        "on the mesh. Boundaries not listed anywhere are "
                        "free. Statics refuses conditions that leave a "
                        "rigid-body motion free.");
      prm.declare_entry("Slip boundary ids",
                        "",
                        ids,
                        "Boundary ids where the normal displacement is zero "
                        "and the tangential free (also on inclined and "
                        "curved boundaries).");
      prm.declare_entry("Prescribed displacement boundary ids",
                        "",
                        ids,
                        "Boundary ids where every displacement component "
                        "is given by Prescribed displacement. Refused by "
                        "the modal analysis.");
      prm.declare_entry("Prescribed displacement",
                        Parameters::default_expression(dim),
                        Patterns::Anything(),
                        "The displacement on the Prescribed displacement "
                        "boundary ids: dim expressions of " +
                          xyz + " and the Constants, separated by ';'.");
      prm.declare_entry("Traction boundary ids",
                        "",
                        ids,
                        "Boundary ids carrying the Traction. Boundaries "
                        "not listed anywhere are free. Refused by the modal "
                        "analysis.");
      prm.declare_entry("Traction",
                        Parameters::default_expression(dim),
                        Patterns::Anything(),
                        "Surface traction [force/area; in 2D force/length "
                        "per unit thickness] on the Traction boundary ids, "
                        "dim expressions of " +
                          xyz + " and the Constants, separated by ';'.");
      prm.declare_entry("Body force",
                        Parameters::default_expression(dim),
                        Patterns::Anything(),
                        "Body force per unit mass (gravity) [m/s^2], dim "
                        "expressions of " +
                          xyz +
                          " and the Constants, separated by ';'. Multiplied "
                          "by Material/Density.");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      clamped    = Parameters::parse_id_list(prm.get("Clamped boundary ids"));
      slip       = Parameters::parse_id_list(prm.get("Slip boundary ids"));
      prescribed = Parameters::parse_id_list(
        prm.get("Prescribed displacement boundary ids"));
      traction_ids =
        Parameters::parse_id_list(prm.get("Traction boundary ids"));
      prescribed_displacement = prm.get("Prescribed displacement");
      traction                = prm.get("Traction");
      body_force              = prm.get("Body force");
      prm.leave_subsection();

      // one kind of condition per boundary id
      const std::vector<std::pair<std::string, const decltype(clamped) *>>
        kinds = {{"Clamped", &clamped},
                 {"Slip", &slip},
                 {"Prescribed displacement", &prescribed},
                 {"Traction", &traction_ids}};
      for (unsigned int a = 0; a < kinds.size(); ++a)
        for (unsigned int b = a + 1; b < kinds.size(); ++b)
          for (const auto i : *kinds[a].second)
            for (const auto j : *kinds[b].second)
              if (i == j)
                throw InputError("Boundary conditions: boundary id " +
                                 std::to_string(i) + " is listed in both '" +
                                 kinds[a].first + " boundary ids' and '" +
                                 kinds[b].first + " boundary ids'");
    }

    // ------------------------------------------------------- Discretisation
    void
    Discretisation::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretisation");
      prm.declare_entry(
        "Formulation",
        "displacement",
        Patterns::Selection("displacement|mixed"),
        "displacement: Q_p elements for u. mixed: Taylor-Hood Q_p/Q_(p-1) "
        "for u and the pressure p = -lambda div u (no volumetric locking; "
        "0 < nu <= 0.5; Polynomial degree at least 2). The displacement "
        "formulation needs nu < 0.5, and so does the modal analysis.");
      prm.declare_entry("Polynomial degree",
                        "2",
                        Patterns::Integer(1, 8),
                        "p of the displacement elements Q_p (mixed: p >= 2, "
                        "the pressure is Q_(p-1)); curved boundaries of a "
                        "mesh file are followed by a mapping of degree p.");
      prm.declare_entry("Refinements",
                        "0, 1, 2",
                        Patterns::List(Patterns::Integer(0, 12), 1),
                        "The refinement study: one run per entry, each "
                        "with that many global refinements of the coarse "
                        "mesh; the list must increase. The last run gives "
                        "the reference value.");
      prm.leave_subsection();
    }

    void
    Discretisation::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretisation");
      formulation = prm.get("Formulation") == "mixed" ?
                      Formulation::mixed :
                      Formulation::displacement;
      degree      = prm.get_integer("Polynomial degree");
      refinements.clear();
      for (const int r : Utilities::string_to_int(
             Utilities::split_string_list(prm.get("Refinements"), ',')))
        refinements.push_back(r);
      prm.leave_subsection();
      if (formulation == Formulation::mixed && degree < 2)
        throw InputError("Discretisation/Polynomial degree = 1 with "
                         "Formulation = mixed: Taylor-Hood needs p >= 2 "
                         "(the pressure is Q_(p-1))");
      for (unsigned int i = 1; i < refinements.size(); ++i)
        if (refinements[i] <= refinements[i - 1])
          throw InputError("Discretisation/Refinements = '" +
                           Utilities::to_string(refinements[i - 1]) + ", " +
                           Utilities::to_string(refinements[i]) +
                           "...': the list must increase");
    }

    // --------------------------------------------------------- LinearSolver
    void
    LinearSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry(
        "Method",
        "direct",
        Patterns::Selection("direct|AMG"),
        "direct: UMFPACK on one process (statics and modal analysis). "
        "AMG: the mesh distributed over the MPI processes (p4est), the "
        "system in Trilinos matrices, solved by CG (displacement "
        "formulation) or MINRES (mixed formulation) preconditioned by ML "
        "algebraic multigrid with the rigid-body modes as near-null space; "
        "statics only. Run it under mpirun for large 3D references; "
        "direct under mpirun with more than one process is refused.");
      prm.declare_entry("Tolerance",
                        "1e-10",
                        Patterns::Double(1e-16, 1e-2),
                        "AMG: the iteration stops when the residual is "
                        "below this fraction of the load vector's norm (CG), "
                        "or when the residual in the preconditioner's norm "
                        "is below this fraction of its initial value "
                        "(MINRES, mixed formulation).");
      prm.declare_entry("Maximum iterations",
                        "10000",
                        Patterns::Integer(1),
                        "AMG: a solve that needs more iterations stops the "
                        "run with status 2.");
      prm.leave_subsection();
    }

    void
    LinearSolver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      method    = prm.get("Method") == "AMG" ? Method::amg : Method::direct;
      tolerance = prm.get_double("Tolerance");
      max_iterations = prm.get_integer("Maximum iterations");
      prm.leave_subsection();
    }

    // ------------------------------------------------------------- Analysis
    template <int dim>
    void
    Analysis<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Analysis");
      prm.declare_entry("Type",
                        "static",
                        Patterns::Selection("static|modal"),
                        "static: K u = f, the displacement at the Points of "
                        "interest. modal: the lowest eigenpairs of "
                        "K u = omega^2 M u (consistent mass, Lanczos with "
                        "shift-and-invert); near-zero (rigid-body) modes "
                        "are skipped and reported. modal refuses the mixed "
                        "formulation, Linear solver/Method = AMG, tractions "
                        "and prescribed displacements.");
      prm.declare_entry("Number of modes",
                        "3",
                        Patterns::Integer(1, 50),
                        "modal: eigenfrequencies reported (not counting "
                        "rigid-body modes). The quantity of interest is the "
                        "first period 2 pi/omega_1.");
      prm.declare_entry("Points of interest",
                        Parameters::default_point(dim, 0.),
                        Patterns::Anything(),
                        "static: points where the displacement is "
                        "evaluated, separated by ';' (e.g. '48, 52; 48, "
                        "60'); each must lie in the body. The first one "
                        "carries the quantity of interest.");
      prm.declare_entry("Component of interest",
                        std::to_string(dim - 1),
                        Patterns::Integer(0, dim - 1),
                        "static: the displacement component at the first "
                        "Point of interest that is the quantity of interest, "
                        "whose change over the refinements is reported "
                        "(0 = x).");
      prm.declare_entry("Reference value",
                        "0",
                        NumberOrConstant(),
                        "A value to compare the result with (static: the "
                        "component of interest; modal: the first period "
                        "[s]); a number or an expression of the Constants; "
                        "0: none.");
      prm.declare_entry("Required relative change",
                        "0",
                        Patterns::Double(0, 1),
                        "If positive, the relative change of the quantity "
                        "of interest over the last two refinements must be "
                        "below this, or mpm-fe warns (exit status stays 0). "
                        "0: no check.");
      prm.leave_subsection();
    }

    template <int dim>
    void
    Analysis<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Analysis");
      type    = prm.get("Type") == "modal" ? Type::modal : Type::statics;
      n_modes = prm.get_integer("Number of modes");
      points.clear();
      for (const auto &p :
           Utilities::split_string_list(prm.get("Points of interest"), ';'))
        points.push_back(
          Parameters::parse_point<dim>(p, "Analysis/Points of interest"));
      if (points.empty())
        throw InputError("Analysis/Points of interest must not be empty");
      component       = prm.get_integer("Component of interest");
      reference_value = get_number(prm, "Reference value");
      required_change = prm.get_double("Required relative change");
      prm.leave_subsection();
    }

    // --------------------------------------------------------------- Output
    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output-fe",
                        Patterns::DirectoryName(),
                        "Folder for refinement_study.csv and the vtu file "
                        "(solution.vtu or modes.vtu), relative to the "
                        "working directory; written only after every run "
                        "succeeded.");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "ParaView file of the finest run: displacement "
                        "(and pressure), or every mode shape.");
      prm.declare_entry("Test summary file",
                        "",
                        Patterns::FileName(),
                        "If set, the refinement table with 6 significant "
                        "digits is written to this file (relative to the "
                        "working directory), for regression tests.");
      prm.leave_subsection();
    }

    void
    Output::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory    = prm.get("Directory");
      write_vtu    = prm.get_bool("Write vtu");
      test_summary = prm.get("Test summary file");
      prm.leave_subsection();
      if (directory.empty())
        throw InputError("Output/Directory must not be empty");
    }

    // -------------------------------------------------------- AllParameters
    template <int dim>
    void
    AllParameters<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "Space dimension of the model: 2 or 3.");
      prm.declare_entry("Kinematic assumption",
                        "default",
                        Patterns::Selection("default|three dimensional|"
                                            "plane strain|plane stress"),
                        "How the model is embedded in 3D: three dimensional "
                        "(3D only), plane strain or plane stress (2D only); "
                        "other combinations are refused. "
                        "default: three dimensional in 3D, plane strain in "
                        "2D. Plane stress uses lambda* = 2 lambda mu / "
                        "(lambda + 2 mu).");
      prm.declare_entry("Constants",
                        "",
                        Patterns::Anything(),
                        "Named constants, comma-separated name=value pairs "
                        "with plain numbers as values, e.g. 'L=1, H=0.1', "
                        "for the expressions, the Material numbers and "
                        "Reference value. A constant named x, y, z or t is "
                        "refused.");
      Geometry<dim>::declare_parameters(prm);
      // The Material subsection of mpm, so that a linear elastic body's
      // section can be copied, but with the one model mpm-fe solves.
      prm.enter_subsection("Material");
      std::string models;
      for (const auto &entry : materials::registered_materials())
        models += (models.empty() ? "" : "|") + entry.name;
      prm.declare_entry("Model",
                        "linear elastic",
                        Patterns::Selection(models),
                        "mpm-fe solves small-strain linear elasticity: "
                        "linear elastic is the only model it accepts (any "
                        "other model of mpm is an input error). The "
                        "subsection is that of mpm's parameter file, so a "
                        "linear elastic body's Material can be copied.");
      prm.declare_entry("Density",
                        "1000",
                        NumberOrConstant(),
                        "Mass density rho [kg/m^3], positive: the mass "
                        "matrix of the modal analysis and the weight of the "
                        "Boundary conditions/Body force.");
      prm.enter_subsection(materials::subsection_name("linear elastic"));
      materials::elasticity::declare_parameters(prm);
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        NumberOrConstant(),
                        "Poisson's ratio nu [-], in [0, 0.5); in (0, 0.5] "
                        "with Discretisation/Formulation = mixed.");
      prm.leave_subsection();
      prm.leave_subsection();
      BoundaryConditions::declare_parameters(prm, dim);
      Discretisation::declare_parameters(prm);
      LinearSolver::declare_parameters(prm);
      Analysis<dim>::declare_parameters(prm);
      Output::declare_parameters(prm);
    }

    template <int dim>
    void
    AllParameters<dim>::parse_parameters(ParameterHandler &prm)
    {
      if (prm.get_integer("Dimension") != dim)
        throw InputError("Dimension mismatch");
      const std::string k = prm.get("Kinematic assumption");
      kinematics =
        k == "plane stress"      ? KinematicAssumption::plane_stress :
        k == "plane strain"      ? KinematicAssumption::plane_strain :
        k == "three dimensional" ? KinematicAssumption::three_dimensional :
        dim == 3                 ? KinematicAssumption::three_dimensional :
                                   KinematicAssumption::plane_strain;
      if ((dim == 3) != (kinematics == KinematicAssumption::three_dimensional))
        throw InputError("Kinematic assumption = '" + k +
                         "' does not fit Dimension = " + std::to_string(dim));
      constants = parse_constants(prm.get("Constants"), "Constants");
      const ConstantsScope scope(constants);

      geometry.parse_parameters(prm);
      discretisation.parse_parameters(prm);
      material.parse_parameters(prm,
                                discretisation.formulation ==
                                  Discretisation::Formulation::mixed);
      boundary.parse_parameters(prm);
      solver.parse_parameters(prm);
      analysis.parse_parameters(prm);
      output.parse_parameters(prm);

      // the expressions are parsed here once so that errors surface now
      const std::string vars = dim == 2 ? "x,y" : "x,y,z";
      Expression<dim>(boundary.prescribed_displacement,
                      dim,
                      vars,
                      constants,
                      false,
                      "Boundary conditions/Prescribed displacement");
      Expression<dim>(boundary.traction,
                      dim,
                      vars,
                      constants,
                      false,
                      "Boundary conditions/Traction");
      Expression<dim>(boundary.body_force,
                      dim,
                      vars,
                      constants,
                      false,
                      "Boundary conditions/Body force");

      if (analysis.type == Analysis<dim>::Type::modal &&
          discretisation.formulation == Discretisation::Formulation::mixed)
        throw InputError("Analysis/Type = modal with Discretisation/"
                         "Formulation = mixed is not implemented (use the "
                         "displacement formulation; the modes of nearly "
                         "incompressible solids are not a reference here)");
      if (analysis.type == Analysis<dim>::Type::modal &&
          solver.method == LinearSolver::Method::amg)
        throw InputError("Analysis/Type = modal with Linear solver/Method = "
                         "AMG is not implemented: the modal analysis "
                         "inverts K - sigma M with UMFPACK on one process "
                         "(set Method = direct)");
      if (analysis.type == Analysis<dim>::Type::modal &&
          (!boundary.traction_ids.empty() || !boundary.prescribed.empty()))
        throw InputError("Analysis/Type = modal: loads and prescribed "
                         "displacements have no meaning for the free "
                         "vibration modes; remove Boundary conditions/"
                         "Traction boundary ids and Prescribed displacement "
                         "boundary ids");
    }

    template struct Geometry<2>;
    template struct Geometry<3>;
    template struct Analysis<2>;
    template struct Analysis<3>;
    template struct AllParameters<2>;
    template struct AllParameters<3>;
  } // namespace fe_reference
} // namespace mpm
