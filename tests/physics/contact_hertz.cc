// Hertzian contact (prm/hertz_contact.prm on a grid twice as coarse,
// h = 0.025): an elastic cylinder, R = 0.5, rests by its weight on a rigid
// plane, frictionless. At rest the nodal contact forces carry the weight,
// push only, along the plane's normal, on the plane's row of nodes, and
// are symmetric about the cylinder's axis; the half-width and the peak
// pressure they give (Benchmark = hertz contact) are within 2% of
// Hertz's a = sqrt(4 P R / (pi E*)) = 4 cells and p0 = 2 P / (pi a).
#include <mpm/contact/gather_contact_forces.h>

#include <algorithm>
#include <array>

#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const double                             G = 220, plane = 0.05;
  mpm_test::Case<2> c("include " SOURCE_DIR "/../../prm/hertz_contact.prm\n"
                      "subsection Grid\n  set Subdivisions = 48, 44\nend\n"
                      "subsection Output\n  set Write vtu = false\n"
                      "  set Write csv = false\nend\n"
                      "subsection Bodies\n"
                      "  subsection Body 0\n    set Refinements = 3\n  end\n"
                      "  subsection Body 1\n    set Subdivisions = 48, 2\n"
                      "  end\nend\n",
                      2);
  auto             &sim = *c.simulator;
  mpm_test::run_until(sim, 0.25, 0.5);

  using L           = mpm::ParticleLayout<2>;
  double local_mass = 0;
  for (const auto &p : sim.particles())
    if (p.get_properties()[L::body] == 0)
      local_mass += p.get_properties()[L::mass];
  const double weight = G * dealii::Utilities::MPI::sum(local_mass, comm);

  // (x, y, f_x, f_y) of every contact node, sorted by x
  std::vector<std::array<double, 4>> nodes;
  for (const auto &f :
       mpm::contact::gather_contact_forces(sim.contact_forces(), comm))
    nodes.push_back({{f.position[0], f.position[1], f.force[0], f.force[1]}});

  double load = 0, largest = 0, off_plane = 0, pull = 0, tangential = 0;
  for (const auto &n : nodes)
    {
      load += n[3];
      largest    = std::max(largest, n[3]);
      off_plane  = std::max(off_plane, std::abs(n[1] - plane));
      pull       = std::min(pull, n[3]);
      tangential = std::max(tangential, std::abs(n[2]));
    }
  double asymmetry = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      const auto &n = nodes[i], &m = nodes[nodes.size() - 1 - i];
      asymmetry = std::max({asymmetry,
                            std::abs(n[0] + m[0] - 1.2),
                            std::abs(n[3] - m[3]) / largest});
    }
  mpm_test::report(nodes.size() >= 7,
                   "at least 7 contact nodes (Hertz: 9)",
                   nodes.size());
  mpm_test::check_small("|sum of nodal contact forces / weight - 1|",
                        load / weight - 1,
                        0.005);
  mpm_test::check_small("contact nodes off the plane's row [m]",
                        off_plane,
                        1e-12);
  mpm_test::check_small("pulling contact force / largest", pull / largest, 0);
  mpm_test::check_small("tangential contact force / largest",
                        tangential / largest,
                        1e-9);
  mpm_test::check_small("asymmetry of the contact forces about the axis",
                        asymmetry,
                        1e-9);

  const auto v = sim.benchmark_values();
  mpm_test::check_small("benchmark load / sum of nodal forces - 1",
                        v[0] / load - 1,
                        1e-12);
  mpm_test::check_small("half-width error against Hertz", v[3], 0.02);
  mpm_test::check_small("peak pressure error against Hertz", v[6], 0.02);
}
