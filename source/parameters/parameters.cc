#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/contact/multi_field_contact.h>
#include <mpm/grid/quadrilateral_mesh.h>
#include <mpm/parameters/parameters.h>
#include <mpm/parameters/parsing.h>
#include <mpm/remedies/registry.h>
#include <mpm/utilities/expression.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <cmath>
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
      prm.declare_entry("End time",
                        "1",
                        Patterns::Double(0),
                        "Simulated end time [s]. The last step is shortened "
                        "so that the run ends exactly at this time.");
      prm.declare_entry(
        "Integrator",
        "explicit",
        Patterns::Selection("explicit|quasi-static|Newmark"),
        "explicit: explicit dynamics; every entry of this subsection "
        "applies. quasi-static: every step solves the static equilibrium "
        "at the end of the step by Newton's method (subsection Implicit "
        "solver); time is a pseudo-time that ramps the loads, each step is "
        "Time step long, and the particles keep their velocity. It needs "
        "Time step control = fixed, refuses Damping coefficient, Velocity "
        "transfer = APIC and a material without shear stiffness at rest "
        "(Newtonian fluid), and does not use Scheme and FLIP fraction. "
        "Newmark: implicit dynamics, every step solves the equation of "
        "motion with the lumped nodal mass at the end of the step by "
        "Newton's method (Newmark beta and gamma). It needs Time step "
        "control = fixed, and the step is not limited by the explicit "
        "stability limit; Damping coefficient applies; Velocity transfer = "
        "APIC and a FLIP fraction below 1 are refused; Scheme is not "
        "used. Both implicit "
        "integrators refuse the locking remedies that have no "
        "linearization: Stress filter = convection correction, Volumetric "
        "smoothing = node and Filtered stress = force only.");
      prm.declare_entry("Newmark beta",
                        "0.25",
                        Patterns::Double(0, 0.5),
                        "beta of Integrator = Newmark: u_n+1 = u_n + dt v_n "
                        "+ dt^2 ((1/2 - beta) a_n + beta a_n+1). With gamma "
                        "= 1/2 and beta = 1/4 (the trapezoidal rule) "
                        "second-order accurate and without numerical "
                        "damping; unconditionally stable for beta >= "
                        "gamma / 2. A beta below Newmark gamma / 2 (only "
                        "conditionally stable) is refused.");
      prm.declare_entry("Newmark gamma",
                        "0.5",
                        Patterns::Double(0.5, 1),
                        "gamma of Integrator = Newmark: v_n+1 = v_n + dt ((1 "
                        "- gamma) a_n + gamma a_n+1); above 1/2 it damps "
                        "high frequencies (first-order accurate).");
      prm.declare_entry(
        "Scheme",
        "MUSL",
        Patterns::Selection("USF|USL|MUSL"),
        "When the explicit step updates the stress: USF "
        "(update stress first: before the internal force, "
        "with the nodal velocity of the mapped momentum), "
        "USL (update stress last: after the grid update, "
        "with the new nodal velocity), MUSL (modified USL: "
        "after the updated particle momentum has been "
        "mapped back to the grid). USL reads the grid "
        "velocity of nodes that particles barely touch at "
        "free surfaces; it then needs a CFL number of about "
        "0.1 (doc/theory/explicit_step.md). Not used by the implicit "
        "integrators.");
      prm.declare_entry(
        "Time step control",
        "CFL",
        Patterns::Selection("fixed|CFL"),
        "fixed: every step is Time step long. CFL: every step uses dt = CFL "
        "number * min_p h_p/(c_p + |v_p|), recomputed every step from the "
        "previous step's stress update (the first step from the initial "
        "state); h_p is the height of the particle's grid cell (its measure "
        "over its largest face's measure; in 1D its length), c_p the "
        "material's current wave speed and v_p the particle velocity. The "
        "implicit integrators need fixed.");
      prm.declare_entry("Time step",
                        "1e-3",
                        Patterns::Double(0),
                        "Step for Time step control = fixed [s]; must be "
                        "positive. Explicit: a step above the stability "
                        "limit min_p h_p/(c_p + |v_p|) of the initial state "
                        "is refused (the limit is not checked again during "
                        "the run). A step that would need more than 2^53 "
                        "steps to reach End time is refused.");
      prm.declare_entry("CFL number",
                        "0.5",
                        Patterns::Double(0, 1),
                        "The fraction C of the stability limit used as step "
                        "with Time step control = CFL; must be positive.");
      prm.declare_entry("FLIP fraction",
                        "1",
                        Patterns::Double(0, 1),
                        "alpha in the particle velocity update v_p <- alpha "
                        "(v_p + sum_i N_ip dv_i) + (1 - alpha) sum_i N_ip "
                        "v_i: 1 = FLIP (increment), 0 = PIC (grid "
                        "velocity), in between a blend. Must stay 1 with "
                        "Velocity transfer = APIC and with Integrator = "
                        "Newmark.");
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
        "conserved. APIC needs a Shape functions/Family other than "
        "standard (with Q1 it is unstable), and the FLIP fraction must "
        "stay 1 (unused). Refused by the implicit integrators.");
      prm.declare_entry(
        "Leapfrog start",
        "false",
        Patterns::Bool(),
        "true: the first explicit step adds half a step of acceleration to "
        "the nodal velocities, v^1/2 = v^0 + dt/2 a^0, so that every grid "
        "velocity is the one at the middle of its step, as the position "
        "update x += dt v takes it (leapfrog). A body given its steady "
        "motion at t = 0 (a spinning disk) then starts on the scheme's own "
        "steady orbit instead of vibrating with an amplitude of order dt; "
        "a body falling from rest is at the exact position at every step. "
        "The velocities and the kinetic energy written are then those of "
        "half a step before the output time. false: the first step adds a "
        "whole step. Explicit integrator only.");
      prm.declare_entry(
        "Damping coefficient",
        "0",
        Patterns::Double(0),
        "Mass-proportional damping c [1/s]: the grid force gets -c m_i v_i. "
        "Meant for reaching a static state with a small FLIP fraction: it "
        "cannot reach FLIP's particle-level velocity modes, which then do "
        "not come to rest. The explicit step multiplies the grid velocity "
        "by 1 - c dt, so c times the first step (Time step, or CFL number "
        "times the initial stability limit) above 1 is refused. With "
        "Integrator = Newmark the damping is implicit, without that limit; "
        "quasi-static refuses it.");
      prm.declare_entry("Maximum number of steps",
                        "0",
                        Patterns::Integer(0),
                        "Stop after this many steps (0: no limit). The final "
                        "state is written when the limit stops the run.");
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
      step_control   = prm.get("Time step control") == "fixed" ?
                         StepControl::fixed :
                         StepControl::cfl;
      time_step      = prm.get_double("Time step");
      cfl_number     = prm.get_double("CFL number");
      flip_fraction  = prm.get_double("FLIP fraction");
      apic           = prm.get("Velocity transfer") == "APIC";
      leapfrog_start = prm.get_bool("Leapfrog start");
      damping        = prm.get_double("Damping coefficient");
      max_steps      = prm.get_integer("Maximum number of steps");
      prm.leave_subsection();
      if (integrator == Integrator::quasi_static)
        {
          if (step_control != StepControl::fixed)
            throw InputError(
              "Time stepping/Integrator = quasi-static has no stability "
              "limit to take a CFL fraction of: set Time step control = "
              "fixed and the load step as Time step");
          if (damping != 0. || apic || leapfrog_start)
            throw InputError(
              "Time stepping/Integrator = quasi-static has no dynamics: "
              "remove Damping coefficient, Velocity transfer = APIC and "
              "Leapfrog start");
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
          if (leapfrog_start)
            throw InputError(
              "Time stepping/Leapfrog start is for the explicit integrator: "
              "Newmark's velocities and positions are already at the same "
              "time; remove the entry");
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
        "error stops the run (status 2) with a message naming the "
        "particle, its position and the step; clamp cuts GIMP boxes at the "
        "grid boundary and moves CPDI corners onto it. Use clamp when a "
        "body fills the grid up to a wall.");
      prm.declare_entry(
        "Cache stencils",
        "true",
        Patterns::Bool(),
        "GIMP, CPDI, CPDI2: build each particle's stencil (nodes, weights, "
        "weight gradients) once per step and keep it for the step's later "
        "passes (G2P, the stress update), at about 200 bytes per particle "
        "in 2D and 600 in 3D (CPDI); false builds it in every pass (less "
        "memory, slower). The results are the same to round-off. The "
        "standard family has no stencil to keep.");
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
      const std::string XYZ = dim == 1 ? "X" : dim == 2 ? "X, Y" : "X, Y, Z";
      prm.declare_entry(
        "Geometry",
        "box",
        Patterns::Selection("box|ball|quadrilateral|mesh file|none"),
        "The body mesh: box (Lower corner, Upper corner, Subdivisions), "
        "ball (Center, Radius, Refinements; a disk in 2D, a segment in 1D), "
        "quadrilateral (the subdivided unit box mapped bi/trilinearly onto "
        "the Corners), mesh file (Mesh file), or none (no particles at the "
        "start; needs an Inflow). Each body cell is split into "
        "n^dim sub-cells (n = Particles per direction), and each sub-cell "
        "becomes one particle. Every particle must lie inside the grid, "
        "and particles of one body must not lie inside another body "
        "(bodies may touch); both are input errors.");
      prm.declare_entry("Lower corner",
                        default_point(dim, 0.25),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: lower corner [m].");
      prm.declare_entry("Upper corner",
                        default_point(dim, 0.75),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: upper corner [m]; must exceed Lower corner in "
                        "every direction.");
      prm.declare_entry("Subdivisions",
                        "4",
                        Patterns::List(Patterns::Integer(1), 1, dim),
                        "Box and quadrilateral: body cells per direction "
                        "(one number for all directions, or one each).");
      prm.declare_entry(
        "Corners",
        "",
        Patterns::Anything(),
        "Quadrilateral (required there, refused for the other geometries): "
        "the 2^dim corners [m] separated by ';', counter-clockwise in 2D "
        "(Cook's membrane: 0, 0; 48, 44; 48, 60; 0, 44); in 3D the bottom "
        "face counter-clockwise, then the top face. Corners that give an "
        "inverted or degenerate cell (clockwise, not convex) are refused. "
        "Boundary ids as for a box in the corners' own directions (2D: 0 "
        "the edge from the first corner to the fourth, 1 from the second to "
        "the third, 2 from the first to the second, 3 from the third to the "
        "fourth).");
      prm.declare_entry("Center",
                        default_point(dim, 0.5),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Ball: centre [m].");
      prm.declare_entry("Radius",
                        "0.25",
                        NumberOrConstant(),
                        "Ball: radius [m], positive (a number or an "
                        "expression of the Constants).");
      prm.declare_entry(
        "Refinements",
        "2",
        Patterns::Integer(0, 10),
        "Ball: global refinements of the coarse ball mesh (12 cells in 2D, "
        "32 in 3D; in 1D the segment is split into 2^(Refinements + 1) "
        "cells). The cells are straight-sided, so the particles fill the "
        "inscribed polygon or polyhedron. Boundary id 0 on the whole "
        "surface (1D: 0 at the left end, 1 at the right end).");
      prm.declare_entry(
        "Mesh file",
        "",
        Patterns::FileName(),
        "Mesh file (required there): the body mesh, Gmsh .msh or UCD "
        ".inp/.ucd, looked up and checked like Grid/Mesh file. Its boundary "
        "ids are those of the file.");
      prm.declare_entry("Particles per direction",
                        "2",
                        Patterns::Integer(1, 10),
                        "n: each body cell gives n^dim particles.");
      prm.declare_entry("Initial velocity",
                        default_expression(dim),
                        Patterns::Anything(),
                        "Velocity at t = 0 [m/s]: dim expressions of the "
                        "initial position " +
                          xyz + " and the Constants, separated by ';'.");
      prm.declare_entry(
        "Initial stress",
        dim == 1 ? "0" :
        dim == 2 ? "0; 0; 0" :
                   "0; 0; 0; 0; 0; 0",
        Patterns::Anything(),
        std::string("Cauchy stress at t = 0 [Pa], tension positive: "
                    "expressions of the initial position ") +
          xyz + " and the Constants, separated by ';': " +
          (dim == 1 ? "xx" :
           dim == 2 ? "xx; yy; xy, and optionally a fourth, zz (without it "
                      "zz starts at 0)" :
                      "xx; yy; zz; yz; xz; xy") +
          ".");
      prm.declare_entry(
        "Body force",
        default_expression(dim),
        Patterns::Anything(),
        "Body force per unit mass [m/s^2], e.g. gravity " +
          std::string(dim == 1 ? "-9.81" :
                      dim == 2 ? "0; -9.81" :
                                 "0; 0; -9.81") +
          ": dim expressions of the current position " + xyz +
          ", the material coordinates " + XYZ +
          " (the initial position), the time t and the Constants, "
          "separated by ';', evaluated at each particle at the start of "
          "each step.");
      prm.declare_entry(
        "Traction",
        default_expression(dim),
        Patterns::Anything(),
        "Surface traction [Pa; in 2D per unit thickness, in 1D per unit "
        "cross-section] on the body-mesh boundaries listed in Traction "
        "boundary ids; same variables as Body force. Each particle next to "
        "a loaded face carries the area of its part of the face and "
        "applies the traction there, evaluated at the face. A dead load: "
        "the area is that of the initial configuration and the traction "
        "does not follow the surface normal.");
      prm.declare_entry("Traction boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
                        "Boundary ids of the body mesh (not of the grid) "
                        "that carry the Traction: box 0/1 x min/max, 2/3 y, "
                        "4/5 z; ball, quadrilateral and mesh file as their "
                        "entries say.");
      prm.declare_entry(
        "Prescribed velocity",
        "",
        Patterns::Anything(),
        "Empty: the body moves with the grid. Otherwise the body is rigid "
        "and moves with this velocity [m/s], dim expressions of t "
        "separated by ';'; it needs Material/Model = rigid, and Time "
        "stepping/Integrator = quasi-static or Newmark, or a Contact law. "
        "Quasi-static and Newmark: the grid nodes it reaches follow its "
        "displacement over each step: in the Prescribed directions where "
        "they also carry another body, in every direction where they do "
        "not (Newmark: their inertia is the other bodies' mass alone); its "
        "reaction is written to the statistics file (reaction_x, ...). With a "
        "Contact law it is a velocity field of its own, which the other "
        "fields meet by the law as if its mass were infinite. A wall's "
        "constraint wins over the body's.");
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
      prm.declare_entry(
        "Contact field",
        "-1",
        Patterns::Integer(-1, 255),
        "The velocity field of the body when Contact/Contact law is not "
        "none: bodies with the same number share a field (and stick where "
        "they meet), bodies of different fields meet by the contact law. "
        "-1: a field of the body's own.");
      prm.declare_entry(
        "Contact normal",
        "",
        Patterns::Anything(),
        "A rigid body's outward surface normal where other fields meet it "
        "(dim numbers or expressions of the Constants, separated by ';'; "
        "normalized), for a flat obstacle that is not aligned with the "
        "grid: the normal from the body's mass gradient follows the cells "
        "its surface crosses, and a body sliding on it catches on the "
        "steps. Empty: the mass gradient's normal.");
      prm.enter_subsection("Material");
      materials::declare_material_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Locking remedies");
      remedies::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Inflow");
      InflowParameters<dim>::declare_parameters(prm);
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
                            g == "none"          ? Geometry::none :
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
      contact_field           = prm.get_integer("Contact field");
      contact_normal.clear();
      if (!prm.get("Contact normal").empty())
        {
          contact_normal = get_numbers(prm, "Contact normal", dim);
          double norm    = 0;
          for (const double c : contact_normal)
            norm += c * c;
          norm = std::sqrt(norm);
          if (!(norm > 0))
            throw InputError("Contact normal = " + prm.get("Contact normal") +
                             " must not be zero");
          for (double &c : contact_normal)
            c /= norm;
        }
      prescribed_directions = 0;
      for (const auto &d :
           Utilities::split_string_list(prm.get("Prescribed directions")))
        prescribed_directions |= 1u << (d[0] - 'x');
      prm.enter_subsection("Locking remedies");
      locking_remedies = remedies::parse_selection(prm);
      prm.leave_subsection();
      prm.enter_subsection("Inflow");
      inflow.parse_parameters(prm);
      prm.leave_subsection();
      if (geometry == Geometry::none && !inflow.enabled)
        throw InputError("Geometry = none gives the body no particles: it "
                         "needs Inflow/Enabled = true");
      if (inflow.enabled && !prescribed_velocity.empty())
        throw InputError("Inflow/Enabled = true: a rigid body (Prescribed "
                         "velocity) cannot have an inflow");
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
                        "directory (or absolute); must not be empty. It is "
                        "created if missing, only after the whole input has "
                        "been checked. Files of the same name are "
                        "overwritten, other files are left alone. The "
                        "statistics file and parameters.prm are always "
                        "written.");
      prm.declare_entry("Interval",
                        "0.1",
                        Patterns::Double(0),
                        "Simulated time between outputs [s]; 0: every "
                        "step. The initial and the final state are always "
                        "written; otherwise an output is written at the end "
                        "of every step that reaches or passes the next "
                        "multiple of Interval (one output however many "
                        "multiples a step passes), so output times are "
                        "step times.");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "ParaView files of the particles with all their "
                        "properties (particles.pvd, particles_NNNNN.pvtu "
                        "and its .vtu pieces), and of the grid if Write "
                        "grid.");
      prm.declare_entry("Write grid",
                        "true",
                        Patterns::Bool(),
                        "Also write the background grid fields (nodal "
                        "mass, nodal velocity, the MPI rank of each cell, "
                        "and with contact the nodal contact force: "
                        "grid.pvd) when Write vtu is on.");
      prm.declare_entry("Write csv",
                        "true",
                        Patterns::Bool(),
                        "Particle table particles-NNNNN.csv, sorted by id, "
                        "with every particle property (gathered on rank "
                        "0); with contact also contact-NNNNN.csv, the "
                        "nodes where the contact law acted in the last "
                        "step with their contact force.");
      prm.declare_entry("Test summary file",
                        "",
                        Patterns::FileName(),
                        "If set, a short summary for regression tests is "
                        "written to this file (relative to the working "
                        "directory) at the end of a successful run: one "
                        "line per output with 7 significant digits.");
      prm.declare_entry("Progress interval",
                        "10",
                        Patterns::Double(0),
                        "Wall-clock seconds between progress lines on the "
                        "screen (one more is printed at the end).");
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
        "whose work is known; the header line output: says whether the "
        "balance is watched.");
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
                        "a multiple of this (0: not by step count), after "
                        "the output of that step. The checkpoints are kept "
                        "in Output/Directory/checkpoint/; the two latest "
                        "complete ones are kept, so a run killed while it "
                        "writes one can resume from the previous one.");
      prm.declare_entry("Wall time between checkpoints",
                        "0",
                        Patterns::Double(0),
                        "Also write a checkpoint when this many wall-clock "
                        "seconds have passed since the last one (or the "
                        "start; 0: not by wall-clock time). Rank 0's clock "
                        "decides.");
      prm.declare_entry(
        "Resume computation",
        "false",
        Patterns::Selection("false|true|auto"),
        "true: continue from the latest checkpoint in "
        "Output/Directory/checkpoint/ (an input error if there is none); "
        "auto: continue if there is one, else start from the initial state "
        "(one command for every job of a chain of batch jobs); false: start "
        "from the initial state. The command-line option --resume sets "
        "true. A restart refuses, before writing anything, a parameter that "
        "differs from the checkpoint's, except those of Output, "
        "Checkpointing and Load balancing, Time stepping/End time and "
        "Maximum number of steps (raise End time to extend a run), and a "
        "changed grid mesh file. In 2D and 3D the number of MPI ranks may "
        "change.");
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
                        "Space dimension of the model: 1, 2 or 3. Read in a "
                        "first pass before the rest of the file (it decides "
                        "how many components points and vectors have), so "
                        "it must be set at top level, in the file or in a "
                        "file it includes. Dimension 1 runs on one MPI rank "
                        "only.");
      prm.declare_entry("Number of bodies",
                        "1",
                        Patterns::Integer(1, 100),
                        "Number of bodies, each described by its own "
                        "subsection Bodies/Body i (i = 0, 1, ..., N-1). A "
                        "missing Body i, or one with i >= N, is an input "
                        "error. Read in the first pass, like Dimension.");
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
        "How the model is embedded in 3D. 3D: three dimensional. 2D: plane "
        "strain (eps_zz = 0, sigma_zz follows) or plane stress (sigma_zz = "
        "sigma_xz = sigma_yz = 0). 1D: uniaxial stress (only sigma_xx is "
        "non-zero: a thin bar) or uniaxial strain (only eps_xx is non-zero, "
        "the lateral stresses follow). Any other combination is refused. "
        "default: three dimensional in 3D, plane strain in 2D, uniaxial "
        "stress in 1D. Plane stress and uniaxial stress need Model = linear "
        "elastic (or rigid); the other models refuse them, so a 1D case "
        "with them needs uniaxial strain.");
      prm.declare_entry(
        "Constants",
        "",
        Patterns::Anything(),
        "Named constants, comma-separated name=value pairs with plain "
        "numbers as values, e.g. 'v0=0.1, L=25'. Every expression can use "
        "them, and so can the entries that take a number or an expression "
        "of the Constants (the material numbers, Radius). Benchmarks read "
        "their physical parameters from here too. A pair that is not "
        "name=value, a value that is not a number, and a constant named x, "
        "y, z or t (variables of the expressions) are refused.");
      prm.declare_entry("Benchmark",
                        "none",
                        Patterns::Selection(
                          benchmarks::benchmark_names_pattern()),
                        "Name of a benchmark whose error measures are added "
                        "as columns of the statistics file, or none. A "
                        "benchmark in a dimension it does not support, or "
                        "without a constant it needs, is an input error. "
                        "Each reads its constants from Constants:" +
                          benchmarks::benchmark_list());
      prm.declare_entry(
        "Memory limit",
        "0",
        Patterns::Double(0),
        "Memory the case may use over all ranks [GB, 10^9 bytes]. Before "
        "anything is allocated, the grid cells and particles are counted "
        "from the parameters and their memory estimated from below "
        "(--validate prints the estimate); a case that needs more is "
        "refused, naming the entries that set the counts. 0: the memory "
        "available on the machines the ranks run on (MemAvailable, or a "
        "container's limit if smaller). A grid or body with more than "
        "2^32 - 1 cells is refused whatever the limit.");
      Grid<dim>::declare_parameters(prm);
      TimeStepping::declare_parameters(prm);
      BoundaryConditions::declare_parameters(prm);
      ShapeFunctions::declare_parameters(prm);
      Output::declare_parameters(prm);
      Checkpointing::declare_parameters(prm);
      LoadBalancing::declare_parameters(prm);
      ImplicitSolver::declare_parameters(prm);
      Contact::declare_parameters(prm);
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
      if (!boundary.moving.empty() &&
          time.integrator == TimeStepping::Integrator::explicit_dynamics)
        throw InputError(
          "Boundary conditions/Moving boundary ids: a moving grid boundary "
          "needs Time stepping/Integrator = quasi-static or Newmark (the "
          "explicit integrator has no prescribed grid motion yet)");
      shape_functions.parse_parameters(prm);
      output.parse_parameters(prm);
      checkpointing.parse_parameters(prm);
      load_balancing.parse_parameters(prm);
      implicit.parse_parameters(prm);
      if (implicit.fixed_geometry &&
          time.integrator == TimeStepping::Integrator::explicit_dynamics)
        throw InputError(
          std::string("Implicit solver/Geometry = ") +
          (implicit.small_strain ? "small strain" : "fixed") +
          " needs Time stepping/Integrator = quasi-static or Newmark (the "
          "explicit step always moves the particles)");
      bodies.resize(n_bodies);
      const ConstantsScope scope(constants);
      contact.parse_parameters(prm);
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
      contact::check_parameters(*this);
    }

    template struct Body<1>;
    template struct Body<2>;
    template struct Body<3>;
    template struct AllParameters<1>;
    template struct AllParameters<2>;
    template struct AllParameters<3>;
  } // namespace Parameters
} // namespace mpm
