// The first eigenfrequency of the vibrating cantilever
// (doc/benchmarks/cantilever.md; plane stress, L = 1, H = 0.1, E = 1e7,
// nu = 0.3, rho = 1000), modal analysis with Q2 elements on 40 x 4 cells,
// against beam theory.
//
// Euler-Bernoulli: T_EB = 2 pi/(3.51602 sqrt(EI/(rho A L^4))) = 0.61904 s.
// Timoshenko (shear, kappa = 5/6, and rotary inertia), solved here by
// shooting: T_T/T_EB = 1.0079 (clamped-free); 1.0354 (free-free, first
// elastic mode, EB: beta L = 4.730041).
//
// Clamped-free: the 2D clamp holds the whole root section (no shear
// strain, no Poisson contraction there), stiffer than Timoshenko's clamp
// (psi = 0 only); the converged FE ratio is 1.00676, 0.12% below
// Timoshenko. Asserted: T_FE/T_EB in [1.005, 1.009] (Euler-Bernoulli,
// 1.000, and shear without rotary inertia, 1.0060, are outside) and
// |T_FE/T_T - 1| < 0.25%.
// Free-free: no clamp effect, so |T_FE/T_T - 1| < 0.2% (kappa between 5/6
// and Cowper's 0.85 moves T_T by 0.01%), and exactly 3 rigid-body modes
// must have been skipped.
#include <deal.II/grid/tria.h>

#include <mpm/fe_reference/elastic_system.h>
#include <mpm/fe_reference/modal_analysis.h>
#include <mpm/fe_reference/reference_mesh.h>

#include <array>

#include "fe_tests.h"

using namespace dealii;

namespace
{
  const double E = 1e7, nu = 0.3, rho = 1000, L = 1, H = 0.1;
  const double A = H, I = H * H * H / 12, G = E / (2 * (1 + nu));
  const double kappa = 5. / 6;

  /**
   * Timoshenko beam, y = (w, w', psi, psi'):
   * kappa G A (w'' - psi') + rho A omega^2 w = 0,
   * E I psi'' + kappa G A (w' - psi) + rho I omega^2 psi = 0.
   * Free end: psi' = 0 and w' - psi = 0. Returns the determinant of the
   * free-end conditions at x = L for the two solutions that start with
   * @p start (the other conditions at x = 0 built in); zero at an
   * eigenfrequency.
   */
  double
  end_determinant(const double                                omega2,
                  const std::array<std::array<double, 4>, 2> &start)
  {
    const auto rhs = [omega2](const std::array<double, 4> &y) {
      const double w = y[0], wp = y[1], p = y[2], pp = y[3];
      return std::array<double, 4>{
        {wp,
         pp - rho * omega2 * w / (kappa * G),
         pp,
         -(kappa * G * A * (wp - p) + rho * I * omega2 * p) / (E * I)}};
    };
    double         m[2][2];
    const unsigned n = 2000;
    const double   h = L / n;
    for (unsigned int s = 0; s < 2; ++s)
      {
        auto y = start[s];
        for (unsigned int step = 0; step < n; ++step)
          {
            // classical Runge-Kutta
            const auto k1 = rhs(y);
            auto       t  = y;
            for (unsigned i = 0; i < 4; ++i)
              t[i] = y[i] + h / 2 * k1[i];
            const auto k2 = rhs(t);
            for (unsigned i = 0; i < 4; ++i)
              t[i] = y[i] + h / 2 * k2[i];
            const auto k3 = rhs(t);
            for (unsigned i = 0; i < 4; ++i)
              t[i] = y[i] + h * k3[i];
            const auto k4 = rhs(t);
            for (unsigned i = 0; i < 4; ++i)
              y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
          }
        m[s][0] = y[3];
        m[s][1] = y[1] - y[2];
      }
    return m[0][0] * m[1][1] - m[0][1] * m[1][0];
  }

  /// The root of end_determinant in [lo, hi] (omega), by bisection.
  double
  timoshenko_omega(double                                      lo,
                   double                                      hi,
                   const std::array<std::array<double, 4>, 2> &start)
  {
    double f_lo = end_determinant(lo * lo, start);
    for (unsigned int it = 0; it < 60; ++it)
      {
        const double mid   = (lo + hi) / 2;
        const double f_mid = end_determinant(mid * mid, start);
        if (f_lo * f_mid <= 0)
          hi = mid;
        else
          {
            lo   = mid;
            f_lo = f_mid;
          }
      }
    return (lo + hi) / 2;
  }

  double
  fe_period(const std::string &boundary, unsigned int &n_rigid)
  {
    const auto               p = fe_test::parameters<2>(R"(
set Kinematic assumption = plane stress
subsection Geometry
  set Lower corner = 0, 0
  set Upper corner = 1, 0.1
  set Subdivisions = 40, 4
end
subsection Material
  set Density = 1000
  subsection Linear elastic
    set Young's modulus = 1e7
    set Poisson's ratio = 0.3
  end
end
subsection Analysis
  set Type = modal
  set Number of modes = 2
end
)" + boundary);
    fe_test::MeshedSystem<2> meshed(p);
    auto                    &system = *meshed.system;
    system.assemble_stiffness_and_mass();
    const auto modes = mpm::fe_reference::compute_modes(system, 2);
    n_rigid          = modes.n_rigid_body_modes;
    return 2 * M_PI / std::sqrt(modes.omega_squared[0]);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double scale = std::sqrt(E * I / (rho * A * L * L * L * L));

  // clamped-free: w = psi = 0 at x = 0
  const double eb_cf = 3.51602 * scale;
  const double t_cf =
    timoshenko_omega(0.9 * eb_cf, eb_cf, {{{{0, 1, 0, 0}}, {{0, 0, 0, 1}}}});
  unsigned int n_rigid  = 0;
  const double period   = fe_period(R"(
subsection Boundary conditions
  set Clamped boundary ids = 0
end
)",
                                  n_rigid);
  const double ratio_eb = period * eb_cf / (2 * M_PI);
  const double ratio_t  = period * t_cf / (2 * M_PI);
  mpm_test::log() << std::fixed << std::setprecision(4)
                  << "clamped-free: T_T/T_EB = " << eb_cf / t_cf
                  << ", T_FE/T_EB = " << ratio_eb << std::endl;
  mpm_test::check(ratio_eb - 1 > 0.005 && ratio_eb - 1 < 0.009,
                  "clamped-free T_FE/T_EB - 1 in [0.005, 0.009]",
                  ratio_eb - 1,
                  0.009);
  mpm_test::check_small("clamped-free |T_FE/T_Timoshenko - 1|",
                        ratio_t - 1,
                        2.5e-3);
  mpm_test::check(n_rigid == 0,
                  "clamped-free: no rigid-body modes",
                  n_rigid,
                  0);

  // free-free: psi' = 0, w' = psi at x = 0
  const double eb_ff     = 4.730041 * 4.730041 * scale;
  const double t_ff      = timoshenko_omega(0.85 * eb_ff,
                                       0.999 * eb_ff,
                                       {{{{1, 0, 0, 0}}, {{0, 1, 1, 0}}}});
  const double period_ff = fe_period("", n_rigid);
  mpm_test::log() << std::fixed << std::setprecision(4)
                  << "free-free: T_T/T_EB = " << eb_ff / t_ff
                  << ", T_FE/T_EB = " << period_ff * eb_ff / (2 * M_PI)
                  << std::endl;
  mpm_test::check_small("free-free |T_FE/T_Timoshenko - 1|",
                        period_ff * t_ff / (2 * M_PI) - 1,
                        2e-3);
  mpm_test::check(n_rigid == 3,
                  "free-free: 3 rigid-body modes skipped",
                  n_rigid,
                  3);
}
