// Filtered stress = force only (theory 4.13): the assumed-stress
// projection makes the same internal force as the written-back filter,
// for uGIMP and CPDI (it needs APIC, so a particle-domain family), but
// the particles keep the stresses their material computed. The body carries a quadratic stress
// field, which the Pian-Sumihara field cannot represent, so the
// written-back filter must change the particle stresses and the
// force-only one must not. Serial and on 2 ranks.
#include <mpm/remedies/stress_filter.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/transfer/particle_to_grid.h>

#include "../tests.h"

namespace
{
  using namespace dealii;
  using namespace mpm;
  constexpr int dim = 2;
  using L           = ParticleLayout<dim>;

  struct ForceAndStress
  {
    NodalVector         force;       ///< the P2G force components
    std::vector<double> initial_sxx; ///< particle sigma_xx before P2G
    std::vector<double> stress_sxx;  ///< particle sigma_xx after P2G
    double              stress_norm; ///< max |sigma| before P2G
  };

  ForceAndStress
  internal_force(const std::string &family, const std::string &target)
  {
    // force only needs APIC, which needs a particle-domain family
    const std::string   transfer = "APIC";
    mpm_test::Case<dim> c(R"(
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 8
end
subsection Shape functions
  set Family = )" + family +
                          R"(
end
subsection Time stepping
  set Velocity transfer = )" +
                          transfer + R"(
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.13, 0.21
    set Upper corner = 0.83, 0.76
    set Subdivisions = 7, 5
    set Particles per direction = 2
    set Initial stress = 1e3*x*x; -2e3*y*y + 300*x; 500*x*y
    subsection Material
      set Model = linear elastic
      set Density = 1000
    end
    subsection Locking remedies
      set Stress filter = assumed stress
      set Filtered stress = )" +
                          target + R"(
    end
  end
end)");
    auto               &sim = *c.simulator;

    std::unique_ptr<shape_functions::DomainShapeFunctions<dim>> domains;
    const auto f = shape_functions::parse_family(family);
    if (f != shape_functions::Family::standard)
      domains = std::make_unique<shape_functions::DomainShapeFunctions<dim>>(
        sim.grid(), f, false, ParticleLayout<dim>().corners());
    remedies::StressFilter<dim> filter(sim.get_bodies());

    ForceAndStress r;
    r.stress_norm = 0;
    for (const auto &p : sim.particles())
      r.initial_sxx.push_back(p.get_properties()[L::stress]);
    for (const auto &p : sim.particles())
      for (unsigned int k = 0; k < 6; ++k)
        r.stress_norm =
          std::max(r.stress_norm, std::abs(p.get_properties()[L::stress + k]));
    r.stress_norm = Utilities::MPI::max(r.stress_norm, MPI_COMM_WORLD);

    sim.grid().initialize_vector(r.force,
                                 transfer::P2GLayout<dim>::n_components);
    const std::string error =
      transfer::particle_to_grid(sim.grid(),
                                 sim.particles(),
                                 sim.get_bodies(),
                                 0.,
                                 transfer::P2GContent::mass_momentum_force,
                                 r.force,
                                 &filter,
                                 domains.get());
    AssertThrow(error.empty(), ExcMessage(error));
    for (const auto &p : sim.particles())
      r.stress_sxx.push_back(p.get_properties()[L::stress]);
    return r;
  }

  /// max |a - b| over the force components, over all ranks
  double
  force_difference(const NodalVector &a, const NodalVector &b, double &scale)
  {
    using P      = transfer::P2GLayout<dim>;
    double diff  = 0;
    double local = 0;
    for (unsigned int i = 0; i < a.locally_owned_size() / P::n_components; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        {
          const unsigned int k = i * P::n_components + P::force + d;
          diff =
            std::max(diff, std::abs(a.local_element(k) - b.local_element(k)));
          local = std::max(local, std::abs(a.local_element(k)));
        }
    scale = Utilities::MPI::max(local, MPI_COMM_WORLD);
    return Utilities::MPI::max(diff, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string family : {"uGIMP", "CPDI"})
    {
      const auto written = internal_force(family, "written back");
      const auto force   = internal_force(family, "force only");

      double       scale = 0;
      const double df    = force_difference(written.force, force.force, scale);
      mpm_test::check_small(family + ": force only gives the written-back "
                                     "filter's internal force (relative)",
                            df / scale,
                            1e-12);

      // The particle stresses: changed by the written-back filter,
      // untouched by the force-only one.
      double changed = 0, kept = 0;
      for (unsigned int k = 0; k < written.stress_sxx.size(); ++k)
        {
          changed =
            std::max(changed,
                     std::abs(written.stress_sxx[k] - written.initial_sxx[k]));
          kept = std::max(kept,
                          std::abs(force.stress_sxx[k] - force.initial_sxx[k]));
        }
      changed = Utilities::MPI::max(changed, MPI_COMM_WORLD);
      kept    = Utilities::MPI::max(kept, MPI_COMM_WORLD);
      mpm_test::check(changed > 1e-3 * written.stress_norm,
                      family + ": written back changes a quadratic stress "
                               "field (max |change| / max |sigma|)",
                      changed / written.stress_norm,
                      1e-3);
      mpm_test::check_small(family + ": force only keeps the particle stresses",
                            kept,
                            0.);
    }
}
