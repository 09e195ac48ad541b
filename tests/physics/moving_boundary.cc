// A moving grid boundary in the implicit steps (Boundary
// conditions/Moving boundary ids and Moving boundary velocity).
//
// Uniaxial strain: a linear elastic block (E = 1e6, nu = 0.3) that fills
// the grid (h = 0.25) between slip walls, its top face moved down by 1%
// of the height in one step, in 2D (plane strain) and 3D. The boundary's
// reaction (boundary_reaction_y) is the block's stress times the top's
// area, -(lambda + 2 mu) 0.01, to 1e-9: the top is on a node row and
// each cell holds whole rows of particles, so the particles integrate the
// uniform stress exactly.
//
// Patch test: every face of the 2D grid moves with the linear velocity
// v = A x (stretch, shear and compression at once), four steps. The
// particles end at (I + A dt)^4 X to round-off (each step moves the grid
// nodes, and so the particles, by A dt x), and their stresses are one
// uniform stress.
//
// Newmark: every face moves with the simple shear v = (g y, 0) the body
// starts with, ten steps. The flow has no acceleration: the particles keep
// their velocity g Y, end at X + g t Y, and carry one uniform stress.
#include <algorithm>
#include <cmath>

#include "../tests.h"
#include "moving_block.h"

namespace
{
  template <int dim>
  std::string
  block(const std::string &slip,
        const std::string &moving,
        const std::string &velocity,
        const std::string &step)
  {
    return mpm_test::moving_block<dim>(
      slip, moving, velocity, step, "linear elastic");
  }

  template <int dim>
  void
  uniaxial_strain()
  {
    mpm_test::Case<dim> c(dim == 2 ?
                            block<2>("0, 1, 2", "3", "0; -0.01", "1") :
                            block<3>("0, 1, 2, 4, 5", "3", "0; -0.01; 0", "1"));
    c.simulator->do_time_step(1);
    const double E = 1e6, nu = 0.3;
    const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    const double reaction =
      mpm_test::integrator_value(*c.simulator, "boundary_reaction_y");
    // (round-off, which differs with the number of ranks: no value
    // printed)
    mpm_test::report(std::abs(reaction / (-M * 0.01) - 1) < 1e-9,
                     std::to_string(dim) +
                       "D uniaxial strain: boundary_reaction_y = "
                       "-(lambda + 2 mu) 0.01 |top| (1e-9 relative)",
                     reaction / (-M * 0.01) - 1);
  }

  void
  patch_test()
  {
    const double      A[2][2] = {{0.004, 0.01}, {0.002, -0.006}};
    const double      dt      = 0.25;
    mpm_test::Case<2> c(block<2>(
      "", "0, 1, 2, 3", "0.004*x + 0.01*y; 0.002*x - 0.006*y", "0.25"));
    auto             &sim = *c.simulator;
    for (unsigned int k = 0; k < 4; ++k)
      sim.do_time_step(dt);
    using L               = mpm::ParticleLayout<2>;
    double position_error = 0;
    double stress_spread = 0, stress_scale = 0;
    double first_stress[6] = {};
    bool   first           = true;
    for (const auto &p : sim.particles())
      {
        const double *prop = p.get_properties().data();
        double        x[2] = {prop[L::X], prop[L::X + 1]};
        for (unsigned int k = 0; k < 4; ++k)
          {
            const double y[2] = {x[0] + dt * (A[0][0] * x[0] + A[0][1] * x[1]),
                                 x[1] + dt * (A[1][0] * x[0] + A[1][1] * x[1])};
            x[0]              = y[0];
            x[1]              = y[1];
          }
        for (unsigned int d = 0; d < 2; ++d)
          position_error =
            std::max(position_error, std::abs(p.get_location()[d] - x[d]));
        for (unsigned int s = 0; s < 6; ++s)
          {
            if (first)
              first_stress[s] = prop[L::stress + s];
            stress_spread =
              std::max(stress_spread,
                       std::abs(prop[L::stress + s] - first_stress[s]));
            stress_scale = std::max(stress_scale, std::abs(first_stress[s]));
          }
        first = false;
      }
    // (every rank compares with its own first particle: the spread over
    // all ranks is at most twice the largest)
    position_error =
      dealii::Utilities::MPI::max(position_error, MPI_COMM_WORLD);
    stress_spread = dealii::Utilities::MPI::max(stress_spread, MPI_COMM_WORLD);
    stress_scale  = dealii::Utilities::MPI::max(stress_scale, MPI_COMM_WORLD);
    mpm_test::report(position_error < 1e-12,
                     "patch test: particles at (I + A dt)^4 X (1e-12)",
                     position_error);
    mpm_test::report(stress_spread < 1e-9 * stress_scale,
                     "patch test: one uniform stress (1e-9 relative)",
                     stress_spread / stress_scale);
    mpm_test::check(stress_scale > 1e3,
                    "patch test: the stress is not zero",
                    stress_scale,
                    1e3);
  }
} // namespace

namespace
{
  /// Newmark: every face moves with the simple shear v = (g y, 0) that
  /// the body starts with, ten steps. The flow has no acceleration, so the
  /// particles keep their velocity g Y and end at X + g t Y; their stress
  /// is uniform.
  void
  newmark_shear()
  {
    const double      g = 0.05, dt = 0.01;
    mpm_test::Case<2> c(mpm_test::newmark_shear_block("linear elastic"));
    auto             &sim = *c.simulator;
    for (unsigned int k = 0; k < 10; ++k)
      sim.do_time_step(dt);
    using L               = mpm::ParticleLayout<2>;
    double position_error = 0, velocity_error = 0, spread = 0, scale = 0;
    double first = std::nan("");
    for (const auto &p : sim.particles())
      {
        const double *prop = p.get_properties().data();
        const double  t    = sim.time();
        position_error =
          std::max({position_error,
                    std::abs(p.get_location()[0] -
                             (prop[L::X] + g * t * prop[L::X + 1])),
                    std::abs(p.get_location()[1] - prop[L::X + 1])});
        velocity_error =
          std::max({velocity_error,
                    std::abs(prop[L::velocity] - g * prop[L::X + 1]),
                    std::abs(prop[L::velocity + 1])});
        const double s_xy = prop[L::stress + 5];
        if (std::isnan(first))
          first = s_xy;
        spread = std::max(spread, std::abs(s_xy - first));
        scale  = std::max(scale, std::abs(s_xy));
      }
    position_error =
      dealii::Utilities::MPI::max(position_error, MPI_COMM_WORLD);
    velocity_error =
      dealii::Utilities::MPI::max(velocity_error, MPI_COMM_WORLD);
    spread = dealii::Utilities::MPI::max(spread, MPI_COMM_WORLD);
    scale  = dealii::Utilities::MPI::max(scale, MPI_COMM_WORLD);
    mpm_test::report(position_error < 1e-12,
                     "Newmark shear: particles at X + g t Y (1e-12)",
                     position_error);
    mpm_test::report(velocity_error < 1e-10,
                     "Newmark shear: velocities g Y (1e-10)",
                     velocity_error);
    mpm_test::report(spread < 1e-9 * scale,
                     "Newmark shear: one uniform shear stress (1e-9 relative)",
                     spread / scale);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  uniaxial_strain<2>();
  uniaxial_strain<3>();
  patch_test();
  newmark_shear();
}
