// Lame's thick cylinder at nu = 0.4999, plane strain: a quarter annulus
// a = 1 < r < b = 2 with slip on the symmetry lines, internal pressure
// p = 1, E = 1000. Exact radial displacement
//   u_r = (1+nu) p a^2/(E (b^2-a^2)) ((1-2nu) r + b^2/r).
// Mixed Taylor-Hood Q2/Q1 on a 4 x 16 cell mesh (curved boundaries
// through MappingQ2) must give u_r to 0.1% at r = 1.1, 1.5, 1.9 (30
// degrees). The pure
// displacement Q1 element on the same mesh locks: its u_r at r = 1.5
// stays below 50% of the exact value (measured: 6%) (asserted, so the test
// shows that the mixed solution's agreement is not a property of the mesh).
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <mpm/fe_reference/elastic_system.h>

#include "fe_tests.h"

using namespace dealii;

namespace
{
  const double a = 1, b = 2, pressure = 1, E = 1000, nu = 0.4999;

  double
  exact_radial_displacement(const double r)
  {
    return (1 + nu) * pressure * a * a / (E * (b * b - a * a)) *
           ((1 - 2 * nu) * r + b * b / r);
  }

  /// u_r at the radii (30 degrees) of one discretisation
  std::vector<double>
  radial_displacements(const std::string         &discretisation,
                       const std::vector<double> &radii)
  {
    const auto       p = fe_test::parameters<2>(R"(
set Kinematic assumption = plane strain
subsection Material
  subsection Linear elastic
    set Young's modulus = 1000
    set Poisson's ratio = 0.4999
  end
end
subsection Boundary conditions
  # quarter_hyper_shell: 0 inner, 1 outer, 2 and 3 the straight edges
  set Slip boundary ids = 2, 3
  set Traction boundary ids = 0
  set Traction = x/sqrt(x^2+y^2); y/sqrt(x^2+y^2)
end
)" + discretisation);
    Triangulation<2> tria;
    GridGenerator::quarter_hyper_shell(tria, Point<2>(), a, b, 4, true);
    tria.refine_global(2);
    mpm::fe_reference::ElasticSystem<2> system(p, tria);
    system.setup();
    system.solve_static();
    std::vector<double> u_r;
    const double        angle = M_PI / 6;
    for (const double r : radii)
      {
        const Point<2> x(r * std::cos(angle), r * std::sin(angle));
        const auto     u = system.point_value(x);
        u_r.push_back(u[0] * std::cos(angle) + u[1] * std::sin(angle));
      }
    return u_r;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<double>        radii = {1.1, 1.5, 1.9};

  const auto mixed = radial_displacements(R"(
subsection Discretisation
  set Formulation = mixed
  set Polynomial degree = 2
end
)",
                                          radii);
  for (unsigned int i = 0; i < radii.size(); ++i)
    mpm_test::check_small("mixed Q2/Q1: u_r/exact - 1 at r = " +
                            std::to_string(radii[i]).substr(0, 3),
                          mixed[i] / exact_radial_displacement(radii[i]) - 1,
                          1e-3);

  const auto   q1     = radial_displacements(R"(
subsection Discretisation
  set Formulation = displacement
  set Polynomial degree = 1
end
)",
                                       radii);
  const double locked = q1[1] / exact_radial_displacement(radii[1]);
  mpm_test::log() << "displacement Q1: u_r/exact at r = 1.5: " << std::fixed
                  << std::setprecision(2) << locked << std::endl;
  mpm_test::check(locked < 0.5,
                  "displacement Q1 locks: u_r/exact at r = 1.5 below 0.5",
                  locked,
                  0.5);
}
