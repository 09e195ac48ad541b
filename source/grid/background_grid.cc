#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <mpm/grid/background_grid.h>
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
        Triangulation<dim>::maximum_smoothing,
        parallel::distributed::Triangulation<dim>::default_setting);
  }

  template <int dim>
  void
  BackgroundGrid<dim>::create(const Parameters::Grid<dim> &prm,
                              const std::string &          input_folder)
  {
    if (prm.type == Parameters::Grid<dim>::Type::hyper_rectangle)
      GridGenerator::subdivided_hyper_rectangle(
        *tria, prm.subdivisions, prm.lower, prm.upper, /*colorize=*/true);
    else
      read_mesh(*tria, prm.mesh_file, input_folder, "Grid/Mesh file");
    if (prm.global_refinements > 0)
      tria->refine_global(prm.global_refinements);
  }

  template <int dim>
  void
  BackgroundGrid<dim>::setup(const Parameters::BoundaryConditions &bc)
  {
    dofs.reinit(*tria);
    dofs.distribute_dofs(fe);
    const IndexSet owned    = dofs.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    partitioner =
      std::make_shared<Utilities::MPI::Partitioner>(owned, relevant, comm);
    n_owned = partitioner->locally_owned_size();
    n_ghost = partitioner->n_ghost_indices();

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
        const double h = cell->minimum_vertex_distance();
        auto &       g = cell_geometry[cell->active_cell_index()];
        g.reinit(v, 1e-12 * h);
        all_boxes = all_boxes && g.is_box;

        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < n_vertices; ++i)
          {
            const unsigned int local =
              partitioner->global_to_local(dof_indices[i]);
            cell_nodes[cell->active_cell_index() * n_vertices + i] = local;
            node_positions[local]                                   = v[i];
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
    cartesian = Utilities::MPI::min(all_boxes ? 1 : 0, comm) == 1;
    if (cartesian)
      mapping_ptr = std::make_unique<MappingCartesian<dim>>();
    else
      mapping_ptr = std::make_unique<MappingQ1<dim>>();

    // Node constraints from boundary faces of owned and ghost cells: every
    // owned node sees all its adjacent cells there.
    std::vector<std::vector<Tensor<1, dim>>> normals(n_owned + n_ghost);
    std::vector<bool>                        fixed(n_owned + n_ghost, false);
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
          for (const auto &n : normals[i])
            {
              // Gram-Schmidt: keep only directions not yet constrained.
              Tensor<1, dim> m = n;
              for (unsigned int k = 0; k < c.n_normals; ++k)
                m -= (m * c.normals[k]) * c.normals[k];
              if (m.norm() > 1e-6 && c.n_normals < dim)
                c.normals[c.n_normals++] = m / m.norm();
            }
        if (c.n_normals > 0)
          {
            constraint_of_node[i] = constraints.size();
            constraints.push_back(c);
          }
      }
  }

  template <int dim>
  void
  BackgroundGrid<dim>::initialize_vector(NodalVector &      v,
                                         const unsigned int nc) const
  {
    // Owned dofs of one rank are a contiguous range, so the packed
    // numbering keeps owned entries first and ghosts sorted by node.
    const IndexSet &owned_nodes = partitioner->locally_owned_range();
    const IndexSet &ghost_nodes = partitioner->ghost_indices();
    IndexSet        owned(partitioner->size() * nc), ghost(partitioner->size() * nc);
    for (auto it = owned_nodes.begin_intervals(); it != owned_nodes.end_intervals();
         ++it)
      owned.add_range(*it->begin() * nc, (it->last() + 1) * nc);
    for (const auto g : ghost_nodes)
      ghost.add_range(g * nc, (g + 1) * nc);
    owned.compress();
    ghost.compress();
    v.reinit(owned, ghost, comm);
  }

  template <int dim>
  std::vector<std::vector<BoundingBox<dim>>>
  BackgroundGrid<dim>::global_bounding_boxes() const
  {
    // One box around the owned cells per rank. (deal.II 9.4's
    // compute_mesh_predicate_bounding_box crashes on unrefined coarse
    // meshes.) Overlapping boxes only cost extra messages at set-up:
    // the owner is decided by the cells themselves.
    std::vector<BoundingBox<dim>> local;
    Point<dim> lo, hi;
    bool       first = true;
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const Point<dim> &x = cell->vertex(v);
            for (unsigned int d = 0; d < dim; ++d)
              {
                lo[d] = first ? x[d] : std::min(lo[d], x[d]);
                hi[d] = first ? x[d] : std::max(hi[d], x[d]);
              }
            first = false;
          }
    if (!first)
      local.emplace_back(std::make_pair(lo, hi));
    return Utilities::MPI::all_gather(comm, local);
  }

  template class BackgroundGrid<1>;
  template class BackgroundGrid<2>;
  template class BackgroundGrid<3>;
} // namespace mpm
