// A slender cantilever (L = 10, H = 1, plane stress, E = 1000, nu = 0.3),
// clamped at x = 0, a shear load P = 1 spread uniformly over the end
// x = L; Q2 elements on 40 x 4 cells. Tip deflection at mid-depth against
// Timoshenko beam theory: delta = P L^3/(3 E I) + P L/(kappa G A) =
// 4 + 0.0312 (kappa = 5/6).
//
// The 2D clamp holds the whole root section (no shear strain and no
// Poisson contraction there), which Timoshenko's clamp does not, and the
// end load is uniform rather than parabolic; both stiffen the 2D beam by
// a few tenths of the shear term's share. Measured (converged, 160 x 16
// cells): delta_FE/delta_T = 0.9982. Asserted: 0.995 < delta_FE/delta_T
// < 1: stiffer than Timoshenko, by less than 0.5%. Euler-Bernoulli alone
// (0.9923 of Timoshenko) is outside, so is any wrong modulus (plane strain
// would give 0.91).
#include <deal.II/grid/tria.h>

#include <mpm/fe_reference/elastic_system.h>
#include <mpm/fe_reference/reference_mesh.h>

#include "fe_tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       p = fe_test::parameters<2>(R"(
set Kinematic assumption = plane stress
subsection Geometry
  set Lower corner = 0, 0
  set Upper corner = 10, 1
  set Subdivisions = 40, 4
end
subsection Material
  subsection Linear elastic
    set Young's modulus = 1000
    set Poisson's ratio = 0.3
  end
end
subsection Boundary conditions
  set Clamped boundary ids = 0
  set Traction boundary ids = 1
  set Traction = 0; -1
end
)");
  fe_test::MeshedSystem<2>         meshed(p);
  auto                            &system = *meshed.system;
  system.solve_static();

  const double E = 1000, nu = 0.3, L = 10, H = 1, P = 1;
  const double I = H * H * H / 12, G = E / (2 * (1 + nu));
  const double bending    = P * L * L * L / (3 * E * I);
  const double timoshenko = bending + P * L / (5. / 6 * G * H);
  const double delta      = -system.point_value(Point<2>(L, H / 2))[1];
  const double ratio      = delta / timoshenko;
  mpm_test::log() << std::fixed << std::setprecision(5)
                  << "delta_FE = " << delta << ", Timoshenko " << timoshenko
                  << ", Euler-Bernoulli " << bending << std::endl;
  mpm_test::check(1 - ratio > 0 && 1 - ratio < 0.005,
                  "1 - delta_FE/delta_Timoshenko in (0, 0.005)",
                  1 - ratio,
                  0.005);
  mpm_test::check(delta > bending,
                  "delta_FE/delta_Euler-Bernoulli - 1 > 0",
                  delta / bending - 1,
                  0);
}
