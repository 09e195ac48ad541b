#include <deal.II/lac/arpack_solver.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>

#include <mpm/fe_reference/modal_analysis.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <complex>
#include <numeric>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    template <int dim>
    Modes
    compute_modes(const ElasticSystem<dim> &system, const unsigned int n_modes)
    {
      const SparseMatrix<double> &K = system.stiffness_matrix();
      const SparseMatrix<double> &M = system.mass_matrix();
      const unsigned int          n = K.m();

      double largest_ratio = 0;
      for (unsigned int i = 0; i < n; ++i)
        if (M.diag_element(i) > 0)
          largest_ratio =
            std::max(largest_ratio, K.diag_element(i) / M.diag_element(i));
      // exactly as many rigid-body modes as the constraints admit come
      // first (none for a clamped body, however small its lowest omega^2)
      const unsigned int n_rigid         = system.n_rigid_body_motions();
      const bool         free_body       = n_rigid > 0;
      const double       rigid_threshold = 1e-9 * largest_ratio;
      const double       shift           = free_body ? -rigid_threshold : 0.;
      const unsigned int n_wanted        = n_modes + n_rigid;
      const unsigned int n_lanczos       = std::max(2 * n_wanted + 2, 30u);
      unsigned int       n_free          = 0;
      for (unsigned int i = 0; i < n; ++i)
        n_free += system.constraints().is_constrained(i) ? 0 : 1;
      if (n_lanczos + 1 > n_free)
        throw InputError(
          "Analysis/Number of modes = " + std::to_string(n_modes) +
          ": the coarsest mesh has " + std::to_string(n_free) +
          " free dofs, too few for the Lanczos iteration; "
          "refine the coarse mesh");

      SparseMatrix<double> shifted(K.get_sparsity_pattern());
      shifted.copy_from(K);
      if (shift != 0)
        shifted.add(-shift, M);
      SparseDirectUMFPACK inverse;
      try
        {
          inverse.initialize(shifted);
        }
      catch (const std::exception &e)
        {
          throw InputError("modal analysis: K - sigma M is singular (" +
                           clean_dealii_message(e.what()) + ")");
        }

      SolverControl control(5000, 1e-11);
      ArpackSolver  eigensolver(
        control,
        ArpackSolver::AdditionalData(n_lanczos,
                                     ArpackSolver::largest_magnitude,
                                     /*symmetric=*/true));
      eigensolver.set_shift(shift);
      std::vector<std::complex<double>> eigenvalues(n_wanted);
      std::vector<Vector<double>>       vectors(n_wanted, Vector<double>(n));
      eigensolver.solve(K, M, inverse, eigenvalues, vectors, n_wanted);

      std::vector<unsigned int> order(n_wanted);
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
        return eigenvalues[a].real() < eigenvalues[b].real();
      });

      Modes                       modes;
      Vector<double>              Ku(n), Mu(n);
      std::vector<Vector<double>> rigid; // M-orthonormal
      for (const unsigned int k : order)
        {
          Vector<double> &u      = vectors[k];
          double          lambda = eigenvalues[k].real();
          if (modes.n_rigid_body_modes < n_rigid &&
              std::abs(lambda) < rigid_threshold)
            {
              // keep the rigid-body modes M-orthonormal for the cleaning
              for (const auto &r : rigid)
                {
                  M.vmult(Mu, r);
                  u.add(-(u * Mu), r);
                }
              M.vmult(Mu, u);
              u /= std::sqrt(u * Mu);
              rigid.push_back(u);
              ++modes.n_rigid_body_modes;
              continue;
            }
          if (modes.omega_squared.size() == n_modes)
            continue;
          // With the negative shift of a free body, K - sigma M is badly
          // conditioned (cond ~ 1e9) and the elastic vectors carry a trace
          // of the rigid-body modes: remove it (M-orthogonal projection)
          // and take the Rayleigh quotient.
          for (const auto &r : rigid)
            {
              M.vmult(Mu, r);
              u.add(-(u * Mu), r);
            }
          K.vmult(Ku, u);
          M.vmult(Mu, u);
          lambda = (u * Ku) / (u * Mu);
          // ARPACK reports failures only through assertions (debug mode):
          // check every pair here
          Vector<double> residual(Ku);
          residual.add(-lambda, Mu);
          const double scale = std::max(Ku.l2_norm(), 1e-300);
          // The vectors of an ill-conditioned K (a free body's negative
          // shift, cond ~ 1e9; a slender beam on a fine mesh) are accurate
          // to about 1e-5..1e-4 only, the omega^2 error is quadratic in it
          // (~1e-8); a failed pair has a residual of order one.
          const double tolerance = 1e-3;
          if (!(residual.l2_norm() <= tolerance * scale))
            throw RuntimeError("in the modal analysis: ARPACK returned an "
                               "eigenpair with relative residual " +
                               std::to_string(residual.l2_norm() / scale));
          Vector<double> shape = u;
          system.constraints().distribute(shape);
          shape /= std::max(shape.linfty_norm(), 1e-300);
          modes.omega_squared.push_back(lambda);
          modes.shapes.push_back(shape);
        }
      if (modes.omega_squared.size() < n_modes)
        throw RuntimeError("in the modal analysis: only " +
                           std::to_string(modes.omega_squared.size()) +
                           " elastic modes found among the lowest " +
                           std::to_string(n_wanted) + " (" +
                           std::to_string(modes.n_rigid_body_modes) +
                           " rigid-body modes)");
      return modes;
    }

    template Modes
    compute_modes(const ElasticSystem<2> &, const unsigned int);
    template Modes
    compute_modes(const ElasticSystem<3> &, const unsigned int);
  } // namespace fe_reference
} // namespace mpm
