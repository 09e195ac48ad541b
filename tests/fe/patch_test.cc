// Patch test of the displacement formulation: a linear displacement field
// prescribed on the whole boundary of a distorted mesh must be reproduced
// at every dof to round-off, and the stress must be the constant stress of
// that field, at every quadrature point. Q1 and Q2 in 2D (plane stress,
// Cook's tapered panel with randomly moved interior vertices) and Q2 in
// 3D (a randomly distorted box). A wrong element, mapping, constraint or
// modulus breaks it by far more than the 1e-9 tolerance (the linear field
// has entries of order 1, so round-off of the direct solver is ~1e-13).
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <mpm/fe_reference/displacement_function.h>
#include <mpm/fe_reference/elastic_system.h>
#include <mpm/fe_reference/reference_mesh.h>
#include <mpm/utilities/expression.h>

#include "fe_tests.h"

using namespace dealii;

namespace
{
  // u = A x + c with a general (non-symmetric) A
  const char *field_2d = "0.1 + 0.3*x - 0.2*y; -0.2 + 0.1*x + 0.4*y";
  const char *field_3d =
    "0.1 + 0.3*x - 0.2*y + 0.1*z; -0.2 + 0.1*x + 0.4*y - 0.3*z; "
    "0.05 - 0.1*x + 0.2*y + 0.25*z";

  template <int dim>
  void
  run(const std::string &geometry,
      const unsigned int degree,
      const bool         mixed = false)
  {
    const std::string field = dim == 2 ? field_2d : field_3d;
    const auto        p     = fe_test::parameters<dim>(
      geometry +
      "subsection Material\n subsection Linear elastic\n"
                 "  set Young's modulus = 7\n  set Poisson's ratio = 0.3\n end\nend\n"
                 "subsection Boundary conditions\n"
                 "  set Prescribed displacement boundary ids = " +
      (dim == 2 ? std::string("0, 1, 2, 3") : std::string("0, 1, 2, 3, 4, 5")) +
      "\n  set Prescribed displacement = " + field +
      "\nend\n"
                 "subsection Discretisation\n  set Polynomial degree = " +
      std::to_string(degree) + "\n  set Formulation = " +
      (mixed ? "mixed" : "displacement") + "\nend\n");

    Triangulation<dim> tria;
    mpm::fe_reference::create_coarse_mesh(tria, p.geometry, "");
    tria.refine_global(dim == 2 ? 2 : 1);
    GridTools::distort_random(0.3, tria, /*keep_boundary=*/true, 42);

    mpm::fe_reference::ElasticSystem<dim> system(p, tria);
    system.setup();
    system.solve_static();

    // the exact field interpolated at every dof
    const mpm::Expression<dim> u(
      field, dim, dim == 2 ? "x,y" : "x,y,z", {}, false, "field");
    Vector<double> exact(system.dof_handler().n_dofs());
    {
      // the exact field as a function of all the system's components (the
      // mixed formulation's pressure is compared through the stress)
      const mpm::fe_reference::DisplacementFunction<dim> exact_function(
        u, dim + (mixed ? 1 : 0));
      VectorTools::interpolate(system.dof_handler(), exact_function, exact);
    }
    // displacement dofs only
    std::vector<bool> u_components(system.dof_handler().get_fe().n_components(),
                                   false);
    for (unsigned int d = 0; d < dim; ++d)
      u_components[d] = true;
    const IndexSet u_dofs =
      DoFTools::extract_dofs(system.dof_handler(), ComponentMask(u_components));
    double max_error = 0, max_u = 0;
    for (const auto i : u_dofs)
      {
        max_error =
          std::max(max_error, std::abs(system.solution()[i] - exact[i]));
        max_u = std::max(max_u, std::abs(exact[i]));
      }

    // the exact stress: eps = sym(A), plane stress lambda* in 2D
    SymmetricTensor<2, dim> eps;
    const double            A2[2][2] = {{0.3, -0.2}, {0.1, 0.4}};
    const double            A3[3][3] = {{0.3, -0.2, 0.1},
                                        {0.1, 0.4, -0.3},
                                        {-0.1, 0.2, 0.25}};
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        eps[i][j] =
          dim == 2 ? 0.5 * (A2[i][j] + A2[j][i]) : 0.5 * (A3[i][j] + A3[j][i]);
    const mpm::materials::LameModuli moduli(7, 0.3, p.kinematics);
    const SymmetricTensor<2, dim>       sigma =
      2 * moduli.mu * eps +
      moduli.lambda * trace(eps) * unit_symmetric_tensor<dim>();
    double stress_error = 0;
    for (const auto &s : system.quadrature_point_stresses())
      stress_error = std::max(stress_error, (s - sigma).norm() / sigma.norm());

    const std::string name =
      std::to_string(dim) + "D Q" + std::to_string(degree) +
      (mixed ? "/Q" + std::to_string(degree - 1) : "") + " (" +
      std::to_string(system.dof_handler().n_dofs()) + " dofs)";
    mpm_test::check_small(name + ": max nodal error / max |u|",
                          max_error / max_u,
                          1e-9);
    mpm_test::check_small(name + ": max relative stress error",
                          stress_error,
                          1e-9);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                cook = R"(
set Kinematic assumption = plane stress
subsection Geometry
  set Type = quadrilateral
  set Corners = 0, 0; 48, 44; 48, 60; 0, 44
  set Subdivisions = 2
end
)";
  run<2>(cook, 1);
  run<2>(cook, 2);
  run<2>(cook, 2, /*mixed=*/true);
  run<3>(R"(
subsection Geometry
  set Type = box
  set Lower corner = 0, 0, 0
  set Upper corner = 2, 1, 1
  set Subdivisions = 2, 1, 1
end
)",
         2);
}
