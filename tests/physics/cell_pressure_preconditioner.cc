// Implicit solver/Preconditioner = AMG with cell pressure solves the same
// tangent systems as AMG: with Volumetric smoothing = cell the tangent is
// K_rest + B^T diag(lambda/V) B exactly, B the cells' volume gradients,
// condensed by the same constraints. So Newton takes the same iterations
// and ends at the same state (strain energy within 1e-8 relative, the
// linear tolerance being 1e-10), while AMG alone needs ten times the
// GMRES iterations on Cook's membrane at nu = 0.4999 (the check: at least
// eight times). Three cases cover the paths the split takes (the two
// small ones only for the equality: AMG solves them in one iteration):
// - Cook's membrane (b), plane strain, nu = 0.4999, linear elastic (the
//   rate form of theta-bar), a traction, one load step, h = 1 (about 750
//   GMRES iterations per solve with AMG, 70 with the cell pressure);
// - a column under its own weight between slip walls on a grid rotated by
//   30 degrees, neo-Hookean (F-bar, the total form), nu = 0.4999: slip
//   lines that couple two directions of a node;
// - a rigid platen pressing a block (nu = 0.49) between slip walls: the
//   predictor's inhomogeneous constraints, and the platen's reaction.
#include "../tests.h"
#include "implicit_run.h"
#include "platen_block.h"
#include "rotated_column.h"

namespace
{
  const std::string amg = "AMG", split = "AMG with cell pressure";

  std::string
  solver(const std::string &preconditioner)
  {
    return R"(
subsection Implicit solver
  set Linear solver = GMRES
  set Preconditioner = )" +
           preconditioner + R"(
  set Linear tolerance = 1e-10
end
subsection Output
  set Directory = results
end
)";
  }

  std::string
  cooks_membrane(const std::string &preconditioner)
  {
    return solver(preconditioner) + R"(
set Kinematic assumption = plane strain
subsection Grid
  set Lower corner = 0, -4
  set Upper corner = 52, 64
  set Subdivisions = 52, 68
end
subsection Boundary conditions
  set Fixed boundary ids = 0
end
subsection Time stepping
  set Integrator = quasi-static
  set Time step control = fixed
  set Time step = 1
  set End time = 1
end
subsection Bodies
  subsection Body 0
    set Geometry = quadrilateral
    set Corners = 0, 0; 48, 44; 48, 60; 0, 44
    set Subdivisions = 48
    set Particles per direction = 2
    set Traction boundary ids = 1
    set Traction = 0; 1/16
    subsection Material
      set Model = linear elastic
      set Density = 1
      subsection Linear elastic
        set Young's modulus = 250
        set Poisson's ratio = 0.4999
      end
    end
    subsection Locking remedies
      set Volumetric smoothing = cell
    end
  end
end
)";
  }

  /// The column of tests/physics/slip_rotated_column.cc, nearly
  /// incompressible, on the rotated grid.
  std::string
  column_case(const std::string &preconditioner, const double angle)
  {
    return solver(preconditioner) +
           rotated_column::parameters(rotated_column::rotated_grid,
                                      angle,
                                      0.4999,
                                      R"(    subsection Locking remedies
      set Volumetric smoothing = cell
    end
)");
  }

  /// The block of tests/physics/rigid_platen.cc at nu = 0.49 with
  /// theta-bar, pressed at a constant speed.
  std::string
  platen(const std::string &preconditioner)
  {
    return solver(preconditioner) +
           platen_block::parameters("0.49",
                                    "-0.2",
                                    R"(    subsection Locking remedies
      set Volumetric smoothing = cell
    end
)");
  }

  using implicit_run::Result;
  using implicit_run::run;

  void
  compare(const std::string &name,
          const Result      &a,
          const Result      &s,
          const double       fewer)
  {
    mpm_test::report(a.energy > 0, name + ": strained", a.energy);
    std::cerr << name << ": energy " << a.energy << " / " << s.energy
              << ", Newton " << a.newton << " / " << s.newton << ", GMRES "
              << a.linear << " / " << s.linear << std::endl;
    implicit_run::same_solution(name, a, s);
    if (fewer > 0)
      mpm_test::report(s.linear * fewer <= a.linear,
                       name + ": at least " + std::to_string(int(fewer)) +
                         " times fewer GMRES iterations with the cell "
                         "pressure",
                       s.linear / a.linear);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             angle = M_PI / 6;
  rotated_column::write_grid(angle);

  compare("Cook's membrane (b)",
          run(cooks_membrane(amg), 1, 1., 1),
          run(cooks_membrane(split), 1, 1., 1),
          8);
  compare("rotated slip column",
          run(column_case(amg, angle), 1, 1., 1),
          run(column_case(split, angle), 1, 1., 1),
          0);
  compare("rigid platen",
          run(platen(amg), 2, 0.25, 2),
          run(platen(split), 2, 0.25, 2),
          0);
}
