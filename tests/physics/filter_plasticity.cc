// The assumed-stress filter with a plastic material: the projection can
// carry a particle's stress outside the yield surface (it mixes the
// stresses of the cell), so the filter hands every stress it writes to the
// material, which returns it to the surface with the plastic flow that
// implies (Material::make_admissible; doc/theory/assumed_stress_filter.md,
// strain consistency).
// A von Mises block in plane strain is pulled apart with a low yield
// stress; after every step no particle lies outside its yield surface,
// while many lie on it (the check is not vacuous).
#include <mpm/materials/von_mises_plasticity.h>

#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string scheme : {"USF", "MUSL"})
    {
      mpm_test::Case<2> c(R"(
set Kinematic assumption = plane strain
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 10
end
subsection Time stepping
  set Scheme = )" + scheme +
                          R"(
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.2, 0.3
    set Upper corner = 0.8, 0.7
    set Subdivisions = 6, 4
    set Particles per direction = 2
    set Initial velocity = 2*(x - 0.5); -0.5*sin(6*x)*(y - 0.5)
    subsection Material
      set Model = von Mises plasticity
      set Density = 1000
      subsection Von Mises plasticity
        set Young's modulus = 1e6
        set Poisson's ratio = 0.3
        set Yield stress = 2e3
        set Hardening modulus = 1e4
      end
    end
    subsection Locking remedies
      set Stress filter = assumed stress
      set Filter metric = compliance
    end
  end
end)");
      auto             &sim = *c.simulator;
      const auto &vm = dynamic_cast<const mpm::materials::VonMisesPlasticity &>(
        *sim.get_bodies()[0].material);
      using L                 = mpm::ParticleLayout<2>;
      const double dt         = 0.3 * sim.stable_time_step();
      double       worst      = -1e300;
      unsigned int on_surface = 0;
      for (unsigned int n = 0; n < 40; ++n)
        {
          sim.do_time_step(dt);
          // the state the next force is computed from
          sim.filter_stress();
          for (const auto &p : sim.particles())
            {
              const double *prop = p.get_properties().data();
              const double  f =
                vm.yield_function(mpm::load_stress(prop + L::stress),
                                  prop[L::history]);
              worst = std::max(worst, f / vm.yield_stress());
              if (f > -1e-9 * vm.yield_stress())
                ++on_surface;
            }
        }
      mpm_test::check(worst <= 1e-12,
                      scheme + ": largest yield function / yield stress",
                      std::max(worst, 0.),
                      1e-12);
      // (the count itself depends on round-off: print only the bound)
      mpm_test::check(on_surface > 100,
                      scheme + ": at least 100 particle-steps on the yield "
                               "surface",
                      std::min(on_surface, 100u),
                      100);
    }
}
