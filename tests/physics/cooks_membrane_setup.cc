// Cook's membrane set-up (doc/benchmarks/cooks_membrane.md,
// prm/cooks_membrane.prm):
// the body mesh Geometry = quadrilateral of the panel (0,0), (48,44),
// (48,60), (0,44) in 12 x 12 cells with 2 x 2 particles each. The particle
// volumes tile the panel exactly (area 48 (44 + 16)/2 = 1440), the
// particles next to body-mesh boundary id 1 (the right edge) carry its
// length 16 and no others do, and the point displacement of
// Benchmark = cooks membrane (the plane fitted through the particles within
// r_fit of the point) reproduces a linear displacement field exactly at
// (48,60) and (48,52), while the particle nearest the corner does not.
#include <deal.II/base/point.h>

#include <mpm/benchmarks/cooks_membrane.h>
#include <mpm/particles/particle_layout.h>

#include <utility>

#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using L = mpm::ParticleLayout<2>;
  mpm_test::Case<2> c(R"(
set Kinematic assumption = plane stress
subsection Grid
  set Lower corner = 0, -4
  set Upper corner = 52, 64
  set Subdivisions = 13, 17
end
subsection Bodies
  subsection Body 0
    set Geometry = quadrilateral
    set Corners = 0, 0; 48, 44; 48, 60; 0, 44
    set Subdivisions = 12
    set Particles per direction = 2
    set Traction boundary ids = 1
    set Traction = 0; 1/16
    subsection Material
      set Model = linear elastic
      set Density = 1
      subsection Linear elastic
        set Young's modulus = 1
        set Poisson's ratio = 1/3
      end
    end
  end
end)");
  auto             &sim  = *c.simulator;
  const MPI_Comm    comm = MPI_COMM_WORLD;

  // a linear displacement field, u_y(X) = a + b.X, and u_x = 0
  const double a = 0.3, bx = 0.01, by = -0.02;
  const unsigned int face = sim.get_bodies()[0].face_offset_slot;
  double             local[6] = {};
  for (auto &p : sim.particles())
    {
      const double *prop = p.get_properties().data();
      const double  X = prop[L::X], Y = prop[L::X + 1];
      local[0] += prop[L::volume];
      local[1] += prop[L::traction_area];
      // loaded particles must sit in the last column of sub-cells (X = 47)
      if (prop[L::traction_area] > 0 && std::abs(X - 47) > 1e-12)
        local[2] += 1;
      local[3] += 1;
      // the traction acts on the loaded edge X = 48: every loaded face
      // point lies on it, and their area-weighted mean is its mid-point
      if (prop[L::traction_area] > 0)
        {
          local[4] = std::max(local[4], std::abs(X + prop[face] - 48));
          local[5] += prop[L::traction_area] * (Y + prop[face + 1]);
        }
      p.set_location(dealii::Point<2>(X, Y + a + bx * X + by * Y));
    }
  const double face_off_edge =
    dealii::Utilities::MPI::max(std::exchange(local[4], 0.), comm);
  double sum[6];
  dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(local, 6),
                              comm,
                              dealii::ArrayView<double>(sum, 6));
  mpm_test::log() << "particles: " << sum[3] << std::endl;
  mpm_test::check_small("sum V_p / 1440 - 1", sum[0] / 1440 - 1, 1e-12);
  mpm_test::check_small("sum traction area / 16 - 1", sum[1] / 16 - 1, 1e-12);
  mpm_test::check_small("loaded particles away from the right edge", sum[2], 0);
  mpm_test::check_small("max |X_face - 48|", face_off_edge, 1e-12);
  mpm_test::check_small("area-weighted Y_face / 52 - 1",
                        sum[5] / sum[1] / 52 - 1,
                        1e-12);

  const mpm::benchmarks::CooksMembrane<2> cook(1, 1, 1, 4);
  const auto   m            = cook.measure(sim.particles(), 0, comm);
  const double exact_corner = a + 48 * bx + 60 * by,
               exact_mid    = a + 48 * bx + 52 * by;
  mpm_test::check_small("fitted u_y(48,60) - exact",
                        m[0] - exact_corner,
                        1e-12);
  mpm_test::check_small("fitted u_y(48,52) - exact", m[1] - exact_mid, 1e-12);
  // the nearest particle sits at (47, 59.33): off by b.(X_p - X0)
  mpm_test::check(std::abs(m[4] - exact_corner) > 1e-3,
                  "nearest particle's u_y(48,60) - exact (must be off)",
                  std::abs(m[4] - exact_corner),
                  1e-3);
}
