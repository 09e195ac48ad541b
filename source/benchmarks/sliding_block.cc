#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/benchmarks/global_sums.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    namespace
    {
      const BenchmarkDeclaration declaration{
        "sliding block",
        "a block (or a cylinder) on a plane inclined at theta with Coulomb "
        "friction mu "
        "(contact), against the rigid block's slide 1/2 g (sin theta - mu "
        "cos theta) t^2, or rest where tan theta <= mu",
        {required_constant("theta", "inclination of the plane [degrees]"),
         required_constant("mu", "friction coefficient of the contact"),
         required_constant("g", "gravitational acceleration [m/s^2]"),
         optional_constant("beta",
                           "angle of the plane against the grid's x axis "
                           "[degrees]: 0 when gravity is tilted instead, "
                           "theta when the plane is drawn inclined",
                           "0"),
         optional_constant("block", "the body index of the block", "0"),
         optional_constant("cylinder",
                           "1: the body is a solid cylinder, which rolls "
                           "(1/3 g sin theta t^2) where mu >= tan(theta)/3 "
                           "and slides otherwise",
                           "0")},
        {"slide", "slide_exact", "slide_error"}};

      /**
       * Sliding block (doc/benchmarks/sliding_block.md). The block's slide
       * is the mass-weighted mean displacement x_p - X_p of its particles
       * along the downhill direction s = (cos beta, -sin beta) in the
       * plane of x and the vertical (y in 2D, z in 3D); exact:
       * 1/2 g (sin theta - mu cos theta) t^2 if tan theta > mu, else 0;
       * for a solid cylinder (constant cylinder = 1) 1/3 g sin theta t^2
       * where mu >= tan(theta)/3 (rolling without slip).
       * The error is (slide - exact) over the frictionless slide
       * 1/2 g sin theta t^2, so that it is defined for a block at rest.
       */
      template <int dim>
      class SlidingBlock : public Benchmark<dim>
      {
      public:
        explicit SlidingBlock(const BenchmarkConstants &c)
          : Benchmark<dim>(declaration.columns)
          , theta(c["theta"] * M_PI / 180)
          , mu(c["mu"])
          , g(c["g"])
          , beta(c.value_or("beta", 0.) * M_PI / 180)
          , block(static_cast<unsigned int>(c.value_or("block", 0.)))
          , cylinder(c.value_or("cylinder", 0.) != 0)
        {}

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double                     t,
                const MPI_Comm                   comm) const override
        {
          using L         = ParticleLayout<dim>;
          double local[2] = {};
          for (const auto &p : particles)
            {
              const double *prop = p.get_properties().data();
              if (static_cast<unsigned int>(prop[L::body]) != block)
                continue;
              const double m = prop[L::mass];
              const auto  &x = p.get_location();
              local[0] += m;
              local[1] += m * ((x[0] - prop[L::X]) * std::cos(beta) -
                               (x[up] - prop[L::X + up]) * std::sin(beta));
            }
          const auto   sums  = global_sums(local, comm);
          const double slide = sums[0] > 0 ? sums[1] / sums[0] : 0.;
          // a solid cylinder rolls without slip where friction can hold
          // its contact point: a = 2/3 g sin(theta)
          const double a            = cylinder && mu >= std::tan(theta) / 3 ?
                                        2. / 3 * g * std::sin(theta) :
                                      std::tan(theta) > mu ?
                                        g * (std::sin(theta) - mu * std::cos(theta)) :
                                        0.;
          const double exact        = 0.5 * a * t * t;
          const double frictionless = 0.5 * g * std::sin(theta) * t * t;
          return {slide,
                  exact,
                  frictionless > 0 ? (slide - exact) / frictionless : 0.};
        }

      private:
        /// the grid's vertical direction (y in 2D, z in 3D)
        static constexpr unsigned int up = dim - 1;
        double                        theta, mu, g, beta;
        unsigned int                  block;
        bool                          cylinder;
      };
    } // namespace

    MPM_REGISTER_BENCHMARK(SlidingBlock, declaration, 2, 3)
  } // namespace benchmarks
} // namespace mpm
