#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <mpm/grid/background_grid.h>
#include <mpm/grid/box_mesh.h>
#include <mpm/grid/mesh_reader.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  using namespace dealii;

  template <int dim>
  BackgroundGrid<dim>::BackgroundGrid(const MPI_Comm comm)
    : comm(comm)
    , fe(1)
  {
    if constexpr (dim == 1)
      {
        // p4est has no 1D; 1D models are small, so they run on one rank.
        if (Utilities::MPI::n_mpi_processes(comm) > 1)
          throw InputError("Dimension = 1 runs on one MPI rank only; start "
                           "it without mpirun or with -np 1");
        tria = std::make_unique<Triangulation<dim>>();
      }
    else
      tria = std::make_unique<parallel::distributed::Triangulation<dim>>(
        comm,
        Triangulation<dim>::limit_level_difference_at_vertices,
        parallel::distributed::Triangulation<dim>::default_setting);
  }

  template <int dim>
  void
  BackgroundGrid<dim>::create(const Parameters::Grid<dim> &prm,
                              const std::string           &input_folder,
                              const bool                   coarse_only)
  {
    if (prm.type == Parameters::Grid<dim>::Type::hyper_rectangle)
      create_box_mesh(
        *tria, prm.subdivisions, prm.lower, prm.upper, !coarse_only);
    else
      read_mesh(*tria, prm.mesh_file, input_folder, "Grid/Mesh file");
    if (prm.global_refinements > 0 && !coarse_only)
      tria->refine_global(prm.global_refinements);
  }

  template <int dim>
  void
  BackgroundGrid<dim>::setup(const Parameters::BoundaryConditions &bc)
  {
    dofs.reinit(*tria);
    dofs.distribute_dofs(fe);
    const IndexSet owned = dofs.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    partitioner =
      std::make_shared<Utilities::MPI::Partitioner>(owned, relevant, comm);
    n_owned = partitioner->locally_owned_size();
    n_ghost = partitioner->n_ghost_indices();

    owned_cell_list.clear();
    index.clear();
    particles_changed_cells();
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        owned_cell_list.push_back(cell);

    // Cell geometry, node numbering and heights for owned and ghost cells.
    const unsigned int n_cells = tria->n_active_cells();
    cell_geometry.assign(n_cells, {});
    cell_nodes.assign(n_cells * n_vertices, numbers::invalid_unsigned_int);
    cell_heights.assign(n_cells, 0.);
    node_positions.assign(n_owned + n_ghost, Point<dim>());
    bool                                 all_boxes = true;
    std::vector<types::global_dof_index> dof_indices(n_vertices);
    for (const auto &cell : dofs.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        std::array<Point<dim>, n_vertices> v;
        for (unsigned int i = 0; i < n_vertices; ++i)
          v[i] = cell->vertex(i);
        // Round-off in vertex coordinates scales with their magnitude.
        double size = 0;
        for (const auto &x : v)
          size = std::max(size, x.norm());
        const double h = cell->minimum_vertex_distance();
        auto        &g = cell_geometry[cell->active_cell_index()];
        g.reinit(v, 1e-12 * h + 1e-14 * size);
        all_boxes = all_boxes && g.is_box;

        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < n_vertices; ++i)
          {
            const unsigned int local =
              partitioner->global_to_local(dof_indices[i]);
            cell_nodes[cell->active_cell_index() * n_vertices + i] = local;
            node_positions[local]                                  = v[i];
          }

        // Smallest height = measure / largest face measure (exact for
        // boxes and parallelograms, a safe estimate otherwise).
        double max_face = 1;
        if constexpr (dim > 1)
          {
            max_face = 0;
            for (const unsigned int f : cell->face_indices())
              max_face = std::max(max_face, cell->face(f)->measure());
          }
        cell_heights[cell->active_cell_index()] = cell->measure() / max_face;
      }
    // Face neighbours by index, for the walks of the domain families.
    neighbors.assign(n_cells * 2 * dim, unknown_cell);
    for (const auto &cell : tria->active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            unsigned int &n =
              neighbors[cell->active_cell_index() * 2 * dim + f];
            if (cell->at_boundary(f))
              n = outside_grid;
            else
              {
                const auto next = cell->neighbor(f);
                if (!next->has_children() && !next->is_artificial() &&
                    next->level() == cell->level())
                  n = next->active_cell_index();
              }
          }
      }
    cartesian = Utilities::MPI::min(all_boxes ? 1 : 0, comm) == 1;
    // After a repartition (setup() again) the mapping stays: the particle
    // handler holds it, and the union of owned and ghost cells over the
    // ranks is still the whole grid, so the choice is the same.
    if (!mapping_ptr)
      {
        if (cartesian)
          mapping_ptr = std::make_unique<MappingCartesian<dim>>();
        else
          mapping_ptr = std::make_unique<MappingQ1<dim>>();
      }

    // Node constraints from boundary faces of owned and ghost cells: every
    // owned node sees all its adjacent cells there.
    std::vector<std::vector<Tensor<1, dim>>> normals(n_owned + n_ghost);
    std::vector<bool>                        fixed(n_owned + n_ghost, false);
    moving_node.assign(n_owned + n_ghost, 0);
    auto contains = [](const std::vector<types::boundary_id> &ids,
                       const types::boundary_id               id) {
      return std::find(ids.begin(), ids.end(), id) != ids.end();
    };
    for (const auto &cell : dofs.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const auto id       = cell->face(f)->boundary_id();
            const bool is_fixed = contains(bc.fixed, id);
            const bool is_slip  = contains(bc.slip, id);
            if (contains(bc.moving, id))
              for (const unsigned int v : cell->face(f)->vertex_indices())
                moving_node[cell_nodes[cell->active_cell_index() * n_vertices +
                                       GeometryInfo<dim>::face_to_cell_vertices(
                                         f, v)]] = 1;
            if (!is_fixed && !is_slip)
              continue;
            // Outward unit normal of the (straight) face at its centre.
            Tensor<1, dim> n;
            if constexpr (dim == 1)
              n[0] = (f == 0) ? -1. : 1.;
            else if constexpr (dim == 2)
              {
                const Tensor<1, dim> t =
                  cell->face(f)->vertex(1) - cell->face(f)->vertex(0);
                n[0] = t[1];
                n[1] = -t[0];
              }
            else
              {
                const auto face = cell->face(f);
                n = cross_product_3d(face->vertex(3) - face->vertex(0),
                                     face->vertex(2) - face->vertex(1));
              }
            n /= n.norm();
            if constexpr (dim > 1)
              if ((cell->face(f)->center() - cell->center()) * n < 0)
                n = -n;
            for (const unsigned int v : cell->face(f)->vertex_indices())
              {
                const unsigned int local =
                  cell_nodes[cell->active_cell_index() * n_vertices +
                             GeometryInfo<dim>::face_to_cell_vertices(f, v)];
                if (is_fixed)
                  fixed[local] = true;
                else
                  normals[local].push_back(n);
              }
          }
      }
    // (a fixed node does not move with a boundary)
    for (unsigned int i = 0; i < n_owned + n_ghost; ++i)
      if (fixed[i])
        moving_node[i] = 0;
    constraint_of_node.assign(n_owned + n_ghost, numbers::invalid_unsigned_int);
    constraints.clear();
    for (unsigned int i = 0; i < n_owned + n_ghost; ++i)
      {
        NodeConstraint c;
        if (fixed[i])
          {
            c.n_normals = dim;
            for (unsigned int d = 0; d < dim; ++d)
              {
                c.normals[d]    = Tensor<1, dim>();
                c.normals[d][d] = 1.;
              }
          }
        else
          {
            // Faces of one smooth wall (a faceted circle, say) differ by
            // small angles: they form one direction, their mean normal.
            // Only faces meeting at a real corner (more than 30 degrees)
            // add a direction.
            std::vector<Tensor<1, dim>> walls;
            for (const auto &n : normals[i])
              {
                bool merged = false;
                for (auto &w : walls)
                  if (n * w / w.norm() > std::cos(M_PI / 6))
                    {
                      w += n;
                      merged = true;
                      break;
                    }
                if (!merged)
                  walls.push_back(n);
              }
            for (const auto &w : walls)
              {
                // Gram-Schmidt: keep only directions not yet constrained.
                Tensor<1, dim> m = w / w.norm();
                for (unsigned int k = 0; k < c.n_normals; ++k)
                  m -= (m * c.normals[k]) * c.normals[k];
                if (m.norm() > 1e-6 && c.n_normals < dim)
                  c.normals[c.n_normals++] = m / m.norm();
              }
          }
        if (c.n_normals > 0)
          {
            constraint_of_node[i] = constraints.size();
            constraints.push_back(c);
          }
      }
    take_owners_constraints();
  }

  template <int dim>
  void
  BackgroundGrid<dim>::take_owners_constraints()
  {
    // A ghost node that no owned cell touches may miss walls of cells
    // beyond the ghost layer; its owner sees them all. The implicit step
    // condenses the constraints of every node its particles reach, so all
    // ranks need the owner's (also where the sums of merged normals differ
    // by round-off between ranks).
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    // per node: moving flag, number of normals, normals
    constexpr unsigned int nc = 2 + dim * dim;
    NodalVector            data;
    initialize_vector(data, nc);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        data.local_element(i * nc + 1 + dim * dim) = moving_node[i];
        const auto c                               = constraint_of_node[i];
        if (c == numbers::invalid_unsigned_int)
          continue;
        data.local_element(i * nc) = constraints[c].n_normals;
        for (unsigned int k = 0; k < constraints[c].n_normals; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            data.local_element(i * nc + 1 + k * dim + d) =
              constraints[c].normals[k][d];
      }
    data.update_ghost_values();
    for (unsigned int i = n_owned; i < n_owned + n_ghost; ++i)
      {
        moving_node[i] = data.local_element(i * nc + 1 + dim * dim) != 0;
        NodeConstraint c;
        c.n_normals = static_cast<unsigned int>(data.local_element(i * nc));
        for (unsigned int k = 0; k < c.n_normals; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            c.normals[k][d] = data.local_element(i * nc + 1 + k * dim + d);
        if (c.n_normals == 0)
          constraint_of_node[i] = numbers::invalid_unsigned_int;
        else
          {
            constraint_of_node[i] = constraints.size();
            constraints.push_back(c);
          }
      }
  }

  template <int dim>
  void
  BackgroundGrid<dim>::initialize_vector(NodalVector       &v,
                                         const unsigned int nc) const
  {
    // Owned dofs of one rank are a contiguous range, so the packed
    // numbering keeps owned entries first and ghosts sorted by node.
    const IndexSet &owned_nodes = partitioner->locally_owned_range();
    const IndexSet &ghost_nodes = partitioner->ghost_indices();
    IndexSet owned(partitioner->size() * nc), ghost(partitioner->size() * nc);
    for (auto it = owned_nodes.begin_intervals();
         it != owned_nodes.end_intervals();
         ++it)
      owned.add_range(*it->begin() * nc, (it->last() + 1) * nc);
    for (const auto g : ghost_nodes)
      ghost.add_range(g * nc, (g + 1) * nc);
    owned.compress();
    ghost.compress();
    v.reinit(owned, ghost, comm);
  }

  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  BackgroundGrid<dim>::owned_bounding_box() const
  {
    Point<dim> lo, hi;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lo[d] = std::numeric_limits<double>::max();
        hi[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              lo[d] = std::min(lo[d], cell->vertex(v)[d]);
              hi[d] = std::max(hi[d], cell->vertex(v)[d]);
            }
    return {lo, hi};
  }

  template <int dim>
  void
  BackgroundGrid<dim>::locate_in_owned_cells(
    const std::vector<Point<dim>>                                  &points,
    std::vector<typename Triangulation<dim>::active_cell_iterator> &cells,
    std::vector<Point<dim>> &reference_points) const
  {
    OwnedCellLocator(*this).locate(points, cells, reference_points);
  }

  template <int dim>
  BackgroundGrid<dim>::OwnedCellLocator::OwnedCellLocator(
    const BackgroundGrid<dim> &grid)
    : grid(grid)
    , owned(grid.owned_cell_list)
  {
    // The owned cells' bounding boxes, from the cached vertices (the same
    // values as cell->bounding_box(), without deal.II's vertex look-ups).
    for (unsigned int d = 0; d < dim; ++d)
      {
        lo[d] = std::numeric_limits<double>::max();
        hi[d] = -std::numeric_limits<double>::max();
      }
    double max_extent = 0;
    for (const auto &cell : owned)
      {
        const auto &v = grid.cell_geometry[cell->active_cell_index()].vertices;
        for (unsigned int d = 0; d < dim; ++d)
          {
            double a = v[0][d], b = v[0][d];
            for (unsigned int i = 1; i < v.size(); ++i)
              {
                a = std::min(a, v[i][d]);
                b = std::max(b, v[i][d]);
              }
            lo[d]      = std::min(lo[d], a);
            hi[d]      = std::max(hi[d], b);
            max_extent = std::max(max_extent, b - a);
          }
      }
    if (owned.empty())
      return;

    // Bucket lattice with about one bucket per owned cell.
    double volume = 1;
    for (unsigned int d = 0; d < dim; ++d)
      volume *= std::max(hi[d] - lo[d], 1e-300);
    size = std::max(max_extent, std::pow(volume / owned.size(), 1. / dim));
    for (unsigned int d = 0; d < dim; ++d)
      n[d] =
        std::max(1u, static_cast<unsigned int>((hi[d] - lo[d]) / size) + 1);
    std::size_t n_buckets = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_buckets *= n[d];

    // Each cell goes to every bucket its bounding box touches; stored
    // compressed (counts, then the cells in ascending order per bucket).
    auto for_each_bucket_of_cell = [&](const unsigned int c, const auto &f) {
      const auto &v =
        grid.cell_geometry[owned[c]->active_cell_index()].vertices;
      std::array<long, dim> first, last;
      for (unsigned int d = 0; d < dim; ++d)
        {
          double a = v[0][d], b = v[0][d];
          for (unsigned int i = 1; i < v.size(); ++i)
            {
              a = std::min(a, v[i][d]);
              b = std::max(b, v[i][d]);
            }
          first[d] = std::max<long>(0, std::floor((a - lo[d]) / size));
          last[d]  = std::min<long>(n[d] - 1, std::floor((b - lo[d]) / size));
        }
      std::array<long, dim> i = first;
      while (true)
        {
          long index = 0, stride = 1;
          for (unsigned int d = 0; d < dim; ++d)
            {
              index += i[d] * stride;
              stride *= n[d];
            }
          f(index);
          unsigned int d = 0;
          for (; d < dim; ++d)
            {
              if (++i[d] <= last[d])
                break;
              i[d] = first[d];
            }
          if (d == dim)
            break;
        }
    };
    // size >= every cell's extent: a cell touches at most 2^dim buckets.
    AssertThrow((owned.size() << dim) <
                  std::numeric_limits<unsigned int>::max(),
                ExcMessage("Too many owned cells for the set-up's cell "
                           "locator on one rank"));
    bucket_start.assign(n_buckets + 1, 0);
    for (unsigned int c = 0; c < owned.size(); ++c)
      for_each_bucket_of_cell(c, [&](const long b) { ++bucket_start[b + 1]; });
    for (std::size_t b = 0; b < n_buckets; ++b)
      bucket_start[b + 1] += bucket_start[b];
    bucket_cells.resize(bucket_start[n_buckets]);
    std::vector<unsigned int> next(bucket_start.begin(),
                                   bucket_start.end() - 1);
    for (unsigned int c = 0; c < owned.size(); ++c)
      for_each_bucket_of_cell(c, [&](const long b) {
        bucket_cells[next[b]++] = c;
      });
  }

  template <int dim>
  void
  BackgroundGrid<dim>::OwnedCellLocator::locate(
    const std::vector<Point<dim>>                                  &points,
    std::vector<typename Triangulation<dim>::active_cell_iterator> &cells,
    std::vector<Point<dim>> &reference_points) const
  {
    const auto &tria = *grid.tria;
    cells.assign(points.size(), tria.end_active(tria.n_levels() - 1));
    reference_points.assign(points.size(), Point<dim>());
    if (owned.empty())
      return;

    auto bucket_of = [&](const Point<dim> &x) -> long {
      long index = 0, stride = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const long i = static_cast<long>(std::floor((x[d] - lo[d]) / size));
          if (i < 0 || i >= long(n[d]))
            return -1;
          index += i * stride;
          stride *= n[d];
        }
      return index;
    };

    // Tie-break for points on faces: test a slightly shifted point with
    // half-open intervals.
    Tensor<1, dim> shift;
    for (unsigned int d = 0; d < dim; ++d)
      shift[d] = 1e-9 * size * (1. - 0.3 * d);
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5;
    for (std::size_t p = 0; p < points.size(); ++p)
      {
        const Point<dim> x = points[p] + shift;
        const long       b = bucket_of(x);
        if (b < 0)
          continue;
        for (unsigned int k = bucket_start[b]; k < bucket_start[b + 1]; ++k)
          {
            const unsigned int c = bucket_cells[k];
            const auto &geo = grid.cell_geometry[owned[c]->active_cell_index()];
            const Point<dim> xi     = geo.inverse_map(x, centre);
            bool             inside = true;
            for (unsigned int d = 0; d < dim; ++d)
              inside = inside && xi[d] >= 0. && xi[d] < 1.;
            if (inside)
              {
                cells[p]       = owned[c];
                Point<dim> xi0 = geo.inverse_map(points[p], xi);
                for (unsigned int d = 0; d < dim; ++d)
                  xi0[d] = std::min(1., std::max(0., xi0[d]));
                reference_points[p] = xi0;
                break;
              }
          }
      }
  }

  template class BackgroundGrid<1>;
  template class BackgroundGrid<2>;
  template class BackgroundGrid<3>;
} // namespace mpm
