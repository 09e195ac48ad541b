// Implicit solver/Geometry = small strain: the fixed geometry with
// linearized kinematics. The materials see the symmetric part of the
// step's displacement gradient as their strain increment, the stress does
// not turn, and the force is sigma on the initial volumes.
//
// Uniaxial strain: a linear elastic block (E = 1e6, nu = 0.3) that fills
// the grid between slip walls, its top face moved down by 2% of the
// height in each of five steps, in 2D (plane strain) and 3D: the
// boundary's reaction is (lambda + 2 mu) 0.1 |top| exactly (the fixed
// geometry's is 0.98^5 times that, through the current volume).
//
// Simple shear: every face moves with v = (g y, 0), g = 0.02, ten steps.
// Linear elastic: sigma_xy = mu g t and no normal stress (the rotation of
// the finite-strain update would give sigma_xx = -sigma_yy of order
// mu (g t)^2). Von Mises (sigma_y = 1e4, no hardening): the shear stress
// stops at sigma_y / sqrt 3 exactly once the block yields.
#include <algorithm>
#include <cmath>

#include "../tests.h"
#include "moving_block.h"

namespace
{
  const std::string small_strain =
    "subsection Implicit solver\n  set Geometry = small strain\nend\n";

  /// The largest |sigma_ij - expected_ij| over the particles (all ranks).
  double
  stress_deviation(mpm::Simulator<2>                   &sim,
                   const dealii::SymmetricTensor<2, 3> &expected)
  {
    using L      = mpm::ParticleLayout<2>;
    double error = 0;
    for (const auto &p : sim.particles())
      {
        const auto sigma =
          mpm::load_stress(p.get_properties().data() + L::stress);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            error = std::max(error, std::abs(sigma[i][j] - expected[i][j]));
      }
    return dealii::Utilities::MPI::max(error, MPI_COMM_WORLD);
  }

  template <int dim>
  void
  uniaxial_strain()
  {
    mpm_test::Case<dim> c(
      (dim == 2 ?
         mpm_test::moving_block<2>(
           "0, 1, 2", "3", "0; -0.02", "1", "linear elastic") :
         mpm_test::moving_block<3>(
           "0, 1, 2, 4, 5", "3", "0; -0.02; 0", "1", "linear elastic")) +
      small_strain);
    for (unsigned int k = 0; k < 5; ++k)
      c.simulator->do_time_step(1);
    const double E = 1e6, nu = 0.3;
    const double mu     = E / (2 * (1 + nu)),
                 lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    // |top| = 1; the reaction balances the compressive stress
    const double expected = -(lambda + 2 * mu) * 0.1;
    const double reaction =
      mpm_test::integrator_value(*c.simulator, "boundary_reaction_y");
    const std::string what = std::to_string(dim) + "D uniaxial strain: ";
    mpm_test::report(std::abs(reaction / expected - 1) < 1e-9,
                     what + "boundary_reaction_y = (lambda + 2 mu) 0.1 |top| "
                            "(1e-9 relative)",
                     reaction / expected - 1);
  }

  /// The shear block of @p model after ten steps of 0.1 (g t = 0.02),
  /// its particles' largest deviation from @p expected.
  double
  sheared(const std::string                   &model,
          const dealii::SymmetricTensor<2, 3> &expected)
  {
    std::string text =
      mpm_test::moving_block<2>("", "0, 1, 2, 3", "0.2*y; 0", "0.1", model) +
      small_strain;
    if (model == "von Mises plasticity")
      text += "subsection Bodies\n  subsection Body 0\n    subsection "
              "Material\n      subsection Von Mises plasticity\n        set "
              "Yield stress = 1e4\n      end\n    end\n  end\nend\n";
    mpm_test::Case<2> c(text);
    for (unsigned int k = 0; k < 10; ++k)
      c.simulator->do_time_step(0.1);
    return stress_deviation(*c.simulator, expected);
  }

  void
  simple_shear()
  {
    const double                  mu    = 1e6 / (2 * 1.3);
    const double                  gamma = 0.2;
    dealii::SymmetricTensor<2, 3> elastic;
    elastic[0][1]                  = mu * gamma;
    const double elastic_deviation = sheared("linear elastic", elastic);
    mpm_test::report(elastic_deviation < 1e-9 * mu * gamma,
                     "linear elastic simple shear: sigma_xy = mu gamma, no "
                     "normal stress (1e-9 of mu gamma)",
                     elastic_deviation);
    dealii::SymmetricTensor<2, 3> plastic;
    plastic[0][1]          = 1e4 / std::sqrt(3.);
    const double deviation = sheared("von Mises plasticity", plastic);
    mpm_test::report(deviation < 1e-9 * plastic[0][1],
                     "von Mises simple shear: sigma_xy = sigma_y / sqrt 3, "
                     "no normal stress (1e-9 of it)",
                     deviation);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  uniaxial_strain<2>();
  uniaxial_strain<3>();
  simple_shear();
}
