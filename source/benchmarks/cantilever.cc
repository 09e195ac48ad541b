#include <deal.II/base/mpi.h>

#include <mpm/benchmarks/cantilever.h>
#include <mpm/particles/particle_layout.h>

namespace mpm
{
  namespace benchmarks
  {
    using namespace dealii;

    template <int dim>
    std::vector<std::string>
    Cantilever<dim>::columns() const
    {
      return {"tip_displacement_y"};
    }

    template <int dim>
    std::vector<double>
    Cantilever<dim>::measure(Particles::ParticleHandler<dim> &particles,
                             const double,
                             const MPI_Comm comm) const
    {
      using L         = ParticleLayout<dim>;
      double local[2] = {};
      for (const auto &p : particles)
        {
          const double *prop = p.get_properties().data();
          if (prop[L::X] > length - depth / 2)
            {
              local[0] += prop[L::mass];
              local[1] +=
                prop[L::mass] * (p.get_location()[1] - prop[L::X + 1]);
            }
        }
      double g[2];
      Utilities::MPI::sum(ArrayView<const double>(local, 2),
                          comm,
                          ArrayView<double>(g, 2));
      return {g[0] > 0 ? g[1] / g[0] : 0.};
    }

    template class Cantilever<2>;
    template class Cantilever<3>;
  } // namespace benchmarks
} // namespace mpm
