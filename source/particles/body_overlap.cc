#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <mpm/parameters/parameters.h>
#include <mpm/particles/body_overlap.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/utilities/input_error.h>

#include <memory>
#include <sstream>

namespace mpm
{
  template <int dim>
  void
  check_bodies_do_not_overlap(
    const std::vector<Body<dim>>                  &bodies,
    const dealii::Particles::ParticleHandler<dim> &particles,
    const std::string                             &input_folder,
    const MPI_Comm                                 comm)
  {
    using namespace dealii;
    using L              = ParticleLayout<dim>;
    const unsigned int n = bodies.size();
    if (n < 2)
      return;
    // every body's mesh with a point locator, and its bounding box
    std::vector<std::unique_ptr<Triangulation<dim>>>    meshes(n);
    std::vector<std::unique_ptr<GridTools::Cache<dim>>> locators(n);
    std::vector<BoundingBox<dim>>                       boxes(n);
    const MappingQ1<dim>                                mapping;
    for (unsigned int b = 0; b < n; ++b)
      {
        // a body without a mesh (its particles enter by an inflow)
        // occupies no volume of its own
        if (bodies[b].prm.geometry == Parameters::Body<dim>::Geometry::none)
          continue;
        meshes[b] = std::make_unique<Triangulation<dim>>();
        create_body_mesh(*meshes[b],
                         bodies[b].prm,
                         input_folder,
                         "Bodies/" + Parameters::body_section(b));
        boxes[b] = GridTools::compute_bounding_box(*meshes[b]);
        locators[b] =
          std::make_unique<GridTools::Cache<dim>>(*meshes[b], mapping);
      }

    // inside[j * n + i]: volume of body j's particles inside body i
    std::vector<double> inside(n * n, 0.), volume(n, 0.);
    for (const auto &p : particles)
      {
        const auto         props = p.get_properties();
        const unsigned int j     = static_cast<unsigned int>(props[L::body]);
        const Point<dim>   x     = p.get_location();
        volume[j] += props[L::volume0];
        for (unsigned int i = 0; i < n; ++i)
          if (i != j && meshes[i] && boxes[i].point_inside(x))
            {
              const auto found =
                GridTools::find_active_cell_around_point(*locators[i], x);
              if (found.first.state() == IteratorState::valid)
                inside[j * n + i] += props[L::volume0];
            }
      }
    Utilities::MPI::sum(inside, comm, inside);
    Utilities::MPI::sum(volume, comm, volume);

    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        if (inside[j * n + i] > 0)
          {
            std::ostringstream s;
            s.precision(3);
            s << "Bodies/" << Parameters::body_section(j) << " overlaps Bodies/"
              << Parameters::body_section(i) << ": particles of "
              << Parameters::body_section(j) << " with a volume of "
              << inside[j * n + i] << " ("
              << 100. * inside[j * n + i] / volume[j]
              << "% of the body) lie inside " << Parameters::body_section(i)
              << ". Overlapping bodies put two masses in one place; move or "
                 "resize one of them (bodies may touch).";
            throw InputError(s.str());
          }
  }

  template void
  check_bodies_do_not_overlap<1>(const std::vector<Body<1>> &,
                                 const dealii::Particles::ParticleHandler<1> &,
                                 const std::string &,
                                 MPI_Comm);
  template void
  check_bodies_do_not_overlap<2>(const std::vector<Body<2>> &,
                                 const dealii::Particles::ParticleHandler<2> &,
                                 const std::string &,
                                 MPI_Comm);
  template void
  check_bodies_do_not_overlap<3>(const std::vector<Body<3>> &,
                                 const dealii::Particles::ParticleHandler<3> &,
                                 const std::string &,
                                 MPI_Comm);
} // namespace mpm
