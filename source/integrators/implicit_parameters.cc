#include <deal.II/base/utilities.h>

#include <mpm/integrators/implicit_parameters.h>
#include <mpm/utilities/input_error.h>

#include <string>

namespace mpm
{
  namespace Parameters
  {
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::List;
    using dealii::Patterns::Selection;

    void
    ImplicitSolver::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Implicit solver");
      prm.declare_entry("Residual tolerance",
                        "1e-8",
                        Double(0),
                        "Newton has converged when the residual's norm "
                        "(free degrees of freedom) is at most this times the "
                        "larger of the norms of the external and of the "
                        "internal force (the internal force includes the "
                        "reactions at fixed and slip nodes), and the energy "
                        "criterion holds. Like every entry of this "
                        "subsection, used by Integrator = quasi-static and "
                        "Newmark only.");
      prm.declare_entry("Absolute residual tolerance",
                        "1e-12",
                        Double(0),
                        "A residual norm [N] at or below this is converged "
                        "whatever the forces (an unloaded step).");
      prm.declare_entry("Energy tolerance",
                        "1e-12",
                        Double(0),
                        "Energy criterion: |du . R| of the last increment at "
                        "most this times that of the first iteration (an "
                        "increment that is the first of its step leaves the "
                        "residual criterion to decide).");
      prm.declare_entry("Maximum Newton iterations",
                        "20",
                        Integer(1),
                        "Iterations before the step is cut in half.");
      prm.declare_entry("Line search",
                        "true",
                        Bool(),
                        "Backtracking on the residual norm: the increment "
                        "is halved (at most 6 times) until the residual "
                        "decreases.");
      prm.declare_entry("Maximum step cuts",
                        "6",
                        Integer(0),
                        "How often a step whose Newton iteration fails may "
                        "be halved. Each half grows back to the full step "
                        "once Newton converges in at most 4 iterations. When "
                        "the last cut fails, the run stops (status 2) with "
                        "the residual history in the message.");
      prm.declare_entry(
        "Linear solver",
        "automatic",
        Selection("automatic|CG|GMRES|direct"),
        "CG or GMRES(100) preconditioned by ML algebraic multigrid with the "
        "rigid-body modes as near-null space, or the Direct solver. "
        "automatic: the direct solver for a solve of at most Automatic "
        "direct limit unknowns, else CG if the tangent is symmetric (every "
        "material hyperelastic, no volumetric smoothing and no stress "
        "filter) and GMRES if not; linear elastic's tangent is not "
        "symmetric (Hughes-Winget rotation). CG with a non-symmetric "
        "tangent is refused.");
      prm.declare_entry(
        "Direct solver",
        "MUMPS",
        Selection("MUMPS|KLU"),
        "The sparse direct solver (through Trilinos Amesos) of Linear "
        "solver = direct and of automatic's small solves. Either factorises "
        "on one process, the matrix gathered there, so that a run repeats "
        "itself bit for bit on any number of ranks. MUMPS: multifrontal. "
        "KLU: slower on grid matrices (doc/guide/implicit.md).");
      prm.declare_entry(
        "Automatic direct limit",
        "100000000, 500000, 20000",
        List(Integer(0), 3, 3),
        "Linear solver = automatic: the largest number of unknowns (over "
        "all ranks) a solve may have to go to the Direct solver, in 1D, "
        "2D and 3D; larger solves take AMG with CG or GMRES, and so does "
        "every solve with 0. With Preconditioner = AMG with cell pressure "
        "automatic is always iterative. The defaults are where MUMPS stops "
        "paying on the measured cases (doc/guide/implicit.md, Linear "
        "solver and preconditioner).");
      prm.declare_entry(
        "Preconditioner",
        "AMG",
        Selection("AMG|AMG with cell pressure"),
        "AMG: ML algebraic multigrid on the tangent. Its iterations grow "
        "as sqrt(lambda/mu) when the material is nearly incompressible. "
        "AMG with cell pressure: for bodies with Volumetric smoothing = "
        "cell, each cell's stiff volumetric part (lambda/V) g b^T, with b "
        "the derivative of the cell's volume change by the nodal increment "
        "and g the gradient of its current volume, on which the pressure "
        "acts, is taken out of the tangent and carried by a pressure "
        "unknown per cell and body; GMRES solves the equivalent displacement-pressure "
        "system, preconditioned block-triangularly by AMG on the rest of "
        "the tangent and a diagonal Schur complement. The displacement is "
        "the same as with AMG, to the linear tolerance, which still "
        "applies to the residual of the tangent. Only bodies with "
        "Volumetric smoothing = cell, no Stress filter, and elastic "
        "moduli with lambda > gamma mu (Cell pressure gamma; nu > 0.455 "
        "in 3D and plane strain at the default) "
        "are split; the others keep their whole tangent in the AMG part, "
        "and a run with none is refused, as is 1D (nothing locks there). "
        "Needs an iterative Linear solver (GMRES; automatic chooses it).");
      prm.declare_entry(
        "Cell pressure gamma",
        "10",
        Double(0),
        "AMG with cell pressure: the split takes lambda - gamma mu of the "
        "cells' volumetric stiffness out, and leaves gamma mu to AMG; "
        "bodies with lambda <= gamma mu are not split. With 0 the "
        "pressure system is the Q1-P0 one, whose near-checkerboard modes "
        "double the GMRES iterations per refinement; with a large gamma "
        "AMG is slow again. 10 needs the fewest iterations on Cook's "
        "membrane at nu = 0.4999 (doc/theory/implicit.md).");
      prm.declare_entry("Linear tolerance",
                        "1e-10",
                        Double(0),
                        "Relative residual reduction of the iterative "
                        "linear solver.");
      prm.declare_entry("Maximum linear iterations",
                        "2000",
                        Integer(1),
                        "Iterations before the linear solver fails (the "
                        "step is then cut).");
      prm.declare_entry(
        "Minimum nodal support",
        "1e-4",
        Double(0, 1),
        "A node is an unknown only where the particles cover at least this "
        "fraction of its support: sum_p S_ap V_p >= fraction * int N_a. A "
        "node that a domain family's particle reaches with a sliver of its "
        "domain has a stiffness of the order of that sliver; left free, it "
        "takes displacements of thousands of cell sizes in the Newton "
        "direction and Newton fails. Such a node is held instead (its "
        "weights at the particles are of the same order). Quasi-static "
        "steps only: with Integrator = Newmark the node's mass holds it.");
      prm.declare_entry(
        "Ghost penalty",
        "0",
        Double(0),
        "beta of a ghost penalty, beta E h int_F [[du/dn]] . [[dw/dn]], "
        "added to the step's residual and tangent on the faces between two "
        "cells whose nodes are all unknowns, where one of the two has a node "
        "covered by less than a quarter of its support (sum_p S_ap V_p < "
        "int N_a / 4). E is the bodies' largest Young's modulus, h the cell "
        "size, u the step's nodal increment. It ties the motion of a weakly "
        "covered cell to its neighbour's, so that a node that a few "
        "particles reach is not free to take a large increment. 0: off. "
        "1e-3 to 1e-2 hold the weak nodes of the strip footing and of "
        "Cook's membrane at finite strain and change the converged "
        "displacement by a few tenths of a percent "
        "(doc/guide/implicit.md). Needs a body with a Young's modulus. "
        "The explicit integrator ignores it.");
      prm.declare_entry(
        "Geometry",
        "updated",
        Selection("updated|fixed|small strain"),
        "updated: each converged step moves the particles and their "
        "domains (updated-Lagrangian, large deformation). fixed: the "
        "particles, their domains and the bodies of prescribed motion stay "
        "where the run starts, and every step finds equilibrium in that "
        "undeformed shape: a limit load without the change of shape that a "
        "large settlement brings (doc/guide/implicit.md). The material is "
        "updated as with updated: F and the volumes accumulate the steps' "
        "increments. small strain: fixed, with linearized kinematics: the "
        "material's strain increment is the symmetric part of the step's "
        "displacement gradient, without rotation, F and the volumes stay "
        "as they start, and the force is sigma on the initial volumes, the "
        "small-deformation analysis of finite elements; for the rate-form "
        "models (linear elastic, von Mises plasticity) with Strain "
        "increment = start of step. Neither with a family whose domain "
        "follows F (cpGIMP, CPDI), nor with Integrator = explicit.");
      prm.leave_subsection();
    }

    void
    ImplicitSolver::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Implicit solver");
      residual_tolerance = prm.get_double("Residual tolerance");
      absolute_residual_tolerance =
        prm.get_double("Absolute residual tolerance");
      energy_tolerance    = prm.get_double("Energy tolerance");
      max_iterations      = prm.get_integer("Maximum Newton iterations");
      line_search         = prm.get_bool("Line search");
      max_step_cuts       = prm.get_integer("Maximum step cuts");
      const std::string s = prm.get("Linear solver");
      linear_solver       = s == "CG"     ? LinearSolver::cg :
                            s == "GMRES"  ? LinearSolver::gmres :
                            s == "direct" ? LinearSolver::direct :
                                            LinearSolver::automatic;
      direct_solver = prm.get("Direct solver") == "KLU" ? DirectSolver::klu :
                                                          DirectSolver::mumps;
      {
        const auto limits = dealii::Utilities::split_string_list(
          prm.get("Automatic direct limit"));
        for (unsigned int d = 0; d < 3; ++d)
          direct_limit[d] = std::stoul(limits[d]);
      }
      preconditioner        = prm.get("Preconditioner") == "AMG" ?
                                Preconditioner::amg :
                                Preconditioner::amg_cell_pressure;
      cell_pressure_gamma   = prm.get_double("Cell pressure gamma");
      linear_tolerance      = prm.get_double("Linear tolerance");
      max_linear_iterations = prm.get_integer("Maximum linear iterations");
      min_nodal_support     = prm.get_double("Minimum nodal support");
      ghost_penalty         = prm.get_double("Ghost penalty");
      small_strain          = prm.get("Geometry") == "small strain";
      fixed_geometry        = prm.get("Geometry") != "updated";
      prm.leave_subsection();
      if (!(residual_tolerance > 0) && !(absolute_residual_tolerance > 0))
        throw InputError("Implicit solver: Residual tolerance and Absolute "
                         "residual tolerance are both zero: Newton could "
                         "never converge");
      if (!(linear_tolerance > 0))
        throw InputError("Implicit solver/Linear tolerance must be positive");
    }
  } // namespace Parameters
} // namespace mpm
