// The sparse direct solvers of the implicit step (Implicit solver/Linear
// solver = direct, Direct solver = MUMPS or KLU) solve the same tangent
// systems as AMG with GMRES, and Linear solver = automatic takes the direct
// one below its Automatic direct limit:
// - the strain energy and the platen's reaction agree with GMRES's to 1e-8
//   (the linear tolerance being 1e-10) with the same Newton iterations;
// - a direct solve counts one linear iteration, and automatic counts as
//   many as direct MUMPS (a small case) and, with the limit 0, as many as
//   GMRES (on the square, where GMRES takes several);
// - the direct solve repeats itself bit for bit (on 2 ranks too: the
//   factorisation runs on one process).
// Two small cases cover the constraints: a rigid platen pressing a block
// between slip walls (the predictor's inhomogeneous constraints and the
// platen's reaction), and a column under its own weight on a grid rotated
// by 30 degrees (slip lines that couple two directions of a node); a
// square of 64 x 64 cells under its own weight is large enough for AMG to
// need several GMRES iterations.
#include "../tests.h"
#include "implicit_run.h"
#include "platen_block.h"
#include "rotated_column.h"

namespace
{
  std::string
  solver(const std::string &linear_solver,
         const std::string &direct_solver = "MUMPS",
         const std::string &limit         = "100000000, 500000, 20000")
  {
    return R"(
subsection Implicit solver
  set Linear solver = )" +
           linear_solver + R"(
  set Direct solver = )" +
           direct_solver + R"(
  set Automatic direct limit = )" +
           limit + R"(
  set Linear tolerance = 1e-10
end
subsection Output
  set Directory = results
end
)";
  }

  std::string
  platen(const std::string &solver_text)
  {
    return solver_text + platen_block::parameters("0.49", "-0.2");
  }

  std::string
  column(const std::string &solver_text, const double angle)
  {
    return solver_text +
           rotated_column::parameters(rotated_column::rotated_grid, angle, 0.3);
  }

  /// A square under its own weight on a fixed base, 64 x 64 cells: large
  /// enough that AMG needs several GMRES iterations per solve.
  std::string
  square(const std::string &solver_text)
  {
    return solver_text + R"(
set Kinematic assumption = plane strain
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 64, 64
end
subsection Boundary conditions
  set Fixed boundary ids = 2
end
subsection Time stepping
  set Integrator = quasi-static
  set Time step control = fixed
  set Time step = 1
  set End time = 1
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0, 0
    set Upper corner = 1, 1
    set Subdivisions = 64, 64
    set Particles per direction = 2
    set Body force = 0; -10*t
    subsection Material
      set Model = linear elastic
      set Density = 1000
      subsection Linear elastic
        set Young's modulus = 1e6
        set Poisson's ratio = 0.3
      end
    end
  end
end
)";
  }

  using implicit_run::Result;
  using implicit_run::run;
  using implicit_run::same_solution;

  template <typename Run>
  void
  check(const std::string &name, const Run &run_with, const bool iterates)
  {
    const Result gmres     = run_with(solver("GMRES"));
    const Result mumps     = run_with(solver("direct"));
    const Result klu       = run_with(solver("direct", "KLU"));
    const Result automatic = run_with(solver("automatic"));
    const Result iterative = run_with(solver("automatic", "MUMPS", "0,0,0"));
    const Result again     = run_with(solver("direct"));
    mpm_test::report(gmres.energy > 0, name + ": strained", gmres.energy);
    std::cerr << name << ": linear iterations GMRES " << gmres.linear
              << ", MUMPS " << mumps.linear << ", automatic "
              << automatic.linear << ", automatic with limit 0 "
              << iterative.linear << std::endl;
    same_solution(name + ", MUMPS against GMRES", gmres, mumps);
    same_solution(name + ", KLU against GMRES", gmres, klu);
    mpm_test::report(mumps.linear == mumps.newton ||
                       mumps.linear == mumps.newton + 1,
                     name + ": one linear iteration per direct solve",
                     mumps.linear);
    mpm_test::report(automatic.linear == mumps.linear &&
                       automatic.energy == mumps.energy,
                     name + ": automatic solves this size directly",
                     automatic.linear);
    // (where AMG solves in one GMRES iteration the counts do not tell)
    if (iterates)
      {
        mpm_test::report(gmres.linear > mumps.linear,
                         name + ": GMRES takes more than one iteration",
                         gmres.linear);
        mpm_test::report(iterative.linear == gmres.linear &&
                           iterative.energy == gmres.energy,
                         name + ": automatic with the limit 0 is GMRES",
                         iterative.linear);
      }
    mpm_test::report(again.energy == mumps.energy &&
                       again.reaction == mumps.reaction,
                     name + ": the direct solve repeats itself bit for bit",
                     again.energy - mumps.energy);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             angle = M_PI / 6;
  rotated_column::write_grid(angle);

  check(
    "rigid platen",
    [](const std::string &s) { return run(platen(s), 2, 0.25, 2); },
    false);
  check(
    "rotated slip column",
    [&](const std::string &s) { return run(column(s, angle), 1, 1., 1); },
    false);
  check(
    "square under its own weight",
    [](const std::string &s) { return run(square(s), 1, 1., 1); },
    true);
}
