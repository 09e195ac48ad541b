#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/benchmark_registry.h>
#include <mpm/contact/gather_contact_forces.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    namespace
    {
      const BenchmarkDeclaration declaration{
        "hertz contact",
        "an elastic cylinder pressed on a rigid plane (contact): the contact "
        "half-width and peak pressure from the nodal contact forces, against "
        "Hertz's a = sqrt(4 P R / (pi E*)) and p0 = 2 P / (pi a) for the "
        "measured load P, E* = E / (1 - nu^2), and the RMS error of the "
        "nodal pressures against Hertz's profile",
        {required_constant("R", "radius of the cylinder [m]"),
         required_constant("E", "Young's modulus of the cylinder [Pa]"),
         required_constant("nu", "Poisson's ratio of the cylinder")},
        {"contact_load",
         "half_width",
         "half_width_exact",
         "half_width_error",
         "peak_pressure",
         "peak_pressure_exact",
         "peak_pressure_error",
         "pressure_profile_error"}};

      /**
       * Hertzian contact of a cylinder on a rigid plane in plane strain
       * (doc/benchmarks/hertz_contact.md). The plane is horizontal (normal
       * y); F_i is the vertical contact force at node i, per unit
       * thickness. Read as F_i = integral of p N_i along the plane with
       * hat functions N_i of spacing w (the grid's), the nodal forces give
       *  - the load P = sum F_i;
       *  - the half-width from the second moment about the centre x_c:
       *    sum F_i (x_i - x_c)^2 / P = a^2 / 4 + w^2 / 6 for Hertz's
       *    p0 sqrt(1 - x^2 / a^2) (the hats add w^2 / 6);
       *  - the peak pressure max F_i / w;
       *  - the profile's error: the RMS over the nodes of the row within
       *    Hertz's width and one spacing beyond it of (F_i - F_i^H) /
       *    (w p0), F_i^H = integral of Hertz's p N_i (p0 and a for the
       *    measured load, centred at x_c), so that one node's scatter
       *    shows beside the peak's.
       * The exact values are Hertz's for the measured load, so that the
       * comparison holds while the load still oscillates.
       */
      template <int dim>
      class HertzContact : public Benchmark<dim>
      {
      public:
        explicit HertzContact(const BenchmarkConstants &c)
          : Benchmark<dim>(declaration.columns)
          , radius(c["R"])
          , plane_strain_modulus(c["E"] / (1 - c["nu"] * c["nu"]))
        {
          if (!(radius > 0))
            throw InputError("Constants: R = " + std::to_string(radius) +
                             " must be positive for Benchmark = hertz "
                             "contact");
          if (!(plane_strain_modulus > 0))
            throw InputError("Constants: E must be positive and -1 < nu < 1 "
                             "for Benchmark = hertz contact");
        }

        std::vector<double>
        measure(Particles::ParticleHandler<dim> &particles,
                const double                     t,
                const MPI_Comm                   comm) const override
        {
          return measure_with_contact(particles, t, comm, {});
        }

        std::vector<double>
        measure_with_contact(
          Particles::ParticleHandler<dim> &,
          const double,
          const MPI_Comm                          comm,
          const contact::NodalContactForces<dim> &forces) const override
        {
          // (x, F) of every contact node, on every rank, sorted by x
          std::vector<std::pair<double, double>> nodes;
          for (const auto &f : contact::gather_contact_forces(forces, comm))
            nodes.emplace_back(f.position[0], std::abs(f.force[dim - 1]));

          double load = 0, first = 0;
          for (const auto &[x, F] : nodes)
            {
              load += F;
              first += F * x;
            }
          // no contact (yet): nothing to compare, and no error to show
          if (!(load > 0))
            {
              std::vector<double> none(
                declaration.columns.size(),
                std::numeric_limits<double>::quiet_NaN());
              none[0] = 0;
              return none;
            }
          const double centre = first / load;
          double       second = 0, largest = 0;
          for (const auto &[x, F] : nodes)
            {
              second += F * (x - centre) * (x - centre);
              largest = std::max(largest, F);
            }
          second /= load;
          // the node spacing along the plane: the smallest gap between
          // contact nodes, the grid's spacing where two of them are
          // neighbours (none with a single node)
          double spacing = 0;
          for (std::size_t i = 1; i < nodes.size(); ++i)
            {
              const double gap = nodes[i].first - nodes[i - 1].first;
              if (gap > 1e-12 * radius && (spacing == 0 || gap < spacing))
                spacing = gap;
            }
          const double half_width =
            2 * std::sqrt(std::max(second - spacing * spacing / 6, 0.));
          const double peak = spacing > 0 ? largest / spacing : 0.;

          const double a_exact =
            std::sqrt(4 * load * radius / (M_PI * plane_strain_modulus));
          const double p0_exact = 2 * load / (M_PI * a_exact);
          return {load,
                  half_width,
                  a_exact,
                  (half_width - a_exact) / a_exact,
                  peak,
                  p0_exact,
                  (peak - p0_exact) / p0_exact,
                  profile_error(nodes, spacing, centre, a_exact, p0_exact)};
        }

      private:
        /// RMS of (F_i - int p N_i) / (w p0) over the row's nodes from
        /// x_c - a - w to x_c + a + w, nodes without a contact force
        /// counting as zero force; forces of nodes at the same x (another
        /// row) add up.
        static double
        profile_error(const std::vector<std::pair<double, double>> &nodes,
                      const double                                  w,
                      const double                                  centre,
                      const double                                  a,
                      const double                                  p0)
        {
          if (!(w > 0) || nodes.empty())
            return std::numeric_limits<double>::quiet_NaN();
          // the row's nodes as multiples of w from the first contact node
          const double x0    = nodes.front().first;
          const auto   index = [&](const double x) {
            return static_cast<long>(std::lround((x - x0) / w));
          };
          const long          first = index(centre - a - w);
          const long          last  = index(centre + a + w);
          std::vector<double> force(last - first + 1, 0.);
          for (const auto &[x, F] : nodes)
            {
              const long k = index(x);
              if (k >= first && k <= last)
                force[k - first] += F;
            }
          // Hertz's nodal force by the midpoint rule on 400 intervals of
          // the hat's support (its kink and the profile's edge are then
          // resolved to below 1e-4 of p0 w)
          constexpr unsigned int n   = 400;
          double                 sum = 0;
          for (long k = first; k <= last; ++k)
            {
              const double xi    = x0 + k * w;
              double       exact = 0;
              for (unsigned int q = 0; q < n; ++q)
                {
                  const double x = xi - w + 2 * w * (q + 0.5) / n;
                  const double s = (x - centre) / a;
                  if (s * s < 1)
                    exact += p0 * std::sqrt(1 - s * s) *
                             (1 - std::abs(x - xi) / w) * 2 * w / n;
                }
              const double e = (force[k - first] - exact) / (w * p0);
              sum += e * e;
            }
          return std::sqrt(sum / force.size());
        }

        double radius, plane_strain_modulus;
      };
    } // namespace

    MPM_REGISTER_BENCHMARK(HertzContact, declaration, 2)
  } // namespace benchmarks
} // namespace mpm
