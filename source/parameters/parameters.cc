#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/grid/quadrilateral_mesh.h>
#include <mpm/parameters/parameters.h>
#include <mpm/parameters/parsing.h>
#include <mpm/remedies/registry.h>
#include <mpm/utilities/expression.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace mpm
{
  namespace Parameters
  {
    using namespace dealii;

    std::string
    body_section(const unsigned int i)
    {
      return "Body " + std::to_string(i);
    }

    // ---------------------------------------------------------- TimeStepping
    void
    TimeStepping::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      prm.declare_entry("End time", "1", Patterns::Double(0), "End time [s].");
      prm.declare_entry(
        "Integrator",
        "explicit",
        Patterns::Selection("explicit|quasi-static|Newmark"),
        "explicit: explicit dynamics (the scheme, step control, FLIP "
        "and damping entries below). quasi-static: every step solves "
        "the static equilibrium at the end of the step by Newton's method "
        "(subsection Implicit solver); time is a pseudo-time that ramps "
        "the loads, the step is Time step (Time step control = fixed), "
        "and the particles keep their velocity. Newmark: implicit "
        "dynamics, every step solves the equation of motion with the "
        "lumped nodal mass at the end of the step by Newton's method "
        "(Newmark beta and gamma; the step is Time step, without a "
        "stability limit).");
      prm.declare_entry("Newmark beta",
                        "0.25",
                        Patterns::Double(0, 0.5),
                        "beta of Integrator = Newmark: u_n+1 = u_n + dt v_n "
                        "+ dt^2 ((1/2 - beta) a_n + beta a_n+1). With gamma "
                        "= 1/2 and beta = 1/4 (the trapezoidal rule) "
                        "second-order accurate and without numerical "
                        "damping; unconditionally stable for beta >= "
                        "gamma / 2.");
      prm.declare_entry("Newmark gamma",
                        "0.5",
                        Patterns::Double(0.5, 1),
                        "gamma of Integrator = Newmark: v_n+1 = v_n + dt ((1 "
                        "- gamma) a_n + gamma a_n+1); above 1/2 it damps "
                        "high frequencies (first-order accurate).");
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
      end_time                          = prm.get_double("End time");
      const std::string integrator_name = prm.get("Integrator");
      integrator                        = integrator_name == "quasi-static" ?
                                            Integrator::quasi_static :
                                          integrator_name == "Newmark" ? Integrator::newmark :
                                                                         Integrator::explicit_dynamics;
      newmark_beta                      = prm.get_double("Newmark beta");
      newmark_gamma                     = prm.get_double("Newmark gamma");
      const std::string s               = prm.get("Scheme");
      scheme                            = s == "USF" ? Scheme::usf :
                                          s == "USL" ? Scheme::usl :
                                                       Scheme::musl;
      step_control  = prm.get("Time step control") == "fixed" ?
                        StepControl::fixed :
                        StepControl::cfl;
      time_step     = prm.get_double("Time step");
      cfl_number    = prm.get_double("CFL number");
      flip_fraction = prm.get_double("FLIP fraction");
      apic          = prm.get("Velocity transfer") == "APIC";
      damping       = prm.get_double("Damping coefficient");
      max_steps     = prm.get_integer("Maximum number of steps");
      prm.leave_subsection();
      if (integrator == Integrator::quasi_static)
        {
          if (step_control != StepControl::fixed)
            throw InputError(
              "Time stepping/Integrator = quasi-static has no stability "
              "limit to take a CFL fraction of: set Time step control = "
              "fixed and the load step as Time step");
          if (damping != 0. || apic)
            throw InputError(
              "Time stepping/Integrator = quasi-static has no dynamics: "
              "remove Damping coefficient and Velocity transfer = APIC");
        }
      if (integrator == Integrator::newmark)
        {
          if (step_control != StepControl::fixed)
            throw InputError(
              "Time stepping/Integrator = Newmark has no stability limit to "
              "take a CFL fraction of: set Time step control = fixed and "
              "the step as Time step");
          if (apic || flip_fraction != 1.)
            throw InputError(
              "Time stepping/Integrator = Newmark updates the particle "
              "velocity by the Newmark velocity change at the nodes (FLIP): "
              "remove Velocity transfer = APIC and FLIP fraction");
          if (newmark_beta < newmark_gamma / 2)
            throw InputError(
              "Time stepping/Newmark beta = " + std::to_string(newmark_beta) +
              " is below Newmark gamma / 2 = " +
              std::to_string(newmark_gamma / 2) +
              ": the scheme would be only conditionally stable; use beta "
              ">= gamma / 2 (beta = 1/4, gamma = 1/2: the trapezoidal rule)");
        }
      if (step_control == StepControl::fixed && !(time_step > 0))
        throw InputError("Time stepping/Time step must be positive");
      // beyond 2^53 steps t + dt = t before the end: the run would never end
      if (step_control == StepControl::fixed &&
          end_time / time_step > max_steps_to_end)
        {
          std::ostringstream msg;
          msg << "Time stepping/Time step = " << time_step << " would need "
              << end_time / time_step
              << " steps to reach End time = " << end_time
              << " (more than 2^53: the time would stop advancing in double "
                 "precision); choose a larger step or a shorter run";
          throw InputError(msg.str());
        }
      if (step_control == StepControl::cfl && !(cfl_number > 0))
        throw InputError("Time stepping/CFL number must be positive");
      if (apic && flip_fraction != 1.)
        throw InputError(
          "Time stepping/FLIP fraction = " + std::to_string(flip_fraction) +
          " has no meaning with Velocity transfer = APIC (its particle "
          "velocity is the grid velocity; the affine part keeps what PIC "
          "loses): remove the entry");
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
      prm.declare_entry(
        "Prescribed velocity",
        "",
        Patterns::Anything(),
        "Empty: the body moves with the grid. Otherwise the body is rigid "
        "(Material/Model = rigid) and moves with this velocity [m/s], dim "
        "expressions of t separated by ';': the nodes it reaches follow "
        "it, in the Prescribed directions where they also carry another "
        "body, in every direction elsewhere (Integrator = quasi-static).");
      prm.declare_entry(
        "Prescribed directions",
        dim == 1 ? "x" :
        dim == 2 ? "x, y" :
                   "x, y, z",
        Patterns::List(Patterns::Selection(dim == 1 ? "x" :
                                           dim == 2 ? "x|y" :
                                                      "x|y|z")),
        "The directions in which a rigid body (Prescribed velocity) "
        "moves the nodes it shares with another body: all for a rough "
        "contact, the normal one for a smooth one (a smooth footing "
        "pressed down in y: y).");
      prm.enter_subsection("Material");
      materials::declare_material_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Locking remedies");
      remedies::declare_parameters(prm);
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
      prescribed_velocity     = prm.get("Prescribed velocity");
      prescribed_directions   = 0;
      for (const auto &d :
           Utilities::split_string_list(prm.get("Prescribed directions")))
        prescribed_directions |= 1u << (d[0] - 'x');
      prm.enter_subsection("Locking remedies");
      locking_remedies = remedies::parse_selection(prm);
      prm.leave_subsection();
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
      prm.declare_entry(
        "Energy balance check",
        "warn",
        Patterns::Selection("none|warn|stop"),
        "At every output, kinetic + strain energy less the work of the "
        "loads since the start (or the resume) is compared with its first "
        "value: walls, damping, plasticity, viscosity and PIC only take "
        "energy out, so growth means the scheme creates energy. warn: one "
        "warning naming the step; stop: a runtime error (status 2). Only "
        "with constant body forces and tractions and no prescribed motion, "
        "whose work is known.");
      prm.declare_entry("Energy balance tolerance",
                        "0.1",
                        Patterns::Double(0),
                        "Growth of the balance that is reported, as a "
                        "fraction of the largest kinetic + strain energy or "
                        "load work seen.");
      prm.leave_subsection();
    }

    void
    Output::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory               = prm.get("Directory");
      interval                = prm.get_double("Interval");
      write_vtu               = prm.get_bool("Write vtu");
      write_grid              = prm.get_bool("Write grid");
      write_csv               = prm.get_bool("Write csv");
      test_summary            = prm.get("Test summary file");
      progress_interval       = prm.get_double("Progress interval");
      const std::string check = prm.get("Energy balance check");
      energy_check            = check == "none" ? EnergyCheck::none :
                                check == "stop" ? EnergyCheck::stop :
                                                  EnergyCheck::warn;
      energy_tolerance        = prm.get_double("Energy balance tolerance");
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
                        "the two latest complete ones are kept.");
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
      prm.declare_entry("Damaged checkpoint",
                        "stop",
                        Patterns::Selection("stop|use previous"),
                        "A restart first checks every file of the latest "
                        "checkpoint against the size and CRC-32 written "
                        "with it. stop: a missing or damaged file is an "
                        "input error naming it; use previous: the restart "
                        "continues from the previous complete checkpoint "
                        "instead (the two latest are kept), and says so.");
      prm.leave_subsection();
    }

    void
    Checkpointing::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpointing");
      steps_between         = prm.get_integer("Steps between checkpoints");
      wall_seconds          = prm.get_double("Wall time between checkpoints");
      const std::string r   = prm.get("Resume computation");
      resume                = r == "true" ? Resume::yes :
                              r == "auto" ? Resume::automatic :
                                            Resume::no;
      fall_back_to_previous = prm.get("Damaged checkpoint") == "use previous";
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
        // a directory opens like an empty file: the defaults would run
        std::error_code error;
        if (fs::is_directory(file_name, error))
          throw InputError("The parameter file '" + file_name +
                           "' is a directory, not a file");
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
            // a NUL would cut every message that quotes the line
            if (text.find('\0') != std::string::npos)
              throw InputError("line " + std::to_string(n) + " of '" +
                               file_name +
                               "' contains a NUL byte (a binary file?)");
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
                std::error_code error;
                if (fs::is_directory(path, error))
                  throw InputError("line " + std::to_string(n) + " of '" +
                                   file_name + "': the included file '" + name +
                                   "' is a directory (" + path.string() +
                                   "), not a file");
                expand_includes(path.string(), out, depth + 1);
              }
            else
              out.push_back({text, file_name, n});
          }
      }

      /// Parse the expanded file; errors name the original file and line.
      /// Returns the expanded lines.
      std::vector<SourceLine>
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
        return lines;
      }

      /// The i of every `subsection Body i` inside `subsection Bodies`.
      std::set<unsigned int>
      described_bodies(const std::vector<SourceLine> &lines)
      {
        std::set<unsigned int>   found;
        std::vector<std::string> path;
        for (const auto &l : lines)
          {
            std::istringstream words(l.text.substr(0, l.text.find('#')));
            std::string        keyword, name, word;
            words >> keyword;
            if (keyword == "end" && !path.empty())
              path.pop_back();
            else if (keyword == "subsection")
              {
                // deal.II reads the name with single spaces
                while (words >> word)
                  name += (name.empty() ? "" : " ") + word;
                path.push_back(name);
                if (path.size() == 2 && path[0] == "Bodies" &&
                    name.compare(0, 5, "Body ") == 0)
                  try
                    {
                      found.insert(std::stoul(name.substr(5)));
                    }
                  catch (...)
                    {
                      // not a number: deal.II names the unknown section
                    }
              }
          }
        return found;
      }
    } // namespace

    Preamble
    read_preamble(const std::string &file_name)
    {
      ParameterHandler        prm;
      std::vector<SourceLine> lines;
      declare_preamble(prm);
      try
        {
          lines = parse_expanded(prm, file_name, /*skip_undefined=*/true);
        }
      catch (const InputError &e)
        {
          throw InputError("Error reading the parameter file '" + file_name +
                           "': " + e.what());
        }
      Preamble preamble;
      preamble.dimension        = prm.get_integer("Dimension");
      preamble.n_bodies         = prm.get_integer("Number of bodies");
      preamble.described_bodies = described_bodies(lines);
      return preamble;
    }

    void
    Preamble::require_every_body_described(const std::string &file_name) const
    {
      for (unsigned int i = 0; i < n_bodies; ++i)
        if (described_bodies.count(i) == 0)
          throw InputError(
            "Error in the parameter file '" + file_name +
            "': Number of bodies = " + std::to_string(n_bodies) +
            ", but there is no subsection Bodies/" + body_section(i) +
            " (bodies are numbered from 0; a body without its subsection "
            "would be the default body)");
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
                        Patterns::Selection(
                          benchmarks::benchmark_names_pattern()),
                        "Name of a benchmark whose error measures are added "
                        "to the statistics file (see doc/benchmarks.md), or "
                        "none. Each reads its constants from Constants:" +
                          benchmarks::benchmark_list());
      prm.declare_entry(
        "Memory limit",
        "0",
        Patterns::Double(0),
        "Memory the case may use over all ranks [GB]. Before anything is "
        "allocated, the grid cells and particles are counted and their "
        "memory estimated from below (--validate prints the estimate); a "
        "case that needs more is refused. 0: the memory available on the "
        "machines the ranks run on (MemAvailable, or a container's limit).");
      Grid<dim>::declare_parameters(prm);
      TimeStepping::declare_parameters(prm);
      BoundaryConditions::declare_parameters(prm);
      ShapeFunctions::declare_parameters(prm);
      Output::declare_parameters(prm);
      Checkpointing::declare_parameters(prm);
      LoadBalancing::declare_parameters(prm);
      ImplicitSolver::declare_parameters(prm);
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
      benchmark    = prm.get("Benchmark");
      memory_limit = prm.get_double("Memory limit");
      constants    = parse_constants(prm.get("Constants"), "Constants");

      grid.parse_parameters(prm);
      time.parse_parameters(prm);
      boundary.parse_parameters(prm);
      shape_functions.parse_parameters(prm);
      output.parse_parameters(prm);
      checkpointing.parse_parameters(prm);
      load_balancing.parse_parameters(prm);
      implicit.parse_parameters(prm);
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

    template struct Body<1>;
    template struct Body<2>;
    template struct Body<3>;
    template struct AllParameters<1>;
    template struct AllParameters<2>;
    template struct AllParameters<3>;
  } // namespace Parameters
} // namespace mpm
