// The stencil cache of the particle-domain families (Shape functions/
// Cache stencils, shape_functions/stencil_cache.h) changes nothing but the
// time: for uGIMP, cpGIMP, CPDI and CPDI2 with USF, USL and MUSL, two
// colliding blocks (one with the node theta-bar, whose stress update walks
// the particles twice) run 30 steps with the cache and without it, and
// every particle's position, velocity and stress agree to round-off (the
// cache merges GIMP's repeated nodes, so sums run in another order). On 2
// ranks the domains reach into the other rank's cells. The cache must
// hold stencils at the end (it is used), and a stale cache would show: USF
// with cpGIMP and CPDI changes the domains within the step.
#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>

#include <map>

#include "../tests.h"
#include "colliding_blocks.h"

namespace
{
  using namespace dealii;
  using namespace mpm;
  constexpr int dim = 2;

  /// Position, velocity and in-plane stress of every particle, by id,
  /// from all ranks.
  std::map<types::particle_index, std::vector<double>>
  state(Simulator<dim> &sim)
  {
    using L = ParticleLayout<dim>;
    std::vector<std::pair<types::particle_index, std::vector<double>>> local;
    for (const auto &p : sim.particles())
      {
        const double       *prop = p.get_properties().data();
        std::vector<double> v;
        for (unsigned int d = 0; d < dim; ++d)
          v.push_back(p.get_location()[d]);
        for (unsigned int d = 0; d < dim; ++d)
          v.push_back(prop[L::velocity + d]);
        for (const unsigned int c : {0u, 1u, 5u}) // xx yy xy
          v.push_back(prop[L::stress + c]);
        local.emplace_back(p.get_id(), v);
      }
    std::map<types::particle_index, std::vector<double>> all;
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
      for (const auto &[id, v] : part)
        all[id] = v;
    return all;
  }

  std::string
  case_text(const std::string &family,
            const std::string &scheme,
            const bool         cache)
  {
    return mpm_test::colliding_blocks(
      "set Family = " + family +
        "\nset Cache stencils = " + (cache ? "true" : "false"),
      "set Scheme = " + scheme,
      "subsection Locking remedies\nset Volumetric smoothing = node\nend");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string family : {"uGIMP", "cpGIMP", "CPDI", "CPDI2"})
    for (const std::string scheme : {"USF", "USL", "MUSL"})
      {
        mpm_test::Case<dim> with(case_text(family, scheme, true), 2);
        mpm_test::Case<dim> without(case_text(family, scheme, false), 2);
        const double        dt = 0.2 * with.simulator->stable_time_step();
        for (unsigned int n = 0; n < 30; ++n)
          {
            with.simulator->do_time_step(dt);
            without.simulator->do_time_step(dt);
          }
        const auto a = state(*with.simulator), b = state(*without.simulator);
        // each column's difference relative to its largest value
        std::vector<double> scale(7, 0.), diff(7, 0.);
        for (const auto &[id, v] : b)
          for (unsigned int k = 0; k < v.size(); ++k)
            {
              scale[k] = std::max(scale[k], std::abs(v[k]));
              diff[k]  = std::max(diff[k], std::abs(a.at(id)[k] - v[k]));
            }
        double worst = 0;
        for (unsigned int k = 0; k < 7; ++k)
          worst = std::max(worst, diff[k] / scale[k]);
        const std::string tag = family + ", " + scheme + ": ";
        mpm_test::report(a.size() == b.size() && a.size() == 128,
                         tag + "the same 128 particles",
                         a.size());
        mpm_test::report(worst <= 1e-12,
                         tag +
                           "cached = rebuilt stencils (x, v, stress; 1e-12)",
                         worst);
        const double held = Utilities::MPI::max(
          static_cast<double>(
            with.simulator->domain_shape_functions()->memory_consumption()),
          MPI_COMM_WORLD);
        mpm_test::report(held > 0, tag + "the cache holds stencils", held);
      }
}
