#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_generator.h>

#include <mpm/grid/box_mesh.h>
#include <mpm/grid/mesh_reader.h>
#include <mpm/grid/quadrilateral_mesh.h>
#include <mpm/particles/body.h>
#include <mpm/shape_functions/q1_cell.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  using namespace dealii;

  std::string
  spatial_variables(const int dim)
  {
    return dim == 1 ? "x" : dim == 2 ? "x,y" : "x,y,z";
  }

  std::string
  load_variables(const int dim)
  {
    return dim == 1 ? "x,X" : dim == 2 ? "x,y,X,Y" : "x,y,z,X,Y,Z";
  }

  template <int dim>
  bool
  Body<dim>::has_body_force() const
  {
    if (!body_force.is_constant())
      return true;
    double b[dim];
    body_force.value({}, 0., b);
    for (unsigned int d = 0; d < dim; ++d)
      if (b[d] != 0.)
        return true;
    return false;
  }

  template <int dim>
  void
  create_body_mesh(Triangulation<dim>          &mesh,
                   const Parameters::Body<dim> &prm,
                   const std::string           &input_folder,
                   const std::string           &where)
  {
    using G = typename Parameters::Body<dim>::Geometry;
    switch (prm.geometry)
      {
        case G::box:
          create_box_mesh(mesh, prm.subdivisions, prm.lower, prm.upper);
          break;
        case G::ball:
          if constexpr (dim == 1)
            {
              GridGenerator::subdivided_hyper_cube(mesh,
                                                   1u << (prm.refinements + 1),
                                                   prm.center[0] - prm.radius,
                                                   prm.center[0] + prm.radius);
            }
          else
            {
              GridGenerator::hyper_ball_balanced(mesh, prm.center, prm.radius);
              mesh.refine_global(prm.refinements);
            }
          break;
        case G::quadrilateral:
          create_quadrilateral_mesh(mesh,
                                    prm.subdivisions,
                                    prm.corners,
                                    where + "/Corners");
          break;
        case G::mesh_file:
          read_mesh(mesh, prm.mesh_file, input_folder, where + "/Mesh file");
          break;
        case G::none: // no cells: the inflow brings the particles
          break;
      }
  }

  namespace
  {
    /// Visit the body-mesh cells with index in [first_cell, end_cell) in
    /// active-cell order, with their Q1 geometry.
    template <int dim, typename Function>
    void
    for_each_body_cell(const Triangulation<dim> &mesh,
                       const unsigned int        first_cell,
                       const unsigned int        end_cell,
                       const Function           &f)
    {
      using Cell              = shape_functions::Q1Cell<dim>;
      unsigned int cell_index = 0;
      for (const auto &cell : mesh.active_cell_iterators())
        {
          const unsigned int this_cell = cell_index++;
          if (this_cell < first_cell)
            continue;
          if (this_cell >= end_cell)
            break;
          std::array<Point<dim>, Cell::n_vertices> v;
          for (unsigned int i = 0; i < Cell::n_vertices; ++i)
            v[i] = cell->vertex(i);
          Cell geo;
          geo.reinit(v, 0.);
          f(cell, this_cell, geo);
        }
    }
  } // namespace

  template <int dim>
  void
  split_body_cells(const Triangulation<dim>              &mesh,
                   const unsigned int                     n,
                   const std::vector<types::boundary_id> &traction_ids,
                   const unsigned int                     first_cell,
                   const unsigned int                     end_cell,
                   std::vector<ParticleSeed<dim>>        &seeds,
                   std::vector<unsigned long long>       &seed_ids)
  {
    using Cell               = shape_functions::Q1Cell<dim>;
    const unsigned int n_sub = Utilities::fixed_power<dim>(n);
    const QGauss<dim>  gauss(2); // exact for det J of Q1 cells
    const QGauss<dim - 1 == 0 ? 1 : dim - 1> face_gauss(2);
    const double                             h = 1. / n;
    const double h_dim = std::pow(h, dim); // sub-cell volume in reference

    for_each_body_cell(
      mesh,
      first_cell,
      end_cell,
      [&](const auto &cell, const unsigned int this_cell, const Cell &geo) {
        for (unsigned int s = 0; s < n_sub; ++s)
          {
            unsigned int idx[dim];
            for (unsigned int d = 0, r = s; d < dim; ++d, r /= n)
              idx[d] = r % n;
            Point<dim> lower;
            for (unsigned int d = 0; d < dim; ++d)
              lower[d] = idx[d] * h;
            auto to_cell = [&](const Point<dim> &q) {
              Point<dim> xi;
              for (unsigned int d = 0; d < dim; ++d)
                xi[d] = lower[d] + h * q[d];
              return xi;
            };

            ParticleSeed<dim> seed;
            Point<dim>        centre;
            for (unsigned int d = 0; d < dim; ++d)
              centre[d] = 0.5;
            seed.position = geo.map(to_cell(centre));
            for (unsigned int q = 0; q < gauss.size(); ++q)
              seed.volume +=
                determinant(geo.jacobian(to_cell(gauss.point(q)))) *
                gauss.weight(q) * h_dim;
            if (!(seed.volume > 0))
              throw InputError("The body mesh has an inverted or degenerate "
                               "cell at " +
                               Utilities::to_string(cell->center()[0]) +
                               " ...: every cell needs a positive volume");
            const Tensor<2, dim> J = geo.jacobian(to_cell(centre));
            seed.domain            = 0.5 * h * J;
            for (unsigned int c = 0; c < Cell::n_vertices; ++c)
              {
                Point<dim> corner;
                for (unsigned int d = 0; d < dim; ++d)
                  corner[d] = (c >> d) & 1;
                seed.corners[c] = geo.map(to_cell(corner));
              }

            // Traction: sub-cells next to a loaded boundary face carry the
            // area of their part of it, and its centroid (the point the
            // traction acts at).
            Tensor<1, dim> face_moment;
            for (const unsigned int f : cell->face_indices())
              {
                if (!cell->face(f)->at_boundary())
                  continue;
                const auto id = cell->face(f)->boundary_id();
                if (std::find(traction_ids.begin(), traction_ids.end(), id) ==
                    traction_ids.end())
                  continue;
                const unsigned int normal_dir = f / 2, side = f % 2;
                if (idx[normal_dir] != (side ? n - 1 : 0))
                  continue;
                if constexpr (dim == 1)
                  {
                    seed.traction_area += 1.;
                    face_moment += geo.map(Point<dim>(double(side)));
                  }
                else
                  for (unsigned int q = 0; q < face_gauss.size(); ++q)
                    {
                      Point<dim> xi;
                      for (unsigned int d = 0, k = 0; d < dim; ++d)
                        xi[d] = (d == normal_dir) ?
                                  double(side) :
                                  lower[d] + h * face_gauss.point(q)[k++];
                      const Tensor<2, dim> Jf = geo.jacobian(xi);
                      double               da = 0;
                      if constexpr (dim == 2)
                        {
                          const unsigned int t = 1 - normal_dir;
                          da                   = std::hypot(Jf[0][t], Jf[1][t]);
                        }
                      else
                        {
                          Tensor<1, 3>       a, b;
                          const unsigned int t1 = (normal_dir + 1) % 3,
                                             t2 = (normal_dir + 2) % 3;
                          for (unsigned int d = 0; d < 3; ++d)
                            {
                              a[d] = Jf[d][t1];
                              b[d] = Jf[d][t2];
                            }
                          da = cross_product_3d(a, b).norm();
                        }
                      const double a =
                        da * face_gauss.weight(q) * std::pow(h, dim - 1);
                      seed.traction_area += a;
                      face_moment += a * geo.map(xi);
                    }
              }
            if (seed.traction_area > 0)
              seed.traction_offset =
                face_moment / seed.traction_area - seed.position;
            seeds.push_back(seed);
            seed_ids.push_back(
              static_cast<unsigned long long>(this_cell) * n_sub + s);
          }
      });
  }

  template <int dim>
  void
  split_body_cell_positions(const Triangulation<dim> &mesh,
                            const unsigned int        n,
                            const unsigned int        first_cell,
                            const unsigned int        end_cell,
                            std::vector<Point<dim>>  &positions)
  {
    // The seed positions of split_body_cells(), computed the same way.
    using Cell               = shape_functions::Q1Cell<dim>;
    const unsigned int n_sub = Utilities::fixed_power<dim>(n);
    const double       h     = 1. / n;
    for_each_body_cell(mesh,
                       first_cell,
                       end_cell,
                       [&](const auto &, unsigned int, const Cell &geo) {
                         for (unsigned int s = 0; s < n_sub; ++s)
                           {
                             Point<dim> xi;
                             for (unsigned int d = 0, r = s; d < dim;
                                  ++d, r /= n)
                               xi[d] = (r % n) * h + h * 0.5;
                             positions.push_back(geo.map(xi));
                           }
                       });
  }

  template struct Body<1>;
  template struct Body<2>;
  template struct Body<3>;
  template void
  create_body_mesh<1>(Triangulation<1> &,
                      const Parameters::Body<1> &,
                      const std::string &,
                      const std::string &);
  template void
  create_body_mesh<2>(Triangulation<2> &,
                      const Parameters::Body<2> &,
                      const std::string &,
                      const std::string &);
  template void
  create_body_mesh<3>(Triangulation<3> &,
                      const Parameters::Body<3> &,
                      const std::string &,
                      const std::string &);
  template void
  split_body_cells<1>(const Triangulation<1> &,
                      unsigned int,
                      const std::vector<types::boundary_id> &,
                      unsigned int,
                      unsigned int,
                      std::vector<ParticleSeed<1>> &,
                      std::vector<unsigned long long> &);
  template void
  split_body_cells<2>(const Triangulation<2> &,
                      unsigned int,
                      const std::vector<types::boundary_id> &,
                      unsigned int,
                      unsigned int,
                      std::vector<ParticleSeed<2>> &,
                      std::vector<unsigned long long> &);
  template void
  split_body_cells<3>(const Triangulation<3> &,
                      unsigned int,
                      const std::vector<types::boundary_id> &,
                      unsigned int,
                      unsigned int,
                      std::vector<ParticleSeed<3>> &,
                      std::vector<unsigned long long> &);
  template void
  split_body_cell_positions<1>(const Triangulation<1> &,
                               unsigned int,
                               unsigned int,
                               unsigned int,
                               std::vector<Point<1>> &);
  template void
  split_body_cell_positions<2>(const Triangulation<2> &,
                               unsigned int,
                               unsigned int,
                               unsigned int,
                               std::vector<Point<2>> &);
  template void
  split_body_cell_positions<3>(const Triangulation<3> &,
                               unsigned int,
                               unsigned int,
                               unsigned int,
                               std::vector<Point<3>> &);
} // namespace mpm
