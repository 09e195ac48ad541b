// A bar fixed at x = 0 and pulled by a surface traction t0 on its end face
// (body-mesh boundary id 1), brought to rest by mass-proportional damping.
// 1D, uniaxial stress, E = 100, rho = 1, L = 1, h = 0.1, 2 particles per
// cell. In 1D the internal force of a cell on its right node is
// sum_p V_p sigma_p / h with V_p = J_p h/2, and no particle changes cell
// here (the tip moves 0.2 h), so nodal equilibrium at rest gives exactly
// J sigma = t0 in every cell: the traction acts on the end face, which has
// moved past node 1.0 and so acts at the last point of its particle's
// cell, node 1.0, with the whole t0. (Applied at the particle next to the
// face instead, node 1.0 would get only N(x_t) t0 and the last
// cell's J sigma would be 0.95 t0.) Damping 20/s decays every mode like
// exp(-10 t): to 2e-9 after 2 s.
#include <mpm/particles/particle_layout.h>

#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using L = mpm::ParticleLayout<1>;
  mpm_test::Case<1> c(R"(
set Constants = t0=2
subsection Grid
  set Lower corner = 0
  set Upper corner = 1.5
  set Subdivisions = 15
end
subsection Time stepping
  set Damping coefficient = 20
  # PIC: grid damping cannot reach FLIP's particle-level velocity modes
  set FLIP fraction = 0
end
subsection Boundary conditions
  set Fixed boundary ids = 0
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0
    set Upper corner = 1
    set Subdivisions = 10
    set Traction = t0
    set Traction boundary ids = 1
    subsection Material
      set Model = linear elastic
      set Density = 1
      subsection Linear elastic
        set Young's modulus = 100
        set Poisson's ratio = 0
      end
    end
  end
end)");
  auto             &sim = *c.simulator;
  while (sim.time() < 2.)
    sim.do_time_step(0.5 * sim.stable_time_step());

  const double t0  = 2;
  double       x_t = 0;
  for (const auto &p : sim.particles())
    if (p.get_properties()[L::traction_area] > 0)
      x_t = p.get_location()[0];
  double error = 0, area = 0, max_v = 0, face = 0;
  for (const auto &p : sim.particles())
    {
      const double *prop = p.get_properties().data();
      const double  Js   = prop[L::F] * prop[L::stress]; // J sigma in 1D
      error              = std::max(error, std::abs(Js - t0) / t0);
      area += prop[L::traction_area];
      max_v = std::max(max_v, std::abs(prop[L::velocity]));
      if (prop[L::traction_area] > 0)
        face = prop[L::X] + prop[sim.get_bodies()[0].face_offset_slot];
    }
  mpm_test::log() << "tip particle at " << x_t << std::endl;
  mpm_test::check_small("traction area - 1", area - 1., 1e-14);
  mpm_test::check_small("loaded face X - 1", face - 1., 1e-14);
  mpm_test::check_small("max |J sigma - t0|/t0, every cell", error, 1e-6);
  mpm_test::check_small("max |v| at rest", max_v, 1e-6);
}
