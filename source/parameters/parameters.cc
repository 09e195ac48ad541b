#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <mpm/grid/quadrilateral_mesh.h>
#include <mpm/parameters/parameters.h>
#include <mpm/utilities/expression.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace mpm
{
  namespace Parameters
  {
    using namespace dealii;

    namespace
    {
      std::vector<unsigned int>
      parse_unsigned_list(const std::string &text,
                          const unsigned int n,
                          const std::string &entry)
      {
        const auto parts = Utilities::split_string_list(text, ',');
        if (parts.size() != n && parts.size() != 1)
          throw InputError("Parameter '" + entry + "' = '" + text +
                           "': expected 1 or " + std::to_string(n) +
                           " comma-separated integers");
        std::vector<unsigned int> out;
        for (const auto &p : parts)
          {
            const int v = Utilities::string_to_int(p);
            if (v <= 0)
              throw InputError("Parameter '" + entry + "' = '" + text +
                               "': entries must be positive integers");
            out.push_back(v);
          }
        if (out.size() == 1)
          out.resize(n, out[0]);
        return out;
      }

    } // namespace

    /// "0; 0" for vector-valued expressions
    std::string
    default_expression(const int dim)
    {
      std::string s = "0";
      for (int d = 1; d < dim; ++d)
        s += "; 0";
      return s;
    }

    std::string
    default_point(const int dim, const double value)
    {
      std::string s;
      for (int d = 0; d < dim; ++d)
        s += (d ? ", " : "") + Utilities::to_string(value);
      return s;
    }

    std::vector<types::boundary_id>
    parse_id_list(const std::string &text)
    {
      std::vector<types::boundary_id> ids;
      for (const int i :
           Utilities::string_to_int(Utilities::split_string_list(text, ',')))
        ids.push_back(static_cast<types::boundary_id>(i));
      return ids;
    }

    template <int dim>
    Point<dim>
    parse_point(const std::string &text, const std::string &entry)
    {
      const auto parts = Utilities::split_string_list(text, ',');
      if (parts.size() != dim)
        throw InputError("Parameter '" + entry + "' = '" + text +
                         "': expected " + std::to_string(dim) +
                         " comma-separated coordinates");
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = Utilities::string_to_double(parts[d]);
      return p;
    }

    std::string
    body_section(const unsigned int i)
    {
      return "Body " + std::to_string(i);
    }

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

    // ---------------------------------------------------------- TimeStepping
    void
    TimeStepping::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      prm.declare_entry("End time", "1", Patterns::Double(0), "End time [s].");
      prm.declare_entry("Scheme",
                        "MUSL",
                        Patterns::Selection("USF|USL|MUSL"),
                        "When the stress is updated: USF (before the "
                        "internal force), USL (after the grid update), MUSL "
                        "(after re-mapping the updated particle momentum). "
                        "USL reads the grid velocity of nodes that particles "
                        "barely touch at free surfaces; it then needs a CFL "
                        "number of about 0.1 (see doc/theory.md).");
      prm.declare_entry("Time step control",
                        "CFL",
                        Patterns::Selection("fixed|CFL"),
                        "Fixed step, or dt = CFL number * min_p h/(c_p + "
                        "|v_p|) recomputed every step.");
      prm.declare_entry("Time step",
                        "1e-3",
                        Patterns::Double(0),
                        "Step for Time step control = fixed [s]. A step above "
                        "the stability limit h/(c + |v|) is refused.");
      prm.declare_entry("CFL number",
                        "0.5",
                        Patterns::Double(0, 1),
                        "Fraction of the stability limit used as step.");
      prm.declare_entry("FLIP fraction",
                        "1",
                        Patterns::Double(0, 1),
                        "Particle velocity update: 1 = FLIP (increment), 0 "
                        "= PIC (grid velocity), in between a blend.");
      prm.declare_entry(
        "Velocity transfer",
        "FLIP",
        Patterns::Selection("FLIP|APIC"),
        "FLIP: the particle velocity is updated by the FLIP fraction "
        "blend of increment and grid velocity. APIC (Jiang et al. 2015): "
        "the particle carries an affine velocity C_p = sum_i v_i grad "
        "N_ip besides v_p = sum_i N_ip v_i, and P2G sends "
        "m_p (v_p + C_p (x_i - x_p)): linear velocity fields (a rigid "
        "rotation) are transferred exactly and angular momentum is "
        "conserved. With APIC the FLIP fraction must stay 1 (unused).");
      prm.declare_entry("Damping coefficient",
                        "0",
                        Patterns::Double(0),
                        "Mass-proportional damping c [1/s]: the grid "
                        "force gets -c m_i v_i (for quasi-static runs).");
      prm.declare_entry("Maximum number of steps",
                        "0",
                        Patterns::Integer(0),
                        "Stop after this many steps (0: no limit).");
      prm.leave_subsection();
    }

    void
    TimeStepping::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      end_time            = prm.get_double("End time");
      const std::string s = prm.get("Scheme");
      scheme              = s == "USF" ? Scheme::usf :
                            s == "USL" ? Scheme::usl :
                                         Scheme::musl;
      step_control        = prm.get("Time step control") == "fixed" ?
                              StepControl::fixed :
                              StepControl::cfl;
      time_step           = prm.get_double("Time step");
      cfl_number          = prm.get_double("CFL number");
      flip_fraction       = prm.get_double("FLIP fraction");
      apic                = prm.get("Velocity transfer") == "APIC";
      damping             = prm.get_double("Damping coefficient");
      max_steps           = prm.get_integer("Maximum number of steps");
      prm.leave_subsection();
      if (step_control == StepControl::fixed && !(time_step > 0))
        throw InputError("Time stepping/Time step must be positive");
      if (step_control == StepControl::cfl && !(cfl_number > 0))
        throw InputError("Time stepping/CFL number must be positive");
      if (apic && flip_fraction != 1.)
        throw InputError(
          "Time stepping/FLIP fraction = " + std::to_string(flip_fraction) +
          " has no meaning with Velocity transfer = APIC (its particle "
          "velocity is the grid velocity; the affine part keeps what PIC "
          "loses): remove the entry");
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

    // ------------------------------------------------------- Shape functions
    void
    ShapeFunctions::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Shape functions");
      prm.declare_entry("Family",
                        "standard",
                        Patterns::Selection(shape_functions::family_pattern()),
                        shape_functions::family_documentation());
      prm.declare_entry(
        "Domain outside the grid",
        "error",
        Patterns::Selection("error|clamp"),
        "What happens when a particle domain reaches outside the grid: "
        "error stops with a message naming the particle; clamp cuts GIMP "
        "boxes at the grid boundary and moves CPDI corners onto it.");
      prm.declare_entry(
        "Cache stencils",
        "true",
        Patterns::Bool(),
        "GIMP, CPDI, CPDI2: build each particle's stencil once per step and "
        "keep it for the step's later passes (G2P, the stress update), at "
        "about 200 bytes per particle in 2D and 600 in 3D (CPDI); false "
        "builds it in every pass (less memory, slower).");
      prm.leave_subsection();
    }

    void
    ShapeFunctions::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Shape functions");
      family         = shape_functions::parse_family(prm.get("Family"));
      clamp          = prm.get("Domain outside the grid") == "clamp";
      cache_stencils = prm.get_bool("Cache stencils");
      prm.leave_subsection();
    }

    // ------------------------------------------------------------------ Body
    template <int dim>
    void
    Body<dim>::declare_parameters(ParameterHandler &prm)
    {
      const std::string xyz = dim == 1 ? "x" : dim == 2 ? "x, y" : "x, y, z";
      prm.declare_entry("Geometry",
                        "box",
                        Patterns::Selection("box|ball|quadrilateral|mesh file"),
                        "Body mesh: a subdivided box, a ball (disk in 2D) "
                        "meshed conformingly, a quadrilateral (the "
                        "subdivided unit box mapped bi/trilinearly onto the "
                        "Corners), or a mesh file. Each body cell is split "
                        "into n^dim particle domains.");
      prm.declare_entry("Lower corner",
                        default_point(dim, 0.25),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: lower corner [m].");
      prm.declare_entry("Upper corner",
                        default_point(dim, 0.75),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: upper corner [m].");
      prm.declare_entry("Subdivisions",
                        "4",
                        Patterns::List(Patterns::Integer(1), 1, dim),
                        "Box and quadrilateral: body cells per direction "
                        "(one number for all directions, or one each).");
      prm.declare_entry(
        "Corners",
        "",
        Patterns::Anything(),
        "Quadrilateral: the 2^dim corners separated by ';', counter-"
        "clockwise in 2D (Cook's membrane: 0, 0; 48, 44; 48, 60; 0, 44); in "
        "3D the bottom face counter-clockwise, then the top face. Boundary "
        "ids as for a box in the corners' own directions (2D: 0 the edge "
        "from the first corner to the fourth, 1 from the second to the "
        "third, 2 from the first to the second, 3 from the third to the "
        "fourth).");
      prm.declare_entry("Center",
                        default_point(dim, 0.5),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Ball: centre [m].");
      prm.declare_entry("Radius",
                        "0.25",
                        NumberOrConstant(),
                        "Ball: radius [m] (a number or an expression of the "
                        "Constants).");
      prm.declare_entry("Refinements",
                        "2",
                        Patterns::Integer(0, 10),
                        "Ball: global refinements of the coarse ball mesh "
                        "(12 cells in 2D, 32 in 3D).");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::FileName(),
                        "Mesh file: body mesh (Gmsh .msh or UCD).");
      prm.declare_entry("Particles per direction",
                        "2",
                        Patterns::Integer(1, 10),
                        "n: each body cell gives n^dim particles.");
      prm.declare_entry("Initial velocity",
                        default_expression(dim),
                        Patterns::Anything(),
                        "Velocity at t = 0 [m/s], dim expressions of " + xyz +
                          " separated by ';' (muparser).");
      prm.declare_entry(
        "Initial stress",
        dim == 1 ? "0" :
        dim == 2 ? "0; 0; 0" :
                   "0; 0; 0; 0; 0; 0",
        Patterns::Anything(),
        std::string("Cauchy stress at t = 0 [Pa], expressions of ") + xyz +
          " separated by ';': " +
          (dim == 1 ? "xx" :
           dim == 2 ? "xx; yy; xy (and optionally a fourth, zz)" :
                      "xx; yy; zz; yz; xz; xy") +
          ".");
      prm.declare_entry("Body force",
                        default_expression(dim),
                        Patterns::Anything(),
                        "Body force per unit mass [m/s^2], expressions of " +
                          xyz + ", the material coordinates " +
                          (dim == 1 ? "X" :
                           dim == 2 ? "X, Y" :
                                      "X, Y, Z") +
                          " (initial position) and t, separated by ';'.");
      prm.declare_entry("Traction",
                        default_expression(dim),
                        Patterns::Anything(),
                        "Surface traction [Pa] on the body-mesh boundaries "
                        "listed in Traction boundary ids; same variables "
                        "as Body force.");
      prm.declare_entry("Traction boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
                        "Body-mesh boundary ids that carry the traction "
                        "(box: 0/1 x min/max, 2/3 y, 4/5 z).");
      prm.enter_subsection("Material");
      materials::declare_material_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Locking remedies");
      prm.declare_entry(
        "Stress filter",
        "none",
        Patterns::Selection("none|assumed stress|convection correction"),
        "assumed stress: project the stresses of this body's particles in "
        "each cell onto the Pian-Sumihara field of the cell (5 parameters "
        "in 2D, 18 in 3D) where the next internal force is computed, and "
        "integrate that field's force exactly over the particle domains "
        "(doc/theory.md). 2D and 3D. "
        "convection correction: the internal force of each cell integrates "
        "the least-squares line of its particles' stresses exactly over the "
        "part of the cell the body occupies (the seed's correction of the "
        "cell-crossing error); the stored stresses are not changed. 1D.");
      prm.declare_entry(
        "Body force correction",
        "true",
        Patterns::Bool(),
        "With Stress filter = convection correction: integrate the body "
        "force the same way, the least-squares line of the particles' force "
        "per length integrated exactly against the shape functions over the "
        "occupied part of each cell, consistently with the stress; the "
        "body's total load stays sum_p m_p b_p (doc/theory.md, 4.11).");
      prm.declare_entry("Filter metric",
                        "mass",
                        Patterns::Selection("mass|compliance"),
                        "mass: the seed's projection (Frobenius inner product, "
                        "weights m_p); compliance: the Hellinger-Reissner "
                        "projection (inner product C^-1, weights V_p), for "
                        "materials with elastic moduli.");
      prm.declare_entry(
        "Filter field",
        "Pian-Sumihara",
        Patterns::Selection("Pian-Sumihara|enriched"),
        "The assumed-stress field of Stress filter = assumed stress. "
        "Pian-Sumihara: the seed's 5-beta (2D) / 18-beta (3D) field. "
        "enriched: adds the linear variation of each normal stress along "
        "its own direction (7 / 21 betas), which does no work on a filled "
        "cell's Q1 velocities but keeps a stress that varies along the "
        "motion of a convecting body (doc/theory.md 4.8).");
      prm.declare_entry(
        "Filtered stress",
        "written back",
        Patterns::Selection("written back|force only"),
        "What the assumed-stress projection replaces. written back: the "
        "particles' stresses (the seed; the strains are made consistent). "
        "force only: the projected field makes the internal force, the "
        "particles keep the stresses their material computed, so a smooth "
        "stress the field cannot represent is not cut back every step "
        "(doc/theory.md 4.13). Elastic and hyperelastic materials only.");
      prm.declare_entry(
        "Volumetric smoothing",
        "none",
        Patterns::Selection("none|cell|node"),
        "The volumetric-locking remedy: the volume change that sets the "
        "pressure is averaged, the deviatoric part stays the particle's. "
        "cell: over this body's particles in the cell (the seed's "
        "theta-bar; F-bar for models that use F); node: mass-weighted to "
        "the grid nodes and interpolated back (averages of all node-smoothed "
        "bodies mix at shared nodes).");
      prm.leave_subsection();
    }

    template <int dim>
    void
    Body<dim>::parse_parameters(ParameterHandler &prm)
    {
      const std::string g = prm.get("Geometry");
      geometry            = g == "box"           ? Geometry::box :
                            g == "ball"          ? Geometry::ball :
                            g == "quadrilateral" ? Geometry::quadrilateral :
                                                   Geometry::mesh_file;
      lower = parse_point<dim>(prm.get("Lower corner"), "Lower corner");
      upper = parse_point<dim>(prm.get("Upper corner"), "Upper corner");
      subdivisions =
        parse_unsigned_list(prm.get("Subdivisions"), dim, "Subdivisions");
      center                  = parse_point<dim>(prm.get("Center"), "Center");
      radius                  = get_number(prm, "Radius");
      refinements             = prm.get_integer("Refinements");
      mesh_file               = prm.get("Mesh file");
      particles_per_direction = prm.get_integer("Particles per direction");
      initial_velocity        = prm.get("Initial velocity");
      initial_stress          = prm.get("Initial stress");
      body_force              = prm.get("Body force");
      traction                = prm.get("Traction");
      traction_boundary_ids   = parse_id_list(prm.get("Traction boundary ids"));
      prm.enter_subsection("Locking remedies");
      assumed_stress_filter = prm.get("Stress filter") == "assumed stress";
      convection_correction =
        prm.get("Stress filter") == "convection correction";
      convection_body_force = prm.get_bool("Body force correction");
      compliance_metric     = prm.get("Filter metric") == "compliance";
      enriched_filter       = prm.get("Filter field") == "enriched";
      filter_force_only     = prm.get("Filtered stress") == "force only";
      const std::string vs  = prm.get("Volumetric smoothing");
      volumetric_smoothing = vs == "cell" ? filters::VolumetricSmoothing::cell :
                             vs == "node" ? filters::VolumetricSmoothing::node :
                                            filters::VolumetricSmoothing::none;
      prm.leave_subsection();
      if (assumed_stress_filter && dim == 1)
        throw InputError("Locking remedies/Stress filter = assumed stress "
                         "needs Dimension 2 or 3");
      if (convection_correction && dim != 1)
        throw InputError("Locking remedies/Stress filter = convection "
                         "correction is the 1D correction of the "
                         "cell-crossing error and needs Dimension 1 (in 2D "
                         "and 3D use assumed stress)");
      if (geometry == Geometry::box)
        for (unsigned int d = 0; d < dim; ++d)
          if (!(upper[d] > lower[d]))
            throw InputError(
              "Upper corner must exceed Lower corner in every direction");
      if (geometry == Geometry::ball && !(radius > 0))
        throw InputError("Radius = " + prm.get("Radius") + " must be positive");
      if (geometry == Geometry::mesh_file && mesh_file.empty())
        throw InputError("Geometry = mesh file needs Mesh file to be set");
      corners.clear();
      const std::string corners_text = prm.get("Corners");
      if (geometry == Geometry::quadrilateral)
        {
          if (corners_text.empty())
            throw InputError("Geometry = quadrilateral needs Corners");
          std::vector<Point<dim>> ccw;
          for (const auto &c : Utilities::split_string_list(corners_text, ';'))
            ccw.push_back(parse_point<dim>(c, "Corners"));
          corners =
            lexicographic_corners(ccw, "Corners = '" + corners_text + "'");
        }
      else if (!corners_text.empty())
        throw InputError("Corners is set but Geometry = " + g +
                         " does not use it");
    }

    // ---------------------------------------------------------------- Output
    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        Patterns::DirectoryName(),
                        "Folder for all results, relative to the working "
                        "directory. Created if missing.");
      prm.declare_entry("Interval",
                        "0.1",
                        Patterns::Double(0),
                        "Simulated time between outputs [s]; 0: every "
                        "step. The first and last states are always "
                        "written.");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "ParaView files of particles (and grid): "
                        "particles.pvd, grid.pvd.");
      prm.declare_entry("Write grid",
                        "true",
                        Patterns::Bool(),
                        "Also write the background grid fields (nodal "
                        "mass, velocity) when Write vtu is on.");
      prm.declare_entry("Write csv",
                        "true",
                        Patterns::Bool(),
                        "Particle table particles-NNNNN.csv, sorted by id.");
      prm.declare_entry("Test summary file",
                        "",
                        Patterns::FileName(),
                        "If set, a short summary for regression tests is "
                        "written to this file (relative to the working "
                        "directory).");
      prm.declare_entry("Progress interval",
                        "10",
                        Patterns::Double(0),
                        "Wall-clock seconds between progress lines.");
      prm.leave_subsection();
    }

    void
    Output::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory         = prm.get("Directory");
      interval          = prm.get_double("Interval");
      write_vtu         = prm.get_bool("Write vtu");
      write_grid        = prm.get_bool("Write grid");
      write_csv         = prm.get_bool("Write csv");
      test_summary      = prm.get("Test summary file");
      progress_interval = prm.get_double("Progress interval");
      prm.leave_subsection();
      if (directory.empty())
        throw InputError("Output/Directory must not be empty");
    }

    void
    Checkpointing::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpointing");
      prm.declare_entry("Steps between checkpoints",
                        "0",
                        Patterns::Integer(0),
                        "Write a checkpoint after every step whose number is "
                        "a multiple of this (0: not by step count). The "
                        "checkpoint is kept in Output/Directory/checkpoint/; "
                        "only the latest complete one is kept.");
      prm.declare_entry("Wall time between checkpoints",
                        "0",
                        Patterns::Double(0),
                        "Also write a checkpoint when this many wall-clock "
                        "seconds have passed since the last one (or the "
                        "start; 0: not by wall-clock time).");
      prm.declare_entry("Resume computation",
                        "false",
                        Patterns::Selection("false|true|auto"),
                        "true: continue from the latest checkpoint in "
                        "Output/Directory/checkpoint/ (an input error if "
                        "there is none); auto: continue if there is one, "
                        "else start from the initial state; false: start "
                        "from the initial state. The command-line option "
                        "--resume sets true. A restart refuses parameters "
                        "that differ from the checkpoint's, except Output, "
                        "Checkpointing, Time stepping/End time and Maximum "
                        "number of steps.");
      prm.leave_subsection();
    }

    void
    Checkpointing::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpointing");
      steps_between       = prm.get_integer("Steps between checkpoints");
      wall_seconds        = prm.get_double("Wall time between checkpoints");
      const std::string r = prm.get("Resume computation");
      resume              = r == "true" ? Resume::yes :
                            r == "auto" ? Resume::automatic :
                                          Resume::no;
      prm.leave_subsection();
    }

    // ------------------------------------------------------------- preamble
    void
    declare_preamble(ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(1, 3),
                        "Space dimension of the model: 1, 2 or 3.");
      prm.declare_entry("Number of bodies",
                        "1",
                        Patterns::Integer(1, 100),
                        "Number of `Body i` subsections (i = 0, 1, ...).");
    }

    namespace
    {
      /// One line of a parameter file after `include` expansion, with
      /// where it came from.
      struct SourceLine
      {
        std::string  text, file;
        unsigned int line;
      };

      /**
       * Read @p file_name and expand `include other.prm` lines in place,
       * each resolved next to the file that contains it (deal.II itself
       * resolves includes against the working directory).
       */
      void
      expand_includes(const std::string       &file_name,
                      std::vector<SourceLine> &out,
                      const unsigned int       depth)
      {
        namespace fs = std::filesystem;
        std::ifstream in(file_name);
        if (!in)
          throw InputError("Cannot open the parameter file '" + file_name +
                           "'");
        if (depth > 20)
          throw InputError("Parameter file '" + file_name +
                           "': includes nested more than 20 deep (a cycle?)");
        std::string  text;
        unsigned int n = 0;
        while (std::getline(in, text))
          {
            ++n;
            const auto first = text.find_first_not_of(" \t");
            if (first != std::string::npos &&
                (text.compare(first, 8, "include ") == 0 ||
                 text.compare(first, 8, "INCLUDE ") == 0))
              {
                std::string name = text.substr(first + 8);
                const auto  hash = name.find('#');
                if (hash != std::string::npos)
                  name = name.substr(0, hash);
                name.erase(0, name.find_first_not_of(" \t"));
                name.erase(name.find_last_not_of(" \t\r") + 1);
                fs::path path(name);
                if (path.is_relative())
                  path = fs::path(file_name).parent_path() / path;
                if (!fs::exists(path))
                  throw InputError("line " + std::to_string(n) + " of '" +
                                   file_name + "': the included file '" + name +
                                   "' does not exist (looked for " +
                                   path.string() + ")");
                expand_includes(path.string(), out, depth + 1);
              }
            else
              out.push_back({text, file_name, n});
          }
      }

      /// Parse the expanded file; errors name the original file and line.
      void
      parse_expanded(ParameterHandler  &prm,
                     const std::string &file_name,
                     const bool         skip_undefined)
      {
        std::vector<SourceLine> lines;
        expand_includes(file_name, lines, 0);
        std::string all;
        for (const auto &l : lines)
          all += l.text + '\n';
        std::istringstream stream(all);
        try
          {
            prm.parse_input(stream, file_name, "", skip_undefined);
          }
        catch (const std::exception &e)
          {
            // Replace deal.II's "Line <N> of file <F>:" by the real place.
            std::string msg = clean_dealii_message(e.what());
            const auto  a   = msg.find("Line <");
            const auto  b   = a == std::string::npos ? a : msg.find('>', a);
            const auto  c = b == std::string::npos ? b : msg.find(">:", b + 1);
            if (c != std::string::npos)
              {
                const unsigned long k =
                  std::stoul(msg.substr(a + 6, b - a - 6)) - 1;
                if (k < lines.size())
                  msg = "line " + std::to_string(lines[k].line) + " of '" +
                        lines[k].file + "':" + msg.substr(c + 2);
              }
            throw InputError(msg);
          }
      }
    } // namespace

    Preamble
    read_preamble(const std::string &file_name)
    {
      ParameterHandler prm;
      declare_preamble(prm);
      try
        {
          parse_expanded(prm, file_name, /*skip_undefined=*/true);
        }
      catch (const InputError &e)
        {
          throw InputError("Error reading the parameter file '" + file_name +
                           "': " + e.what());
        }
      return {static_cast<unsigned int>(prm.get_integer("Dimension")),
              static_cast<unsigned int>(prm.get_integer("Number of bodies"))};
    }

    void
    parse_file(ParameterHandler &prm, const std::string &file_name)
    {
      try
        {
          parse_expanded(prm, file_name, /*skip_undefined=*/false);
        }
      catch (const InputError &e)
        {
          throw InputError("Error in the parameter file '" + file_name +
                           "':\n    " + e.what());
        }
    }

    // -------------------------------------------------------- AllParameters
    template <int dim>
    void
    AllParameters<dim>::declare_parameters(ParameterHandler  &prm,
                                           const unsigned int n_bodies)
    {
      declare_preamble(prm);
      prm.declare_entry(
        "Kinematic assumption",
        "default",
        Patterns::Selection("default|three dimensional|plane strain|"
                            "plane stress|uniaxial strain|uniaxial stress"),
        "How the model is embedded in 3D. default: three dimensional in 3D, "
        "plane strain in 2D, uniaxial stress in 1D.");
      prm.declare_entry("Constants",
                        "",
                        Patterns::Anything(),
                        "Named constants for all expressions, e.g. "
                        "'v0=0.1, L=25'. Benchmarks read their physical "
                        "parameters from here too.");
      prm.declare_entry("Benchmark",
                        "none",
                        Patterns::Anything(),
                        "Name of a benchmark whose error measures are added "
                        "to the statistics file (see doc/benchmarks.md), or "
                        "none.");
      Grid<dim>::declare_parameters(prm);
      TimeStepping::declare_parameters(prm);
      BoundaryConditions::declare_parameters(prm);
      ShapeFunctions::declare_parameters(prm);
      Output::declare_parameters(prm);
      Checkpointing::declare_parameters(prm);
      LoadBalancing::declare_parameters(prm);
      prm.enter_subsection("Bodies");
      for (unsigned int i = 0; i < n_bodies; ++i)
        {
          prm.enter_subsection(body_section(i));
          Body<dim>::declare_parameters(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    template <int dim>
    void
    AllParameters<dim>::parse_parameters(ParameterHandler &prm)
    {
      if (prm.get_integer("Dimension") != dim)
        throw InputError("Dimension mismatch");
      n_bodies            = prm.get_integer("Number of bodies");
      const std::string k = prm.get("Kinematic assumption");
      if (k == "default")
        kinematics = dim == 3 ? KinematicAssumption::three_dimensional :
                     dim == 2 ? KinematicAssumption::plane_strain :
                                KinematicAssumption::uniaxial_stress;
      else if (k == "three dimensional")
        kinematics = KinematicAssumption::three_dimensional;
      else if (k == "plane strain")
        kinematics = KinematicAssumption::plane_strain;
      else if (k == "plane stress")
        kinematics = KinematicAssumption::plane_stress;
      else if (k == "uniaxial strain")
        kinematics = KinematicAssumption::uniaxial_strain;
      else
        kinematics = KinematicAssumption::uniaxial_stress;
      const bool ok =
        (dim == 3 && kinematics == KinematicAssumption::three_dimensional) ||
        (dim == 2 && (kinematics == KinematicAssumption::plane_strain ||
                      kinematics == KinematicAssumption::plane_stress)) ||
        (dim == 1 && (kinematics == KinematicAssumption::uniaxial_strain ||
                      kinematics == KinematicAssumption::uniaxial_stress));
      if (!ok)
        throw InputError("Kinematic assumption = '" + k +
                         "' does not fit Dimension = " + std::to_string(dim));
      benchmark = prm.get("Benchmark");
      constants = parse_constants(prm.get("Constants"), "Constants");

      grid.parse_parameters(prm);
      time.parse_parameters(prm);
      boundary.parse_parameters(prm);
      shape_functions.parse_parameters(prm);
      output.parse_parameters(prm);
      checkpointing.parse_parameters(prm);
      load_balancing.parse_parameters(prm);
      bodies.resize(n_bodies);
      const ConstantsScope scope(constants);
      prm.enter_subsection("Bodies");
      for (unsigned int i = 0; i < n_bodies; ++i)
        {
          prm.enter_subsection(body_section(i));
          try
            {
              bodies[i].parse_parameters(prm);
            }
          catch (const InputError &e)
            {
              throw InputError("Bodies/" + body_section(i) + ": " + e.what());
            }
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    template struct Grid<1>;
    template struct Grid<2>;
    template struct Grid<3>;
    template struct Body<1>;
    template struct Body<2>;
    template struct Body<3>;
    template struct AllParameters<1>;
    template struct AllParameters<2>;
    template struct AllParameters<3>;
    template Point<1>
    parse_point<1>(const std::string &, const std::string &);
    template Point<2>
    parse_point<2>(const std::string &, const std::string &);
    template Point<3>
    parse_point<3>(const std::string &, const std::string &);
  } // namespace Parameters
} // namespace mpm
