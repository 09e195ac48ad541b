// Rigid-body modes are counted from the constraints, not guessed from
// small eigenvalues, and the refinement-study CSV parses.
//
// 1. A slender clamped cantilever (L/H = 100, plane stress, Q2 on 400 x 4
//    cells): its lowest omega^2 is below 1e-9 max K_ii/M_ii, which once
//    made the modal analysis take it for a rigid-body mode. It has none:
//    0 skipped, three elastic modes, omega_1 within 0.05% of
//    Euler-Bernoulli's 1.875104^2 sqrt(EI/(rho A L^4)) (shear adds about
//    1e-4 at this slenderness; measured 5e-5) and omega_2/omega_1 within
//    0.2% (measured 0.05%) of (4.694091/1.875104)^2 = 6.2669.
// 2. The same beam on a slip base only: one rigid-body motion (sliding
//    along x) is admissible, none of the rotations; statics is refused.
// 3. A static study with two points of interest: every row of
//    refinement_study.csv has as many fields as its header (the points'
//    coordinates must not be split by the field separator).
#include <deal.II/grid/tria.h>

#include <mpm/fe_reference/elastic_system.h>
#include <mpm/fe_reference/modal_analysis.h>
#include <mpm/fe_reference/reference_mesh.h>
#include <mpm/fe_reference/refinement_study.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "fe_tests.h"

using namespace dealii;

namespace
{
  const std::string beam = R"(
set Kinematic assumption = plane stress
subsection Geometry
  set Lower corner = 0, 0
  set Upper corner = 1, 0.01
  set Subdivisions = 400, 4
end
subsection Material
  set Density = 1000
  subsection Linear elastic
    set Young's modulus = 1e7
    set Poisson's ratio = 0.3
  end
end
)";
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  {
    const auto               p = fe_test::parameters<2>(beam + R"(
subsection Boundary conditions
  set Clamped boundary ids = 0
end
subsection Analysis
  set Type = modal
  set Number of modes = 3
end
)");
    fe_test::MeshedSystem<2> meshed(p);
    auto                    &system = *meshed.system;
    system.assemble_stiffness_and_mass();
    const auto   modes = mpm::fe_reference::compute_modes(system, 3);
    const double H = 0.01, E = 1e7, rho = 1000;
    const double omega_eb =
      1.875104 * 1.875104 * std::sqrt(E * H * H * H / 12 / (rho * H));
    mpm_test::check(modes.n_rigid_body_modes == 0,
                    "clamped slender beam: no rigid-body modes skipped",
                    modes.n_rigid_body_modes,
                    0);
    mpm_test::check(modes.omega_squared.size() == 3,
                    "clamped slender beam: three elastic modes",
                    modes.omega_squared.size(),
                    3);
    const double omega_1 = std::sqrt(modes.omega_squared[0]);
    mpm_test::check_small("|omega_1/omega_EB - 1|",
                          omega_1 / omega_eb - 1,
                          5e-4);
    mpm_test::check_small("|omega_2/omega_1 / 6.2669 - 1|",
                          std::sqrt(modes.omega_squared[1]) / omega_1 / 6.2669 -
                            1,
                          2e-3);
  }

  {
    const auto               p = fe_test::parameters<2>(beam + R"(
subsection Geometry
  set Subdivisions = 100, 1
end
subsection Boundary conditions
  set Slip boundary ids = 2
end
)");
    fe_test::MeshedSystem<2> meshed(p);
    auto                    &system = *meshed.system;
    mpm_test::check(system.n_rigid_body_motions() == 1,
                    "slip base: one admissible rigid-body motion",
                    system.n_rigid_body_motions(),
                    1);
    bool refused = false;
    try
      {
        system.solve_static();
      }
    catch (const mpm::InputError &)
      {
        refused = true;
      }
    mpm_test::check(refused, "slip base: statics refused", refused, 1);
  }

  {
    auto               p = fe_test::parameters<2>(beam + R"(
subsection Geometry
  set Subdivisions = 100, 1
end
subsection Boundary conditions
  set Clamped boundary ids = 0
  set Traction boundary ids = 1
  set Traction = 0; -1
end
subsection Discretisation
  set Refinements = 0, 1
end
subsection Analysis
  set Points of interest = 1, 0.005; 0.5, 0.005
end
subsection Output
  set Directory = results
  set Write vtu = false
end
)");
    std::ostringstream log;
    mpm::fe_reference::run_refinement_study(p, log);
    std::ifstream     csv("results/refinement_study.csv");
    std::string       line;
    std::vector<long> fields;
    while (std::getline(csv, line))
      fields.push_back(std::count(line.begin(), line.end(), ',') + 1);
    const bool same = fields.size() == 3 &&
                      std::all_of(fields.begin(), fields.end(), [&](long n) {
                        return n == fields[0];
                      });
    mpm_test::check(same,
                    "refinement_study.csv: header and 2 rows, equal field "
                    "counts",
                    fields.empty() ? 0 : fields[0],
                    fields.empty() ? 0 : fields.back());
  }
}
