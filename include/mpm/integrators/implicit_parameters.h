#pragma once

#include <deal.II/base/parameter_handler.h>

namespace mpm
{
  namespace Parameters
  {
    /**
     * subsection Implicit solver: Newton's method of the implicit step and
     * its linear solver (integrators/implicit_integrator.h). Part of the
     * parameter file of parameters/parameters.h, kept beside the
     * integrator that reads it.
     */
    struct ImplicitSolver
    {
      enum class LinearSolver
      {
        automatic, ///< direct up to direct_limit unknowns, else CG or GMRES
        cg,
        gmres,
        direct
      };
      /// The package behind LinearSolver::direct (either factorises on
      /// one process, the matrix gathered there).
      enum class DirectSolver
      {
        mumps, ///< multifrontal
        klu
      };
      enum class Preconditioner
      {
        amg,              ///< ML AMG on the tangent
        amg_cell_pressure ///< AMG without the cells' stiff volumetric part
      };
      double       residual_tolerance          = 1e-8;
      double       absolute_residual_tolerance = 1e-12;
      double       energy_tolerance            = 1e-12;
      unsigned int max_iterations              = 20;
      bool         line_search                 = true;
      unsigned int max_step_cuts               = 6;
      LinearSolver linear_solver               = LinearSolver::automatic;
      DirectSolver direct_solver               = DirectSolver::mumps;
      /// Linear solver = automatic: the largest number of unknowns (over
      /// all ranks) of a solve that goes to the direct solver, per
      /// dimension 1, 2, 3
      unsigned long  direct_limit[3] = {0, 0, 0};
      Preconditioner preconditioner  = Preconditioner::amg;
      /// AMG with cell pressure: the volumetric stiffness left in the AMG
      /// part, in units of mu
      double       cell_pressure_gamma   = 10;
      double       linear_tolerance      = 1e-10;
      unsigned int max_linear_iterations = 2000;
      double       min_nodal_support     = 1e-4;
      /// beta of the ghost penalty on weakly covered cells (0: off)
      double ghost_penalty = 0;
      /// Geometry = fixed or small strain: the particles and their
      /// domains stay where the run starts (equilibrium in the undeformed
      /// shape)
      bool fixed_geometry = false;
      /// Geometry = small strain: the materials see the symmetric part of
      /// the step's displacement gradient, F and the volumes stay
      bool small_strain = false;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace mpm
