// P2G and G2P conserve mass and linear momentum exactly: a free, stressed,
// moving block (no boundary conditions, no external force) keeps its total
// mass and momentum to round-off over many steps, for every scheme, and
// its angular momentum up to the time discretisation. The same holds with
// the locking remedies: the assumed-stress filter's force sums to zero in
// every cell, and the volumetric smoothing changes only the stress.
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string remedy : {"none", "filter", "theta-bar"})
    for (const std::string scheme : {"USF", "USL", "MUSL"})
      for (const std::string flip : {"1", "0"})
        {
          if (remedy != "none" && flip == "0")
            continue;
          mpm_test::Case<2> c(
            R"(
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 12
end
subsection Time stepping
  set Scheme = )" +
            scheme + R"(
  set FLIP fraction = )" +
            flip +
            R"(
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.3, 0.25
    set Upper corner = 0.7, 0.65
    set Subdivisions = 7
    set Particles per direction = 3
    set Initial velocity = 0.3 + 0.2*sin(3*y); -0.1 + 0.3*x*x
    set Initial stress = 1e3*x; -2e3*y*x; 500*x*y
    subsection Material
      set Model = linear elastic
      set Density = 1000
    end
    subsection Locking remedies
      set Stress filter = )" +
            std::string(remedy == "filter" ? "assumed stress" : "none") + R"(
      set Volumetric smoothing = )" +
            std::string(remedy == "theta-bar" ? "cell" : "none") + R"(
    end
  end
end)");
          auto        &sim = *c.simulator;
          const auto   s0  = sim.statistics();
          const double dt  = 0.2 * sim.stable_time_step();
          for (unsigned int n = 0; n < 30; ++n)
            sim.do_time_step(dt);
          const auto        s1  = sim.statistics();
          const double      p   = std::hypot(s0.momentum[0], s0.momentum[1]);
          const std::string tag = (remedy == "none" ? "" : remedy + ", ") +
                                  scheme + ", FLIP " + flip + ": ";
          mpm_test::check_small(tag + "mass change",
                                (s1.mass - s0.mass) / s0.mass,
                                1e-14);
          mpm_test::check_small(tag + "momentum x change",
                                (s1.momentum[0] - s0.momentum[0]) / p,
                                1e-12);
          mpm_test::check_small(tag + "momentum y change",
                                (s1.momentum[1] - s0.momentum[1]) / p,
                                1e-12);
        }
}
