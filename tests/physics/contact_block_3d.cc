// The sliding block in 3D (prm/sliding_block.prm extruded 0.2 m across the
// slope, between slip walls): a block on a rigid plane inclined at 30
// degrees, Coulomb friction mu = 0.3, slides 1/2 g (sin theta - mu cos
// theta) t^2; with mu = 0.7 > tan theta it stays. On 1 and 2 ranks the
// printed figures are the same.
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double theta = 30 * M_PI / 180, g = 9.81, t_end = 0.2;
  const double frictionless = 0.5 * g * std::sin(theta) * t_end * t_end;
  for (const double mu : {0.3, 0.7})
    {
      std::ostringstream prm;
      prm << "set Constants = theta=30, mu=" << mu
          << ", g=9.81, E=1e7, nu=0.3, rho=1000, top=0.5\n"
          << R"(set Number of bodies = 2
subsection Grid
  set Lower corner = 0, 0, 0
  set Upper corner = 1.2, 0.75, 0.2
  set Subdivisions = 24, 15, 4
end
subsection Boundary conditions
  set Slip boundary ids = 4, 5
end
subsection Time stepping
  set End time = 0.2
  set Time step control = CFL
  set CFL number = 0.5
end
subsection Contact
  set Contact law = Coulomb
  set Friction coefficient = mu
end
subsection Output
  set Write vtu = false
  set Write csv = false
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.2, 0.25, 0
    set Upper corner = 0.7, 0.5, 0.2
    set Subdivisions = 10, 5, 4
    set Particles per direction = 2
    set Body force = g*sin(theta*pi/180); -g*cos(theta*pi/180); 0
    set Initial stress = \
      -nu/(1-nu)*rho*g*cos(theta*pi/180)*(top-y); \
      -rho*g*cos(theta*pi/180)*(top-y); \
      -nu/(1-nu)*rho*g*cos(theta*pi/180)*(top-y); 0; 0; \
      rho*(g*sin(theta*pi/180) - max(0, g*(sin(theta*pi/180) - mu*cos(theta*pi/180))))*(top-y)
    subsection Material
      set Model = linear elastic
      set Density = rho
      subsection Linear elastic
        set Young's modulus = E
        set Poisson's ratio = nu
      end
    end
  end
  subsection Body 1
    set Lower corner = 0, 0, 0
    set Upper corner = 1.2, 0.25, 0.2
    set Subdivisions = 24, 5, 4
    set Particles per direction = 2
    set Prescribed velocity = 0; 0; 0
    subsection Material
      set Model = rigid
      set Density = rho
    end
  end
end
)";
      mpm_test::Case<3> c(prm.str(), 2);
      mpm_test::run_until(*c.simulator, t_end, 0.5);
      const double slide = mpm_test::mean_displacement(*c.simulator, 0)[0];
      const double a =
        std::tan(theta) > mu ? g * (std::sin(theta) - mu * std::cos(theta)) : 0;
      const double       exact = 0.5 * a * t_end * t_end;
      std::ostringstream tag;
      tag << "3D, Coulomb, mu = " << mu
          << ": |slide - exact| / frictionless slide";
      mpm_test::check(std::abs(slide - exact) < 0.02 * frictionless,
                      tag.str(),
                      std::abs(slide - exact) / frictionless,
                      0.02);
    }
}
