#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/benchmark.h>
#include <mpm/benchmarks/cantilever.h>
#include <mpm/benchmarks/convecting_bar.h>
#include <mpm/benchmarks/cooks_membrane.h>
#include <mpm/benchmarks/manufactured_solution.h>
#include <mpm/benchmarks/self_weight_column.h>
#include <mpm/benchmarks/spinning_disk.h>
#include <mpm/benchmarks/thick_cylinder.h>
#include <mpm/benchmarks/water_column.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/utilities/input_error.h>

#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    namespace
    {
      double
      constant(const std::map<std::string, double> &c,
               const std::string                   &name,
               const std::string                   &benchmark)
      {
        const auto it = c.find(name);
        if (it == c.end())
          throw InputError("Benchmark = " + benchmark +
                           " needs the constant '" + name +
                           "' in the entry Constants");
        return it->second;
      }

      /**
       * BENCHMARKS.md section 9: fixed-free bar of length L (fixed at
       * X = 0 of the bar), modulus E, density rho, initial velocity
       * v0 sin(beta X). Exact: v = v0 cos(omega t) sin(beta X),
       * beta = pi/(2L), omega = beta c. Columns: centre-of-mass velocity,
       * its exact value v0 cos(omega t)/(beta L), and the mass-weighted
       * RMS of (v_p - v_exact(X_p)) / v0. X is measured from the constant
       * x0 (the fixed end).
       */
      template <int dim>
      class AxialBar : public Benchmark<dim>
      {
      public:
        explicit AxialBar(const std::map<std::string, double> &c)
        {
          const std::string n = "axial bar";
          L                   = constant(c, "L", n);
          E                   = constant(c, "E", n);
          rho                 = constant(c, "rho", n);
          v0                  = constant(c, "v0", n);
          x0                  = c.count("x0") ? c.at("x0") : 0.;
          beta                = M_PI / (2 * L);
          omega               = beta * std::sqrt(E / rho);
        }

        std::vector<std::string>
        columns() const override
        {
          return {"v_cm", "v_cm_exact", "v_rms_error"};
        }

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double                     t,
                const MPI_Comm                   comm) const override
        {
          using Lay       = ParticleLayout<dim>;
          double local[3] = {};
          for (const auto &p : particles)
            {
              const double *prop = p.get_properties().data();
              const double  m    = prop[Lay::mass];
              const double  X    = prop[Lay::X] - x0;
              const double  v    = prop[Lay::velocity];
              const double  ve = v0 * std::cos(omega * t) * std::sin(beta * X);
              local[0] += m;
              local[1] += m * v;
              local[2] += m * (v - ve) * (v - ve);
            }
          double g[3];
          Utilities::MPI::sum(ArrayView<const double>(local, 3),
                              comm,
                              ArrayView<double>(g, 3));
          return {g[1] / g[0],
                  v0 * std::cos(omega * t) / (beta * L),
                  std::sqrt(g[2] / g[0]) / v0};
        }

      private:
        double L, E, rho, v0, x0, beta, omega;
      };
    } // namespace

    template <int dim>
    std::unique_ptr<Benchmark<dim>>
    create_benchmark(const std::string                   &name,
                     const std::map<std::string, double> &constants)
    {
      if (name == "none" || name.empty())
        return nullptr;
      if (name == "axial bar")
        return std::make_unique<AxialBar<dim>>(constants);
      if (name == "spinning disk")
        {
          if constexpr (dim == 2)
            return std::make_unique<SpinningDisk<dim>>(
              constant(constants, "a", name),
              constant(constants, "omega", name),
              constant(constants, "nu", name),
              constant(constants, "rho", name));
          else
            throw InputError("Benchmark = spinning disk needs Dimension = 2");
        }
      if (name == "convecting bar")
        return std::make_unique<ConvectingBar<dim>>(
          constant(constants, "L", name),
          constant(constants, "A", name),
          constant(constants, "b0", name),
          constant(constants, "v0", name),
          constant(constants, "x0", name));
      if (name == "cantilever")
        {
          if constexpr (dim >= 2)
            return std::make_unique<Cantilever<dim>>(
              constant(constants, "L", name), constant(constants, "H", name));
          else
            throw InputError("Benchmark = cantilever needs Dimension 2 or 3");
        }
      if (name == "self-weight column")
        {
          if constexpr (dim >= 2)
            return std::make_unique<SelfWeightColumn<dim>>(
              constant(constants, "H", name),
              constant(constants, "rho", name),
              constant(constants, "g", name),
              constant(constants, "nu", name));
          else
            throw InputError(
              "Benchmark = self-weight column needs Dimension 2 or 3");
        }
      if (name == "thick cylinder")
        {
          if constexpr (dim == 2)
            return std::make_unique<ThickCylinder<dim>>(
              constant(constants, "a", name),
              constant(constants, "b", name),
              constant(constants, "p", name),
              constant(constants, "E", name),
              constant(constants, "nu", name));
          else
            throw InputError("Benchmark = thick cylinder needs Dimension = 2");
        }
      if (name == "cooks membrane")
        {
          if constexpr (dim == 2)
            {
              const double F     = constant(constants, "F", name);
              const double r_fit = constant(constants, "r_fit", name);
              if (!(F != 0) || !(r_fit > 0))
                throw InputError("Benchmark = cooks membrane needs the "
                                 "constants F != 0 (the ratios are divided "
                                 "by it) and r_fit > 0");
              return std::make_unique<CooksMembrane<dim>>(
                F,
                constant(constants, "uy_ref", name),
                constant(constants, "uy_ref_mid", name),
                r_fit);
            }
          else
            throw InputError("Benchmark = cooks membrane needs Dimension = 2");
        }
      if (name == "manufactured solution")
        {
          if constexpr (dim >= 2)
            {
              const double G = constant(constants, "G", name);
              if (!(G > 0))
                throw InputError("Benchmark = manufactured solution needs "
                                 "the constant G > 0 (errors are divided by "
                                 "it)");
              return std::make_unique<ManufacturedSolution<dim>>(
                G,
                constant(constants, "E", name),
                constant(constants, "nu", name),
                constant(constants, "rho", name));
            }
          else
            throw InputError(
              "Benchmark = manufactured solution needs Dimension 2 or 3");
        }
      if (name == "water column")
        {
          if constexpr (dim >= 2)
            {
              const double a = constant(constants, "a", name);
              return std::make_unique<WaterColumn<dim>>(
                a,
                constant(constants, "g", name),
                constant(constants, "rho", name),
                constants.count("wall_band") ? constants.at("wall_band") :
                                               a / 10);
            }
          else
            throw InputError("Benchmark = water column needs Dimension 2 or 3");
        }
      throw InputError("Benchmark = '" + name +
                       "' is unknown; known: none, axial bar, spinning disk, "
                       "cantilever, self-weight column, convecting bar, "
                       "thick cylinder, cooks membrane, manufactured "
                       "solution, water column");
    }

    template std::unique_ptr<Benchmark<1>>
    create_benchmark<1>(const std::string &,
                        const std::map<std::string, double> &);
    template std::unique_ptr<Benchmark<2>>
    create_benchmark<2>(const std::string &,
                        const std::map<std::string, double> &);
    template std::unique_ptr<Benchmark<3>>
    create_benchmark<3>(const std::string &,
                        const std::map<std::string, double> &);
  } // namespace benchmarks
} // namespace mpm
