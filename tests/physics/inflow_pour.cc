// A jet poured through an inlet into a closed box (slip walls), on 1 and
// 2 ranks with repartitions while the particles enter. The box is 0.2 m
// wide, h = 0.01; the inlet a segment of half-width R = 0.02 at y = 0.12
// pointing down, v = 0.5 m/s, layers s = 0.005 thick (8 particles each),
// Volume = 0.012 m^2: 60 layers, poured in 0.3 s.
// - In flight (t = 0.05): every layer whose centre has crossed the inlet
//   is there, with ids 0..n-1; the injected mass is rho A s per layer and
//   within half a layer of rho A v t; mass + removed = injected; the jet
//   falls freely (momentum against sum m (v + g (t - tau_k))).
// - Settled (t = 1.5): all 480 particles, the total kinetic energy a
//   millionth of the potential energy released, and the stress balances
//   the weight: sum V sigma_yy = -g sum m y (a fluid at rest on the floor
//   y = 0 under a free surface), which the checkerboard of standard MPM
//   does not change.
#include <algorithm>

#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const double g = 9.81, rho = 1000, R = 0.02, v = 0.5, s = 0.005, y0 = 0.12;
  mpm_test::Case<2> c(
    "subsection Grid\n  set Upper corner = 0.2, 0.2\n"
    "  set Subdivisions = 20\nend\n"
    "subsection Time stepping\n  set End time = 1.5\n"
    "  set FLIP fraction = 0.95\nend\n"
    "subsection Boundary conditions\n  set Slip boundary ids = 0, 1, 2, 3\n"
    "end\n"
    "subsection Load balancing\n  set Repartition interval (steps) = 20\n"
    "end\n"
    "subsection Output\n  set Write vtu = false\n  set Write csv = false\n"
    "end\n"
    "subsection Bodies\n  subsection Body 0\n    set Geometry = none\n"
    "    set Body force = 0; -9.81\n"
    "    subsection Inflow\n      set Enabled = true\n"
    "      set Center = 0.1, 0.12\n      set Direction = 0, -1\n"
    "      set Radius = 0.02\n      set Speed = 0.5\n"
    "      set Particle spacing = 0.005\n      set Volume = 0.012\n    end\n"
    "    subsection Material\n      set Model = Newtonian fluid\n"
    "      set Density = 1000\n      subsection Newtonian fluid\n"
    "        set Viscosity = 0.5\n        set Equation of state = Tait\n"
    "        set Bulk modulus = 2.5e5\n      end\n    end\n  end\nend\n",
    1);
  auto &sim               = *c.simulator;
  using L                 = mpm::ParticleLayout<2>;
  const double layer_mass = rho * 2 * R * s;

  // in flight
  const double t1 = 0.05;
  mpm_test::run_until(sim, t1, 0.5);
  auto                     stats = sim.statistics();
  const unsigned long long layers =
    static_cast<unsigned long long>(std::floor(t1 * v / s + 0.5));
  mpm_test::report(stats.n_particles == 8 * layers,
                   "8 particles for each layer that has crossed the inlet",
                   stats.n_particles);
  double ids[3]     = {0, 0, -1}; // sum, sum of squares, largest
  double momentum_y = 0, expected_y = 0;
  for (const auto &p : sim.particles())
    {
      const double id = p.get_id();
      ids[0] += id;
      ids[1] += id * id;
      ids[2]             = std::max(ids[2], id);
      const double *prop = p.get_properties().data();
      momentum_y += prop[L::mass] * prop[L::velocity + 1];
      // the layer's crossing time from its id: k = id / 8
      const double tau = (std::floor(id / 8) + 0.5) * s / v;
      expected_y -= prop[L::mass] * (v + g * (t1 - tau));
    }
  ids[0]         = dealii::Utilities::MPI::sum(ids[0], comm);
  ids[1]         = dealii::Utilities::MPI::sum(ids[1], comm);
  ids[2]         = dealii::Utilities::MPI::max(ids[2], comm);
  momentum_y     = dealii::Utilities::MPI::sum(momentum_y, comm);
  expected_y     = dealii::Utilities::MPI::sum(expected_y, comm);
  const double n = stats.n_particles;
  mpm_test::report(ids[0] == n * (n - 1) / 2 &&
                     ids[1] == (n - 1) * n * (2 * n - 1) / 6 && ids[2] == n - 1,
                   "the particle ids are 0 .. n-1",
                   ids[0]);
  mpm_test::check_small("injected mass / (rho A s per layer) - 1",
                        sim.injected_mass() / (layers * layer_mass) - 1,
                        1e-14);
  mpm_test::check_small("|injected mass - rho A v t| / (rho A s)",
                        (sim.injected_mass() - rho * 2 * R * v * t1) /
                          layer_mass,
                        0.5);
  mpm_test::check_small("(mass + removed - injected) / injected",
                        (stats.mass + stats.removed_mass -
                         sim.injected_mass()) /
                          sim.injected_mass(),
                        1e-14);
  mpm_test::check_small("falling jet: momentum_y / free fall - 1",
                        momentum_y / expected_y - 1,
                        0.01);
  mpm_test::check_small("falling jet: momentum_x / momentum_y",
                        stats.momentum[0] / momentum_y,
                        1e-10);

  // settled
  mpm_test::run_until(sim, 1.5, 0.5);
  stats = sim.statistics();
  mpm_test::report(stats.n_particles == 480 && stats.removed_mass == 0,
                   "480 particles, none removed",
                   stats.n_particles);
  mpm_test::check_small("injected mass / 60 layers - 1",
                        sim.injected_mass() / (60 * layer_mass) - 1,
                        1e-14);
  double sums[2] = {}; // sum V sigma_yy, -g sum m y
  for (const auto &p : sim.particles())
    {
      const double *prop = p.get_properties().data();
      sums[0] += prop[L::volume] * prop[L::stress + 1];
      sums[1] -= g * prop[L::mass] * p.get_location()[1];
    }
  sums[0] = dealii::Utilities::MPI::sum(sums[0], comm);
  sums[1] = dealii::Utilities::MPI::sum(sums[1], comm);
  // potential energy released: from the inlet height to the pool's
  const double released = sim.injected_mass() * g * y0 + sums[1];
  mpm_test::check_small("settled: kinetic energy / potential energy released",
                        stats.kinetic_energy / released,
                        1e-4);
  mpm_test::check_small("settled: sum V sigma_yy / (-g sum m y) - 1",
                        sums[0] / sums[1] - 1,
                        0.02);
}
