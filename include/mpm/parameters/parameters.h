#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <mpm/contact/contact_parameters.h>
#include <mpm/grid/grid_parameters.h>
#include <mpm/integrators/implicit_parameters.h>
#include <mpm/materials/material.h>
#include <mpm/particles/inflow_parameters.h>
#include <mpm/remedies/selection.h>
#include <mpm/shape_functions/family.h>

#include <map>
#include <set>
#include <string>
#include <vector>

/**
 * The parameter file, one struct per subsection. Each struct declares its
 * entries (with documentation and defaults) and reads them back. The
 * documentation strings are the parameter reference of the manual
 * (generated from `mpm --print-parameters DIM json`); doc/parameter_file.md
 * describes the file format. The grid's subsections are in
 * grid/grid_parameters.h.
 */
namespace mpm
{
  namespace Parameters
  {
    /// Time integration and the choice of the update scheme.
    struct TimeStepping
    {
      /// More steps than this to the end (2^53): t + dt = t in double
      /// precision before the end; refused for a fixed step, stops a run
      /// whose adaptive step has become that small.
      static constexpr double max_steps_to_end = 9007199254740992.;

      enum class Scheme
      {
        usf,
        usl,
        musl
      };
      enum class StepControl
      {
        fixed,
        cfl
      };
      /// explicit dynamics, Newton's method on the quasi-static
      /// equilibrium of every step (load steps in pseudo-time), or on
      /// Newmark's implicit equation of motion
      enum class Integrator
      {
        explicit_dynamics,
        quasi_static,
        newmark
      };
      Integrator  integrator    = Integrator::explicit_dynamics;
      Scheme      scheme        = Scheme::musl;
      StepControl step_control  = StepControl::cfl;
      double      end_time      = 1.0;
      double      time_step     = 1e-3;
      double      cfl_number    = 0.5;
      double      flip_fraction = 1.0;
      bool        apic          = false; ///< affine velocity transfer
      /// first explicit step adds dt/2 of acceleration (leapfrog)
      bool         leapfrog_start = false;
      double       damping        = 0.0;
      unsigned int max_steps      = 0;
      double       newmark_beta   = 0.25;
      double       newmark_gamma  = 0.5;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// The shape-function family of the transfers
    /// (doc/theory/grid_and_shape_functions.md).
    struct ShapeFunctions
    {
      shape_functions::Family family = shape_functions::Family::standard;
      bool                    clamp  = false; ///< domains cut at the grid
      /// Keep each step's domain stencils for the later passes of the step
      bool cache_stencils = true;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// One body: its geometry, particles, material and initial state.
    template <int dim>
    struct Body
    {
      enum class Geometry
      {
        box,
        ball,
        quadrilateral, ///< the subdivided unit box mapped onto 2^dim corners
        mesh_file,
        none ///< no particles at the start (an Inflow brings them)
      };
      Geometry                        geometry = Geometry::box;
      dealii::Point<dim>              lower, upper;
      std::vector<unsigned int>       subdivisions;
      std::vector<dealii::Point<dim>> corners; ///< deal.II vertex order
      dealii::Point<dim>              center;
      double                          radius      = 1.0;
      unsigned int                    refinements = 2;
      std::string                     mesh_file;
      unsigned int                    particles_per_direction = 2;

      std::string initial_velocity; // muparser, dim components
      std::string initial_stress;   // muparser, Voigt components
      std::string body_force;       // muparser of x, X and t
      std::string traction;         // muparser of x, X and t
      std::vector<dealii::types::boundary_id> traction_boundary_ids;
      /// muparser of t, dim components; empty: the body moves freely
      std::string prescribed_velocity;
      /// the directions the body imposes on the nodes it shares with
      /// others (bit d: direction d)
      unsigned int prescribed_directions = 0;
      /// the velocity field of the body (subsection Contact); -1: its own
      int contact_field = -1;
      /// a rigid body's outward surface normal for contact (dim numbers);
      /// empty: from the mass gradients
      std::vector<double> contact_normal;

      /// The locking remedies of this body, with their settings
      /// (subsection Locking remedies; remedies/registry.h).
      remedies::Selection locking_remedies;
      /// The inlet that adds particles of the body (subsection Inflow).
      InflowParameters<dim> inflow;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Where and how often results are written.
    struct Output
    {
      std::string directory  = "output";
      double      interval   = 0.1;
      bool        write_vtu  = true;
      bool        write_csv  = true;
      bool        write_grid = true;
      std::string test_summary;
      double      progress_interval = 10.0;
      /// The energy balance at every output (solver/energy_watch.h).
      enum class EnergyCheck
      {
        none,
        warn,
        stop
      };
      EnergyCheck energy_check     = EnergyCheck::warn;
      double      energy_tolerance = 0.1;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Periodic checkpoints and resuming from them (doc/checkpointing.md).
    struct Checkpointing
    {
      enum class Resume
      {
        no,       ///< start from the initial state
        yes,      ///< continue from the latest checkpoint; refuse if none
        automatic ///< continue if a checkpoint exists, else start
      };
      unsigned int steps_between = 0; ///< 0: not by step count
      double       wall_seconds  = 0; ///< 0: not by wall-clock time
      Resume       resume        = Resume::no;
      /// A damaged latest checkpoint: resume from the previous one (else
      /// refuse)
      bool fall_back_to_previous = false;

      bool
      enabled() const
      {
        return steps_between > 0 || wall_seconds > 0;
      }

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Everything in one place, read from one file.
    template <int dim>
    struct AllParameters
    {
      std::string            file_name;
      unsigned int           n_bodies   = 1;
      KinematicAssumption    kinematics = KinematicAssumption::plane_strain;
      Grid<dim>              grid;
      TimeStepping           time;
      BoundaryConditions     boundary;
      ShapeFunctions         shape_functions;
      std::vector<Body<dim>> bodies;
      Output                 output;
      Checkpointing          checkpointing;
      LoadBalancing          load_balancing;
      ImplicitSolver         implicit;
      Contact                contact;
      std::string            benchmark = "none";
      std::map<std::string, double> constants;
      /// Memory the case may use [GB]; 0: what the machines have
      /// (solver/resource_estimate.h).
      double memory_limit = 0;

      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const unsigned int        n_bodies);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Section name of body i ("Body 0", "Body 1", ...).
    std::string
    body_section(const unsigned int i);

    /**
     * Read `Dimension` and `Number of bodies` from a parameter file without
     * declaring the rest, so that the full set can then be declared.
     */
    struct Preamble
    {
      unsigned int dimension = 2;
      unsigned int n_bodies  = 1;
      /// the i of every `subsection Body i` inside `subsection Bodies`
      std::set<unsigned int> described_bodies;

      /// An InputError unless Body 0 ... Body n_bodies-1 are all
      /// described: an undescribed body would silently be the default
      /// body, on top of any other default one.
      void
      require_every_body_described(const std::string &file_name) const;
    };
    Preamble
    read_preamble(const std::string &file_name);

    /// Declare the two preamble entries (also part of the full set).
    void
    declare_preamble(dealii::ParameterHandler &prm);

    /**
     * Parse a parameter file with all entries declared; every failure
     * (unknown entry, bad value, missing file) becomes an InputError that
     * names the file and, where deal.II reports it, the line.
     */
    void
    parse_file(dealii::ParameterHandler &prm, const std::string &file_name);
  } // namespace Parameters
} // namespace mpm
