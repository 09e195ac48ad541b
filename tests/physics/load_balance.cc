// Load balancing by particle count (Load balancing/Balance at set-up and
// Repartition interval).
//
// (a) A body in one corner of the grid: p4est's partition into equal
//     numbers of cells gives all its particles to one rank; the
//     repartition at set-up weighs cells by their particles and shares
//     them out. The particle counts per rank before and after are printed.
// (b) The same runs with and without repartitioning (every 4 steps while
//     the body moves across the grid) give the same particles to
//     round-off: every property of every particle (so every statistic and
//     benchmark measure computed from them), for standard MPM, the
//     assumed-stress filter, node-based theta-bar (nodal vectors rebuilt),
//     uGIMP and CPDI (domains walking into the other rank's cells), and in
//     3D. Each particle's mass is carried bit for bit (an order-independent
//     checksum of ids and masses), and a repartition moves every particle
//     with its location, reference location and properties unchanged.
#include <mpm/grid/load_balancer.h>

#include <cstdint>
#include <cstring>
#include <map>

#include "../tests.h"

namespace
{
  using namespace dealii;
  using namespace mpm;

  /// The moving, rotating elastic block in the lower corner; balanced at
  /// set-up unless @p at_setup is false (the default is left implicit).
  template <int dim>
  std::string
  case_text(const std::string &variant,
            const unsigned int interval,
            const bool         at_setup = true)
  {
    auto point = [](const double v) {
      std::string s = std::to_string(v);
      for (int d = 1; d < dim; ++d)
        s += ", " + std::to_string(v);
      return s;
    };
    std::string family = "standard", remedies, velocity;
    if (variant == "filter")
      remedies = "set Stress filter = assumed stress";
    else if (variant == "theta-bar node")
      remedies = "set Volumetric smoothing = node";
    else if (variant != "standard")
      family = variant;
    velocity = dim == 2 ? "2 - 3*(y - 0.18); 1 + 3*(x - 0.18)" :
                          "2 - 3*(y - 0.18); 1 + 3*(x - 0.18); 1.5";
    return R"(
subsection Grid
  set Lower corner = )" +
           point(0) + R"(
  set Upper corner = )" +
           point(1) + R"(
  set Subdivisions = )" +
           (dim == 2 ? "32" : "12") + R"(
end
subsection Shape functions
  set Family = )" +
           family + R"(
end
subsection Load balancing
  set Repartition interval (steps) = )" +
           std::to_string(interval) + (at_setup ? "" : R"(
  set Balance at set-up = false)") +
           R"(
end
subsection Output
  set Write vtu = false
  set Write csv = false
end
subsection Bodies
  subsection Body 0
    set Lower corner = )" +
           point(0.02) + R"(
    set Upper corner = )" +
           point(0.34) + R"(
    set Subdivisions = )" +
           (dim == 2 ? "16" : "6") + R"(
    set Particles per direction = 2
    set Initial velocity = )" +
           velocity + R"(
    subsection Locking remedies
      )" + remedies +
           R"(
    end
    subsection Material
      set Model = linear elastic
      set Density = 1000
      subsection Linear elastic
        set Young's modulus = 1e4
        set Poisson's ratio = 0.3
      end
    end
  end
end)";
  }

  /// Order-independent checksum of every particle's id and mass (or, with
  /// @p everything, also its location, reference location and all
  /// properties), summed over the ranks modulo 2^64.
  template <int dim>
  std::uint64_t
  checksum(Simulator<dim> &sim, const bool everything)
  {
    auto mix = [](std::uint64_t h, const double v) {
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      return (h ^ bits) * 1099511628211ull;
    };
    std::uint64_t local = 0;
    for (const auto &p : sim.particles())
      {
        std::uint64_t h     = 14695981039346656037ull ^ p.get_id();
        const auto    props = p.get_properties();
        h                   = mix(h, props[ParticleLayout<dim>::mass]);
        if (everything)
          {
            for (unsigned int d = 0; d < dim; ++d)
              h =
                mix(mix(h, p.get_location()[d]), p.get_reference_location()[d]);
            for (const double v : props)
              h = mix(h, v);
          }
        local += h;
      }
    std::uint64_t global = 0;
    MPI_Allreduce(&local, &global, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    return global;
  }

  /// Location and properties of every particle by id (rank 0; empty on
  /// the others).
  template <int dim>
  std::map<types::particle_index, std::vector<double>>
  gather_particles(Simulator<dim> &sim)
  {
    std::vector<double> local;
    for (const auto &p : sim.particles())
      {
        local.push_back(p.get_id());
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(p.get_location()[d]);
        for (const double v : p.get_properties())
          local.push_back(v);
      }
    const auto         all = Utilities::MPI::gather(MPI_COMM_WORLD, local, 0);
    const unsigned int n =
      1 + dim + sim.particles().n_properties_per_particle();
    std::map<types::particle_index, std::vector<double>> out;
    for (const auto &from : all)
      for (std::size_t i = 0; i < from.size(); i += n)
        out[static_cast<types::particle_index>(from[i])] =
          std::vector<double>(from.begin() + i + 1, from.begin() + i + n);
    return out;
  }

  /// Largest difference of a slot between two runs, relative to the
  /// largest magnitude of that slot.
  double
  largest_difference(
    const std::map<types::particle_index, std::vector<double>> &a,
    const std::map<types::particle_index, std::vector<double>> &b)
  {
    if (a.size() != b.size())
      return 1e300;
    if (a.empty())
      return 0;
    const std::size_t   n = a.begin()->second.size();
    std::vector<double> scale(n, 0.), diff(n, 0.);
    for (const auto &[id, va] : a)
      {
        const auto it = b.find(id);
        if (it == b.end())
          return 1e300;
        for (std::size_t k = 0; k < n; ++k)
          {
            scale[k] = std::max(scale[k], std::abs(va[k]));
            diff[k]  = std::max(diff[k], std::abs(va[k] - it->second[k]));
          }
      }
    double worst = 0;
    for (std::size_t k = 0; k < n; ++k)
      if (scale[k] > 0)
        worst = std::max(worst, diff[k] / scale[k]);
    return worst;
  }

  std::string
  counts(const ParticleBalance &b)
  {
    return "min " + std::to_string(b.min) + ", max " + std::to_string(b.max) +
           " of " + std::to_string(b.total);
  }

  template <int dim>
  void
  compare(const std::string &variant, const unsigned int n_steps)
  {
    const std::string   tag = std::to_string(dim) + "D " + variant + ": ";
    mpm_test::Case<dim> plain(case_text<dim>(variant, 0, false));
    mpm_test::Case<dim> balanced(case_text<dim>(variant, 4));
    auto               &a = *plain.simulator;
    auto               &b = *balanced.simulator;

    const auto   sum0 = checksum(b, false);
    const auto   s0   = b.statistics();
    const double dt   = 0.3 * a.stable_time_step();
    for (unsigned int n = 0; n < n_steps; ++n)
      {
        a.do_time_step(dt);
        b.do_time_step(dt);
      }
    const auto sa = a.statistics(), sb = b.statistics();

    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const auto ba = LoadBalancer<dim>::balance(a.particles(), MPI_COMM_WORLD);
    const auto bb = LoadBalancer<dim>::balance(b.particles(), MPI_COMM_WORLD);
    mpm_test::log() << tag << "particles per rank after " << n_steps
                    << " steps without repartitioning: " << counts(ba)
                    << "; with " << b.load_balancer()->n_repartitions
                    << " repartitions: " << counts(bb) << std::endl;
    mpm_test::check(n_ranks == 1 || bb.imbalance() < 1.15,
                    tag + "balanced at the end (largest / mean)",
                    bb.imbalance(),
                    1.15);
    mpm_test::check(checksum(b, false) == sum0 && checksum(a, false) == sum0,
                    tag + "every particle's mass carried bit for bit",
                    0,
                    0);
    // The sums over the particles differ by their order on the ranks.
    mpm_test::check_small(tag + "total mass, relative",
                          (sb.mass - sa.mass) / sa.mass,
                          1e-13);
    mpm_test::check_small(tag + "total mass unchanged, relative",
                          (sb.mass - s0.mass) / s0.mass,
                          1e-13);
    const double p_scale = std::sqrt(2 * sa.mass * sa.kinetic_energy);
    double       dp      = 0;
    for (unsigned int d = 0; d < dim; ++d)
      dp = std::max(dp, std::abs(sb.momentum[d] - sa.momentum[d]));
    mpm_test::check_small(tag + "momentum, relative", dp / p_scale, 1e-12);
    mpm_test::check_small(tag + "kinetic energy, relative",
                          (sb.kinetic_energy - sa.kinetic_energy) /
                            sa.kinetic_energy,
                          1e-12);
    mpm_test::check_small(tag + "strain energy, relative",
                          (sb.strain_energy - sa.strain_energy) /
                            sa.strain_energy,
                          1e-11);
    const auto   pa = gather_particles(a), pb = gather_particles(b);
    const double d =
      Utilities::MPI::broadcast(MPI_COMM_WORLD, largest_difference(pa, pb), 0);
    mpm_test::check_small(tag + "every property of every particle, relative to "
                                "its largest magnitude",
                          d,
                          1e-10);
    mpm_test::log() << tag << std::scientific << std::setprecision(6) << "Ekin "
                    << sb.kinetic_energy << ", Estrain " << sb.strain_energy
                    << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);

  // (a) the body in the corner, and the default repartition at set-up
  // moving every particle
  {
    mpm_test::Case<2> c(case_text<2>("standard", 0));
    auto             &sim = *c.simulator;
    const auto       &b   = sim.balance_at_setup();
    mpm_test::log() << "particles per rank at set-up, cells balanced: "
                    << counts(b[0]) << std::endl
                    << "after the repartition by weight: " << counts(b[1])
                    << std::endl;
    mpm_test::check(n_ranks == 1 || b[0].imbalance() > 1.9,
                    "unbalanced before (largest / mean)",
                    b[0].imbalance(),
                    1.9);
    mpm_test::check(b[1].imbalance() < 1.15,
                    "particles balanced after (largest / mean)",
                    b[1].imbalance(),
                    1.15);
    // The cells' weights (1 per cell, 10 per particle) are what p4est
    // balances; the particle counts differ by the empty cells each rank
    // holds, and p4est keeps groups of 2^dim sibling cells together.
    unsigned long long weight = 0;
    for (const auto &cell : sim.grid().triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        weight += sim.load_balancer()->weight(
          sim.particles().n_particles_in_cell(cell));
    const double mean =
      Utilities::MPI::sum(weight, MPI_COMM_WORLD) / double(n_ranks);
    const double largest = Utilities::MPI::max(weight, MPI_COMM_WORLD);
    mpm_test::check(largest / mean < 1.03,
                    "weights balanced after (largest / mean)",
                    largest / mean,
                    1.03);
    const auto before = checksum(sim, true);
    sim.repartition();
    mpm_test::check(checksum(sim, true) == before,
                    "a repartition carries location, reference location "
                    "and every property bit for bit",
                    0,
                    0);
  }

  // (b) with and without repartitioning
  for (const std::string variant :
       {"standard", "filter", "theta-bar node", "uGIMP", "CPDI"})
    compare<2>(variant, 60);
  compare<3>("standard", 30);
}
