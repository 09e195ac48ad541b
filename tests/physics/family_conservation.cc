// Every shape-function family (standard, uGIMP, cpGIMP, CPDI, CPDI2)
// conserves mass and linear momentum in P2G and G2P: two blocks, one of
// them spinning, collide in the middle of the grid (no boundary
// conditions, no external force), for USF, USL and MUSL with FLIP and
// PIC. In every step the grid mass and momentum of a P2G pass with the
// family's weights equal the particles' to round-off (sum_i S_ip = 1),
// and over the steps the particles' momentum does not change (the nodal
// forces sum to zero, sum_i grad S_ip = 0, and G2P uses the weights of
// P2G). On 2 ranks the domains reach into the other rank's cells, and the
// output is the same as on one.
#include <mpm/particles/cell_loop.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/transfer/particle_to_grid.h>

#include <set>

#include "../tests.h"
#include "colliding_blocks.h"

namespace
{
  using namespace dealii;
  using namespace mpm;
  constexpr int dim = 2;

  struct GridCheck
  {
    double mass_error     = 0; ///< |sum m_i - sum m_p| / sum m_p
    double momentum_error = 0; ///< |sum p_i - sum m_p v_p| / p_scale
    unsigned long long reaching_ghosts = 0; ///< particles (all ranks)
    bool               ok              = true;
  };

  /// One P2G pass with the family's weights (standard: null), compared
  /// with the particle sums; counts the particles whose domain reaches
  /// nodes of cells this rank does not own.
  GridCheck
  check_grid(Simulator<dim>                                   &sim,
             const shape_functions::DomainShapeFunctions<dim> *domains)
  {
    using P           = transfer::P2GLayout<dim>;
    const auto &grid  = sim.grid();
    const auto  stats = sim.statistics();
    NodalVector nodal;
    grid.initialize_vector(nodal, P::n_components);
    const std::string error =
      transfer::particle_to_grid(grid,
                                 sim.particles(),
                                 sim.get_bodies(),
                                 sim.time(),
                                 transfer::P2GContent::mass_momentum,
                                 nodal,
                                 static_cast<remedies::StressFilter<dim> *>(
                                   nullptr),
                                 domains);
    double local[1 + dim] = {};
    for (unsigned int i = 0; i < grid.n_owned_nodes(); ++i)
      for (unsigned int c = 0; c < 1 + dim; ++c)
        local[c] += nodal.local_element(i * P::n_components + c);

    // nodes of the owned cells, and the particles reaching beyond them
    unsigned long long reaching = 0;
    if (domains)
      {
        std::set<unsigned int> own;
        for (const auto &cell : grid.triangulation().active_cell_iterators())
          if (cell->is_locally_owned())
            own.insert(grid.nodes(cell), grid.nodes(cell) + 4);
        shape_functions::Stencil<dim> s;
        for_each_cell_with_particles(
          grid, sim.particles(), [&](const auto &cell, const auto &pic) {
            for (const auto &p : pic)
              {
                if (domains->evaluate(cell->active_cell_index(),
                                      p.get_reference_location(),
                                      p.get_properties().data(),
                                      s) !=
                    shape_functions::DomainShapeFunctions<dim>::Status::ok)
                  continue;
                for (unsigned int k = 0; k < s.n; ++k)
                  if (own.count(s.node[k]) == 0)
                    {
                      ++reaching;
                      break;
                    }
              }
          });
      }

    GridCheck r;
    double    global[1 + dim];
    Utilities::MPI::sum(ArrayView<const double>(local, 1 + dim),
                        MPI_COMM_WORLD,
                        ArrayView<double>(global, 1 + dim));
    r.reaching_ghosts = Utilities::MPI::sum(reaching, MPI_COMM_WORLD);
    r.ok = Utilities::MPI::min(error.empty() ? 1 : 0, MPI_COMM_WORLD) == 1;
    const double p_scale = std::sqrt(2 * stats.mass * stats.kinetic_energy);
    r.mass_error         = std::abs(global[0] - stats.mass) / stats.mass;
    for (unsigned int d = 0; d < dim; ++d)
      r.momentum_error =
        std::max(r.momentum_error,
                 std::abs(global[1 + d] - stats.momentum[d]) / p_scale);
    return r;
  }

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  for (const std::string family :
       {"standard", "uGIMP", "cpGIMP", "CPDI", "CPDI2"})
    for (const std::string scheme : {"USF", "USL", "MUSL"})
      for (const std::string flip : {"1", "0"})
        {
          mpm_test::Case<dim> c(
            mpm_test::colliding_blocks("set Family = " + family,
                                       "set Scheme = " + scheme +
                                         "\nset FLIP fraction = " + flip),
            2);
          auto &sim = *c.simulator;

          // the family's weights, as the simulator builds them
          const auto f = shape_functions::parse_family(family);
          std::unique_ptr<shape_functions::DomainShapeFunctions<dim>> domains;
          if (f != shape_functions::Family::standard)
            {
              ParticleLayout<dim> layout;
              for (const auto &body : sim.get_bodies())
                layout.n_history =
                  std::max(layout.n_history, body.material->n_history());
              layout.has_corners = f == shape_functions::Family::cpdi2;
              domains =
                std::make_unique<shape_functions::DomainShapeFunctions<dim>>(
                  sim.grid(), f, false, layout.corners());
            }

          const auto   s0 = sim.statistics();
          const double dt = 0.2 * sim.stable_time_step();
          GridCheck    worst;
          for (unsigned int n = 0; n < 20; ++n)
            {
              const GridCheck g = check_grid(sim, domains.get());
              worst.ok          = worst.ok && g.ok;
              worst.mass_error  = std::max(worst.mass_error, g.mass_error);
              worst.momentum_error =
                std::max(worst.momentum_error, g.momentum_error);
              worst.reaching_ghosts += g.reaching_ghosts;
              sim.do_time_step(dt);
            }
          const auto   s1      = sim.statistics();
          const double p_scale = std::sqrt(2 * s0.mass * s0.kinetic_energy);
          double       dp      = 0;
          for (unsigned int d = 0; d < dim; ++d)
            dp = std::max(dp, std::abs(s1.momentum[d] - s0.momentum[d]));

          const std::string tag =
            family + ", " + scheme + ", FLIP " + flip + ": ";
          mpm_test::report(worst.ok, tag + "every P2G pass succeeds", 0);
          mpm_test::report(worst.mass_error <= 1e-14,
                           tag +
                             "grid mass = particle mass in every step (1e-14)",
                           worst.mass_error);
          mpm_test::report(worst.momentum_error <= 1e-13,
                           tag +
                             "grid momentum = particle momentum in every step "
                             "(1e-13)",
                           worst.momentum_error);
          mpm_test::report(s1.mass == s0.mass,
                           tag + "particle mass unchanged",
                           0);
          mpm_test::report(dp / p_scale <= 1e-12,
                           tag + "momentum conserved over 20 steps (1e-12)",
                           dp / p_scale);
          mpm_test::report(f == shape_functions::Family::standard ||
                             n_ranks == 1 || worst.reaching_ghosts > 0,
                           tag +
                             "on 2 ranks, domains reach the other rank's cells",
                           worst.reaching_ghosts);
          // the dynamics, to compare 1 and 2 ranks
          mpm_test::log() << tag << std::scientific << std::setprecision(6)
                          << "Ekin " << s0.kinetic_energy << " -> "
                          << s1.kinetic_energy << ", Estrain "
                          << s1.strain_energy << ", Lz "
                          << s1.angular_momentum[2] << std::endl;
        }
}
