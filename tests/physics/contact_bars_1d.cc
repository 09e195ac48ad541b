// Two equal elastic bars in 1D meet head-on at +-v0 (each its own velocity
// field, frictionless contact, with and without the gap check). An elastic
// impact of equal bars lasts 2 L / c, after which the bars leave each other
// with their velocities swapped. Checked: the total momentum stays zero to
// round-off at every step (equal and opposite exchange at the contact
// node); without the gap check the bars meet while still apart (they share
// a node), with it where their ends touch; they separate; and no energy is
// created.
#include <mpm/particles/particle_layout.h>

#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using L = mpm::ParticleLayout<1>;
  using mpm_test::check;
  // E = 1e4, rho = 1: c = 100; bars 0.5 long and 0.1 apart at v0 = 1:
  // contact from t = 0.05 to 0.06
  const double v0 = 1, t_end = 0.1;
  for (const std::string gap : {"false", "true"})
    {
      std::ostringstream prm;
      prm << "set Kinematic assumption = uniaxial stress\n"
          << "set Number of bodies = 2\n"
          << "subsection Grid\n  set Lower corner = 0\n"
          << "  set Upper corner = 1.6\n  set Subdivisions = 32\nend\n"
          << "subsection Time stepping\n  set End time = " << t_end
          << "\n  set Time step control = CFL\n  set CFL number = 0.4\nend\n"
          << "subsection Contact\n  set Contact law = frictionless\n"
          << "  set Gap check = " << gap << "\nend\n"
          << "subsection Output\n  set Write vtu = false\n"
          << "  set Write csv = false\nend\n"
          << "subsection Bodies\n";
      for (unsigned int b = 0; b < 2; ++b)
        prm << "  subsection Body " << b << "\n"
            << "    set Lower corner = " << (b == 0 ? 0.25 : 0.85) << "\n"
            << "    set Upper corner = " << (b == 0 ? 0.75 : 1.35) << "\n"
            << "    set Subdivisions = 10\n"
            << "    set Particles per direction = 2\n"
            << "    set Initial velocity = " << (b == 0 ? v0 : -v0) << "\n"
            << "    subsection Material\n      set Model = linear elastic\n"
            << "      set Density = 1\n      subsection Linear elastic\n"
            << "        set Young's modulus = 1e4\n"
            << "        set Poisson's ratio = 0\n      end\n    end\n"
            << "  end\n";
      prm << "end\n";
      mpm_test::Case<1> c(prm.str(), 2);
      auto             &sim          = *c.simulator;
      const double      e0           = sim.statistics().kinetic_energy;
      const double      m_v0         = sim.statistics().mass / 2 * v0;
      double            max_momentum = 0, min_gap = 1;
      double            v[2] = {};
      while (sim.time() < t_end - 1e-12)
        {
          sim.do_time_step(
            std::min(0.4 * sim.stable_time_step(), t_end - sim.time()));
          // per bar: mass, momentum, and its nearest end to the other bar
          double m[2] = {}, p[2] = {}, front = -1e9, back = 1e9;
          for (const auto &particle : sim.particles())
            {
              const double *prop = particle.get_properties().data();
              const int     b    = prop[L::body] != 0;
              const double  x    = particle.get_location()[0];
              m[b] += prop[L::mass];
              p[b] += prop[L::mass] * prop[L::velocity];
              const double half = 0.5 * prop[L::volume]; // unit area
              if (b == 0)
                front = std::max(front, x + half);
              else
                back = std::min(back, x - half);
            }
          max_momentum = std::max(max_momentum, std::abs(p[0] + p[1]) / m_v0);
          min_gap      = std::min(min_gap, back - front);
          v[0]         = p[0] / m[0];
          v[1]         = p[1] / m[1];
        }
      const std::string tag = "gap check " + gap;
      check(max_momentum < 1e-12,
            tag + ": largest |total momentum| / (m v0) below 1e-12",
            max_momentum < 1e-12 ? 0. : max_momentum,
            1e-12);
      // without the gap check the bars meet as soon as they share a node,
      // up to 2 h apart; with it, where their ends touch (the particles'
      // domains may overlap by less than a tenth of a cell)
      if (gap == "false")
        check(min_gap > 0,
              tag + ": smallest distance between the bars' ends / h, above 0",
              min_gap / 0.05,
              0);
      else
        check(std::abs(min_gap) < 0.1 * 0.05,
              tag + ": smallest distance between the bars' ends / h, "
                    "within 0.1 of 0",
              min_gap / 0.05,
              0.1);
      check(v[0] < -0.8 * v0 && v[1] > 0.8 * v0,
            tag + ": velocities swapped, v_left / v0",
            v[0] / v0,
            -0.8);
      const auto   last  = sim.statistics();
      const double total = (last.kinetic_energy + last.strain_energy) / e0;
      check(total < 1.0, tag + ": energy after / before", total, 1.0);
    }
}
