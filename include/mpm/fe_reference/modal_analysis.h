#pragma once

#include <deal.II/lac/vector.h>

#include <mpm/fe_reference/elastic_system.h>

#include <vector>

namespace mpm
{
  namespace fe_reference
  {
    /// The lowest elastic modes, rigid-body modes removed.
    struct Modes
    {
      std::vector<double>                 omega_squared; ///< ascending
      std::vector<dealii::Vector<double>> shapes;        ///< max |u| = 1
      unsigned int n_rigid_body_modes = 0; ///< near-zero modes skipped
    };

    /**
     * The @p n_modes lowest eigenpairs of K u = omega^2 M u (K and M as
     * assembled by ElasticSystem::assemble_stiffness_and_mass()), by
     * ARPACK's Lanczos iteration with shift-and-invert, the inverse
     * (K - sigma M)^-1 applied by UMFPACK. With a clamped or prescribed
     * boundary sigma = 0. Otherwise K is singular (rigid-body modes), so
     * sigma = -s with s = 1e-9 max_i K_ii/M_ii, and the modes with
     * omega^2 < s are counted as rigid-body modes and skipped; the elastic
     * modes are cleaned of their trace (M-orthogonal projection, then the
     * Rayleigh quotient). Every returned pair is checked: |K u - omega^2 M u|
     * <= 1e-6 |K u| (1e-3 for a free body: the badly conditioned shifted
     * matrix leaves its vectors accurate to about 1e-4, omega^2 to about
     * 1e-8), else a RuntimeError.
     */
    template <int dim>
    Modes
    compute_modes(const ElasticSystem<dim> &system, const unsigned int n_modes);
  } // namespace fe_reference
} // namespace mpm
