// Implicit solver/Geometry = fixed: the implicit steps find equilibrium
// in the undeformed shape; the particles stay where they start.
//
// Uniaxial strain: a neo-Hookean block (E = 1e6, nu = 0.3) that fills the
// grid between slip walls, its top face moved down by 2% of the height in
// each of five steps, in 2D (plane strain) and 3D. Every step's gradient
// is taken on the undeformed grid, h_yy = -0.02, so F_yy = 0.98^5 (and not
// the 0.9 of the moved geometry). The step's force f_a = V_n tau G_a, with
// tau = j sigma and V_n = 0.98^4 V_0, gives the boundary's reaction
// 0.98^5 sigma_yy(F) |top| to 1e-9, sigma = (mu (b - I) + lambda ln J I) /
// J: the current volume times the Cauchy stress on the undeformed grid,
// with no push-forward by the last step; every particle is still at its
// initial place, exactly.
//
// Newmark: every face moves with the simple shear v = (g y, 0) that the
// body starts with, ten steps. The particles keep their velocity g Y and
// their place.
#include <algorithm>
#include <cmath>

#include "../tests.h"
#include "moving_block.h"

namespace
{
  const std::string fixed =
    "subsection Implicit solver\n  set Geometry = fixed\nend\n";

  /// moving_block.h's block of neo-Hookean material in a fixed geometry.
  template <int dim>
  std::string
  block(const std::string &slip,
        const std::string &moving,
        const std::string &velocity)
  {
    return mpm_test::moving_block<dim>(
             slip, moving, velocity, "1", "neo-Hookean") +
           fixed;
  }

  /// The largest distance of a particle from its initial place (all ranks).
  template <int dim>
  double
  largest_motion(mpm::Simulator<dim> &sim)
  {
    using L       = mpm::ParticleLayout<dim>;
    double motion = 0;
    for (const auto &p : sim.particles())
      for (unsigned int d = 0; d < dim; ++d)
        motion = std::max(motion,
                          std::abs(p.get_location()[d] -
                                   p.get_properties()[L::X + d]));
    return dealii::Utilities::MPI::max(motion, MPI_COMM_WORLD);
  }

  template <int dim>
  void
  uniaxial_strain()
  {
    mpm_test::Case<dim> c(dim == 2 ?
                            block<2>("0, 1, 2", "3", "0; -0.02") :
                            block<3>("0, 1, 2, 4, 5", "3", "0; -0.02; 0"));
    for (unsigned int k = 0; k < 5; ++k)
      c.simulator->do_time_step(1);
    const double E = 1e6, nu = 0.3;
    const double mu       = E / (2 * (1 + nu)),
                 lambda   = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double F        = std::pow(0.98, 5);
    const double sigma_yy = (mu * (F * F - 1) + lambda * std::log(F)) / F;
    const double expected = std::pow(0.98, 5) * sigma_yy;
    const double reaction =
      mpm_test::integrator_value(*c.simulator, "boundary_reaction_y");
    const std::string what = std::to_string(dim) + "D uniaxial strain: ";
    // (round-off, which differs with the number of ranks: no value
    // printed)
    mpm_test::report(std::abs(reaction / expected - 1) < 1e-9,
                     what + "boundary_reaction_y = 0.98^5 sigma_yy(F_yy = "
                            "0.98^5) |top| (1e-9 relative)",
                     reaction / expected - 1);
    mpm_test::report(largest_motion(*c.simulator) == 0,
                     what + "every particle at its initial place",
                     largest_motion(*c.simulator));
  }

  void
  newmark_shear()
  {
    const double      g = 0.05, dt = 0.01;
    mpm_test::Case<2> c(mpm_test::newmark_shear_block("neo-Hookean") + fixed);
    auto             &sim = *c.simulator;
    for (unsigned int k = 0; k < 10; ++k)
      sim.do_time_step(dt);
    using L               = mpm::ParticleLayout<2>;
    double velocity_error = 0;
    for (const auto &p : sim.particles())
      {
        const double *prop = p.get_properties().data();
        velocity_error =
          std::max({velocity_error,
                    std::abs(prop[L::velocity] - g * prop[L::X + 1]),
                    std::abs(prop[L::velocity + 1])});
      }
    velocity_error =
      dealii::Utilities::MPI::max(velocity_error, MPI_COMM_WORLD);
    mpm_test::report(largest_motion(sim) == 0,
                     "Newmark shear: every particle at its initial place",
                     largest_motion(sim));
    mpm_test::report(velocity_error < 1e-10,
                     "Newmark shear: velocities g Y (1e-10)",
                     velocity_error);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  uniaxial_strain<2>();
  uniaxial_strain<3>();
  newmark_shear();
}
