// Locking remedies/Particle volume with Volumetric smoothing = cell, one
// explicit step of a body moving with a non-uniform velocity (linear
// elastic: the rate form; neo-Hookean: F-bar). With `smoothed` every
// particle of a cell leaves the step with the cell's volume ratio, V / V0 =
// J_bar, and det F = V / V0; the cells' volumes are those of `own`, whose
// particles keep their own volumes (the check that the test can fail:
// their V / V0 varies in a cell).
#include <cmath>
#include <map>

#include "../tests.h"

namespace
{
  struct Volumes
  {
    double spread   = 0; ///< largest spread of V / V0 in one cell
    double mismatch = 0; ///< largest |det F - V / V0|
    double total    = 0; ///< sum of V
  };

  Volumes
  volumes_after_one_step(const std::string &material,
                         const std::string &particle_volume)
  {
    mpm_test::Case<2> c(R"(
set Kinematic assumption = plane strain
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 8
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.25, 0.25
    set Upper corner = 0.75, 0.75
    set Subdivisions = 4
    set Particles per direction = 3
    set Initial velocity = 0.1*sin(5*x*y); 0.1*cos(4*x) + 0.05*y*y
    subsection Material
      set Model = )" + material +
                        R"(
      set Density = 1000
      subsection Linear elastic
        set Young's modulus = 1e6
        set Poisson's ratio = 0.49
      end
      subsection Neo-Hookean
        set Young's modulus = 1e6
        set Poisson's ratio = 0.49
      end
    end
    subsection Locking remedies
      set Volumetric smoothing = cell
      set Particle volume = )" +
                        particle_volume + R"(
    end
  end
end)");
    auto             &sim = *c.simulator;
    sim.do_time_step(0.1 * sim.stable_time_step());
    using L = mpm::ParticleLayout<2>;
    std::map<unsigned int, std::pair<double, double>> range;
    Volumes                                           v;
    for (const auto &p : sim.particles())
      {
        const double *prop  = p.get_properties().data();
        const double  ratio = prop[L::volume] / prop[L::volume0];
        v.total += prop[L::volume];
        v.mismatch =
          std::max(v.mismatch,
                   std::abs(determinant(mpm::load_matrix<2>(prop + L::F)) -
                            ratio));
        const auto c  = p.get_surrounding_cell()->active_cell_index();
        auto       it = range.find(c);
        if (it == range.end())
          range[c] = {ratio, ratio};
        else
          it->second = {std::min(it->second.first, ratio),
                        std::max(it->second.second, ratio)};
      }
    for (const auto &[cell, r] : range)
      v.spread = std::max(v.spread, r.second - r.first);
    v.spread   = dealii::Utilities::MPI::max(v.spread, MPI_COMM_WORLD);
    v.mismatch = dealii::Utilities::MPI::max(v.mismatch, MPI_COMM_WORLD);
    v.total    = dealii::Utilities::MPI::sum(v.total, MPI_COMM_WORLD);
    return v;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string material : {"linear elastic", "neo-Hookean"})
    {
      const Volumes     own      = volumes_after_one_step(material, "own");
      const Volumes     smoothed = volumes_after_one_step(material, "smoothed");
      const std::string tag      = material + ": ";
      mpm_test::check(own.spread > 1e-6,
                      tag + "own: V / V0 varies in a cell",
                      own.spread,
                      1e-6);
      // (round-off, which differs with the number of ranks: no value
      // printed)
      mpm_test::report(smoothed.spread < 1e-13,
                       tag + "smoothed: V / V0 is one per cell (1e-13)",
                       smoothed.spread);
      mpm_test::report(smoothed.mismatch < 1e-13,
                       tag + "smoothed: det F = V / V0 (1e-13)",
                       smoothed.mismatch);
      mpm_test::report(std::abs(smoothed.total / own.total - 1) < 1e-13,
                       tag + "smoothed: the total volume of own (1e-13)",
                       smoothed.total / own.total - 1);
    }
}
