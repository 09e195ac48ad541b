#pragma once

#include <mpm/fe_reference/parameters.h>

#include <ostream>
#include <string>
#include <vector>

namespace mpm
{
  namespace fe_reference
  {
    /// One run of a refinement study.
    struct StudyRow
    {
      unsigned int        refinements = 0;
      unsigned int        cells       = 0;
      unsigned int        dofs        = 0;
      std::vector<double> values;       ///< displacement components, or omega_k
      double              quantity = 0; ///< of interest: u_c, or T_1
      double              change   = 0; ///< relative, to the previous run
      unsigned int        rigid_body_modes = 0;
      /// Linear solver = AMG: iterations and wall times of the solve
      unsigned int linear_iterations = 0;
      double       assembly_seconds  = 0;
      double       amg_setup_seconds = 0;
      double       solve_seconds     = 0;
    };

    /**
     * Solve on the coarse mesh refined globally by each entry of
     * Discretisation/Refinements; print the table to @p log as it grows;
     * at the end write Output/Directory/refinement_study.csv, the vtu of
     * the finest run and the test summary (nothing is written if a run
     * fails). With Linear solver/Method = AMG the meshes are distributed
     * over MPI_COMM_WORLD: the call is collective, @p log is written by
     * every process (pass a null stream on all but one), the files by
     * process 0 (the vtu by all). Returns the rows.
     */
    template <int dim>
    std::vector<StudyRow>
    run_refinement_study(const AllParameters<dim> &parameters,
                         std::ostream             &log);
  } // namespace fe_reference
} // namespace mpm
