#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/convecting_bar.h>
#include <mpm/particles/particle_layout.h>

#include <cmath>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    template <int dim>
    std::vector<std::string>
    ConvectingBar<dim>::columns() const
    {
      return {"sigma_rms_error", "v_rms_error"};
    }

    template <int dim>
    std::vector<double>
    ConvectingBar<dim>::measure(Particles::ParticleHandler<dim> &particles,
                                const double,
                                const MPI_Comm comm) const
    {
      using L         = ParticleLayout<dim>;
      double local[3] = {};
      for (const auto &p : particles)
        {
          const double *prop = p.get_properties().data();
          const double  m    = prop[L::mass];
          const double  xi   = (prop[L::X] - x0) / length;
          const double  ds   = prop[L::stress] + sigma0 * std::sin(M_PI * xi);
          const double  dv   = prop[L::velocity] - v0;
          local[0] += m;
          local[1] += m * ds * ds;
          local[2] += m * dv * dv;
        }
      double g[3];
      Utilities::MPI::sum(ArrayView<const double>(local, 3),
                          comm,
                          ArrayView<double>(g, 3));
      // v0 = 0 (the bar at rest): the velocity error in m/s
      return {std::sqrt(g[1] / g[0]) / sigma0,
              std::sqrt(g[2] / g[0]) / (v0 != 0 ? std::abs(v0) : 1.)};
    }

    template class ConvectingBar<1>;
    template class ConvectingBar<2>;
    template class ConvectingBar<3>;
  } // namespace benchmarks
} // namespace mpm
