#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/benchmarks/checkerboard.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>
#include <limits>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    namespace
    {
      const BenchmarkDeclaration declaration{
        "water column",
        "collapse of a water column of width a and height 2a against the "
        "wall x = 0, released under gravity (the dam break of Martin & "
        "Moyce 1952)",
        {required_constant("a", "width of the column [m]"),
         required_constant("g", "gravity [m/s^2]"),
         required_constant("rho", "density [kg/m^3]"),
         optional_constant("wall_band",
                           "width of the band at the wall where the height "
                           "is measured [m]",
                           "a/10")},
        {"x_front",
         "height",
         "T",
         "Z",
         "tau",
         "H",
         "checkerboard",
         "max_speed"}};

      /**
       * Water column (doc/benchmarks/water_column.md): collapse of a water
       * column of width a and height 2a standing on the floor y = 0 against the
       * wall x = 0. With s_p = V_p^(1/dim) the side of a square (cube) of the
       * particle's current volume, columns:
       * - x_front: max_p (x_p + s_p/2), the surge front, the right edge of
       *   the particle furthest from the wall (the current volume rather
       *   than F times the domain vectors: a fluid's F is sheared without
       *   limit, its volume is not);
       * - height: max (y_p + s_p/2) over the particles with
       *   x_p < wall_band, the top of the column at the wall (0 if none is
       *   there);
       * - T = t sqrt(2g/a), Z = x_front/a (Martin & Moyce's front
       *   variables), tau = t sqrt(g/a), H = height/(2a) (their height
       *   variables);
       * - checkerboard: as in the self-weight column, of p + rho g y (the
       *   pressure less its hydrostatic gradient, so that a smooth
       *   hydrostatic field gives 0), divided by rho g 2a;
       * - max_speed: max_p |v_p| (to check that the sound speed is at
       *   least 10 times the flow speed).
       * Both maxima start at a and 2a, the edges of the body.
       */
      template <int dim>
      class WaterColumn : public Benchmark<dim>
      {
      public:
        explicit WaterColumn(const BenchmarkConstants &c)
          : Benchmark<dim>(declaration.columns)
          , a(c["a"])
          , g(c["g"])
          , rho(c["rho"])
          , wall_band(c.value_or("wall_band", a / 10))
        {}

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double                     time,
                const MPI_Comm                   comm) const override
        {
          using L = ParticleLayout<dim>;
          // local maxima: front, height at the wall, speed
          double local[3] = {-std::numeric_limits<double>::max(), 0., 0.};
          for (const auto &p : particles)
            {
              const double *prop = p.get_properties().data();
              const double  half = 0.5 * std::pow(prop[L::volume], 1. / dim);
              const auto    x    = p.get_location();
              local[0]           = std::max(local[0], x[0] + half);
              double v2          = 0;
              for (unsigned int d = 0; d < dim; ++d)
                v2 += prop[L::velocity + d] * prop[L::velocity + d];
              local[2] = std::max(local[2], std::sqrt(v2));
              if (x[0] < wall_band)
                local[1] = std::max(local[1], x[1] + half);
            }
          double global[3];
          Utilities::MPI::max(ArrayView<const double>(local, 3),
                              comm,
                              ArrayView<double>(global, 3));
          const double head               = rho * g * 2 * a;
          auto         p_less_hydrostatic = [&](const double     *prop,
                                        const Point<dim> &x) {
            const double *s = prop + L::stress;
            return -(s[0] + s[1] + s[2]) / 3 + rho * g * x[1];
          };
          const double cb = checkerboard_with_position<dim>(particles,
                                                            p_less_hydrostatic,
                                                            comm);
          return {global[0],
                  global[1],
                  time * std::sqrt(2 * g / a),
                  global[0] / a,
                  time * std::sqrt(g / a),
                  global[1] / (2 * a),
                  cb / head,
                  global[2]};
        }

      private:
        double a, g, rho, wall_band;
      };
    } // namespace

    MPM_REGISTER_BENCHMARK(WaterColumn, declaration, 2, 3)
  } // namespace benchmarks
} // namespace mpm
