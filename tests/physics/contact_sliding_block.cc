// A block on a plane inclined at 30 degrees (prm/sliding_block.prm, coarse):
// the plane is a rigid body at rest, gravity is tilted, and the block meets
// the plane by the contact law. Frictionless and Coulomb with mu = 0.3 it
// slides 1/2 g (sin theta - mu cos theta) t^2; with mu = 0.7 > tan theta it
// stays; with the law no separation (single-field MPM's behaviour) it
// sticks to the plane however smooth. The same with the plane drawn
// inclined across the grid's cells (prm/sliding_block_rotated.prm), its
// contact normal given. And a solid cylinder on the same plane
// (prm/rolling_cylinder.prm) with mu = 0.5, which rolls without slip: its
// centre travels 1/3 g sin theta t^2 with the gap check (Gap check),
// and less than 0.8 of that without it (the nodes the cylinder shares with
// the plane hold it as a flat face would).
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double theta = 30 * M_PI / 180, g = 9.81, t_end = 0.3;
  const double frictionless = 0.5 * g * std::sin(theta) * t_end * t_end;
  // the plane along the grid (tilted gravity) and drawn inclined across
  // the cells (its Contact normal given)
  for (const std::string file : {"sliding_block", "sliding_block_rotated"})
    for (const auto &[law, mu] :
         std::vector<std::pair<std::string, double>>{{"frictionless", 0.},
                                                     {"Coulomb", 0.3},
                                                     {"Coulomb", 0.7},
                                                     {"no separation", 0.}})
      {
        const bool rotated = file == "sliding_block_rotated";
        if (rotated && law != "Coulomb")
          continue;
        std::ostringstream prm;
        prm << "include " SOURCE_DIR "/../../prm/" << file << ".prm\n"
            << "set Constants = theta=30, beta=" << (rotated ? 30 : 0)
            << ", mu=" << mu << ", g=9.81, E=1e7, nu=0.3, rho=1000, top=0.5"
            << (rotated ? ", qx=0.373205080757, qy=1.2" : "") << "\n"
            << "subsection Contact\n  set Contact law = " << law
            << "\n  set Friction coefficient = mu\nend\n"
            << "subsection Output\n"
            << "  set Write vtu = false\nend\n";
        mpm_test::Case<2> c(prm.str(), 2);
        mpm_test::run_until(*c.simulator, t_end, 0.5);
        // along the plane
        const auto   u     = mpm_test::mean_displacement(*c.simulator, 0);
        const double beta  = rotated ? theta : 0.;
        const double slide = u[0] * std::cos(beta) - u[1] * std::sin(beta);
        const double a     = std::tan(theta) > mu ?
                               g * (std::sin(theta) - mu * std::cos(theta)) :
                               0;
        const double exact =
          law == "no separation" ? 0 : 0.5 * a * t_end * t_end;
        std::ostringstream tag;
        tag << (rotated ? "plane across the cells, " : "") << law
            << ", mu = " << mu << ": |slide - exact| / frictionless slide";
        mpm_test::check(std::abs(slide - exact) < 0.02 * frictionless,
                        tag.str(),
                        std::abs(slide - exact) / frictionless,
                        0.02);
      }

  for (const bool gap : {true, false})
    {
      std::ostringstream prm;
      prm << "include " SOURCE_DIR "/../../prm/rolling_cylinder.prm\n"
          << "subsection Contact\n  set Gap check = "
          << (gap ? "true" : "false") << "\nend\n"
          << "subsection Output\n  set Write vtu = false\n"
          << "  set Write csv = false\nend\n";
      mpm_test::Case<2> c(prm.str(), 2);
      mpm_test::run_until(*c.simulator, t_end, 0.5);
      const double travel  = mpm_test::mean_displacement(*c.simulator, 0)[0];
      const double rolling = g * std::sin(theta) * t_end * t_end / 3;
      std::ostringstream tag;
      tag << "rolling cylinder, mu = 0.5, gap check " << (gap ? "on" : "off")
          << ": travel / rolling travel";
      if (gap)
        mpm_test::check(std::abs(travel / rolling - 1) < 0.03,
                        tag.str() + ", within 3% of 1",
                        travel / rolling,
                        0.03);
      else
        mpm_test::check(travel / rolling < 0.8,
                        tag.str() + ", below 0.8",
                        travel / rolling,
                        0.8);
    }
}
