#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <mpm/grid/grid_parameters.h>
#include <mpm/particles/particle_index.h>
#include <mpm/shape_functions/q1_cell.h>

#include <array>
#include <memory>
#include <vector>

namespace mpm
{
  using NodalVector = dealii::LinearAlgebra::distributed::Vector<double>;

  /**
   * The Q1 background grid: the triangulation (distributed with p4est in
   * 2D/3D, serial in 1D), its degrees of freedom (one per vertex = grid
   * node), the geometry of every cell for direct Q1 evaluation, and the
   * boundary constraints of the nodes.
   *
   * Nodal quantities are stored "packed": n_components values per node,
   * node-major, in a distributed vector whose local numbering matches
   * local_node(): node-local index i, component c is entry i*nc + c.
   */
  template <int dim>
  class BackgroundGrid
  {
  public:
    static constexpr unsigned int n_vertices = shape_functions::n_q1<dim>;

    explicit BackgroundGrid(const MPI_Comm comm);

    /// Build the triangulation; mesh paths are tried relative to
    /// @p input_folder first. Throws InputError on bad input. With
    /// @p coarse_only, no refinement (for loading a checkpoint into it).
    void
    create(const Parameters::Grid<dim> &prm,
           const std::string           &input_folder,
           const bool                   coarse_only = false);

    /// Distribute nodes, cache cell geometry and node constraints. Called
    /// again after a repartition: rebuilds everything of the partition.
    void
    setup(const Parameters::BoundaryConditions &bc);

    dealii::Triangulation<dim> &
    triangulation()
    {
      return *tria;
    }
    const dealii::Triangulation<dim> &
    triangulation() const
    {
      return *tria;
    }
    const dealii::Mapping<dim> &
    mapping() const
    {
      return *mapping_ptr;
    }
    const dealii::DoFHandler<dim> &
    dof_handler() const
    {
      return dofs;
    }

    using ActiveCell =
      typename dealii::Triangulation<dim>::active_cell_iterator;

    /// The locally owned active cells, in active cell index order: what
    /// the particle loops walk (without deal.II's search for the first
    /// active cell through every coarser level at each loop).
    const std::vector<ActiveCell> &
    owned_cells() const
    {
      return owned_cell_list;
    }

    /// The locally owned particles by cell (cells in active cell index
    /// order), as of the last particle loop: kept and rebuilt by
    /// for_each_cell_with_particles() (particles/cell_loop.h), emptied
    /// whenever the grid's cells change.
    ParticleIndex<dim> &
    particle_index() const
    {
      return index;
    }

    /// Particles may be in other cells or other places of the handler's
    /// storage now (moved, sorted, inserted, removed, restored): the next
    /// particle loop rebuilds particle_index().
    void
    particles_changed_cells() const
    {
      index.invalidate();
    }

    /// Geometry of an owned or ghost cell.
    const shape_functions::Q1Cell<dim> &
    geometry(const typename dealii::Triangulation<dim>::active_cell_iterator
               &cell) const
    {
      return cell_geometry[cell->active_cell_index()];
    }

    /// Node-local indices of a cell's vertices (deal.II vertex order).
    const unsigned int *
    nodes(const typename dealii::Triangulation<dim>::active_cell_iterator &cell)
      const
    {
      return &cell_nodes[cell->active_cell_index() * n_vertices];
    }

    /// The same by active cell index (owned or ghost cells).
    const shape_functions::Q1Cell<dim> &
    geometry(const unsigned int cell_index) const
    {
      return cell_geometry[cell_index];
    }
    const unsigned int *
    nodes(const unsigned int cell_index) const
    {
      return &cell_nodes[cell_index * n_vertices];
    }

    /// face_neighbor() across a boundary face.
    static constexpr unsigned int outside_grid =
      dealii::numbers::invalid_unsigned_int - 1;
    /// face_neighbor() of a neighbour this rank does not know (artificial)
    /// or that is refined or coarser (no single cell across the face).
    static constexpr unsigned int unknown_cell =
      dealii::numbers::invalid_unsigned_int;

    /**
     * Active cell index of the neighbour of an owned or ghost cell across
     * face @p face (deal.II face order), or outside_grid / unknown_cell.
     * Lets the particle-domain families walk the grid by index.
     */
    unsigned int
    face_neighbor(const unsigned int cell_index, const unsigned int face) const
    {
      return neighbors[cell_index * 2 * dim + face];
    }

    /// Smallest height of a cell (for the CFL condition).
    double
    cell_height(const typename dealii::Triangulation<dim>::active_cell_iterator
                  &cell) const
    {
      return cell_heights[cell->active_cell_index()];
    }

    /// Number of owned nodes (they come first in the local numbering).
    unsigned int
    n_owned_nodes() const
    {
      return n_owned;
    }
    /// Owned plus ghost nodes.
    unsigned int
    n_local_nodes() const
    {
      return n_owned + n_ghost;
    }
    const dealii::Point<dim> &
    node_position(const unsigned int i) const
    {
      return node_positions[i];
    }

    /// Whether every cell of the whole grid is an axis-parallel box.
    bool
    is_cartesian() const
    {
      return cartesian;
    }

    /// A vector with @p n_components values per node.
    void
    initialize_vector(NodalVector &v, const unsigned int n_components) const;

    /// Remove the constrained components of a nodal vector quantity
    /// (fixed: all, slip: the normal ones) at owned node i.
    void
    constrain(const unsigned int i, double *value) const
    {
      const auto c = constraint_of_node[i];
      if (c == dealii::numbers::invalid_unsigned_int)
        return;
      const auto &nc = constraints[c];
      for (unsigned int k = 0; k < nc.n_normals; ++k)
        {
          double dot = 0;
          for (unsigned int d = 0; d < dim; ++d)
            dot += value[d] * nc.normals[k][d];
          for (unsigned int d = 0; d < dim; ++d)
            value[d] -= dot * nc.normals[k][d];
        }
    }

    /// Number of constrained directions of node i (owned or ghost, the
    /// owner's at a ghost): dim at a fixed node, one per wall at a slip
    /// node, 0 if free.
    unsigned int
    n_constrained_directions(const unsigned int i) const
    {
      const auto c = constraint_of_node[i];
      return c == dealii::numbers::invalid_unsigned_int ?
               0 :
               constraints[c].n_normals;
    }

    /// Whether node i (owned or ghost, the owner's at a ghost) lies on a
    /// face of Boundary conditions/Moving boundary ids and on no fixed
    /// face: it moves with the boundary in the directions no wall
    /// constrains.
    bool
    on_moving_boundary(const unsigned int i) const
    {
      return moving_node[i] != 0;
    }

    /// Constrained direction k of node i (orthonormal to the others).
    const dealii::Tensor<1, dim> &
    constrained_direction(const unsigned int i, const unsigned int k) const
    {
      return constraints[constraint_of_node[i]].normals[k];
    }

    /// Global grid statistics for the screen.
    dealii::types::global_cell_index
    n_global_cells() const
    {
      return tria->n_global_active_cells();
    }
    dealii::types::global_dof_index
    n_global_nodes() const
    {
      return dofs.n_dofs();
    }


    /**
     * Set-up helper: for each point, the owned cell that contains it and
     * the reference coordinates there, or an end iterator if no owned cell
     * does. A point on a face between cells is given to exactly one of
     * them (the test uses the point shifted by a tiny fixed offset), so
     * ranks never both claim it. Uses a temporary bucket lattice over the
     * owned cells: O(1) per point.
     */
    void
    locate_in_owned_cells(
      const std::vector<dealii::Point<dim>> &points,
      std::vector<typename dealii::Triangulation<dim>::active_cell_iterator>
                                      &cells,
      std::vector<dealii::Point<dim>> &reference_points) const;

    /**
     * locate_in_owned_cells() for many calls: the bucket lattice over the
     * owned cells is built once, at construction, and reused by every
     * locate() (set-up locates the particles of a body chunk by chunk).
     * Gives the same cells and reference coordinates as
     * locate_in_owned_cells(). Valid while the grid is not changed.
     */
    class OwnedCellLocator
    {
    public:
      explicit OwnedCellLocator(const BackgroundGrid<dim> &grid);

      void
      locate(
        const std::vector<dealii::Point<dim>> &points,
        std::vector<typename dealii::Triangulation<dim>::active_cell_iterator>
                                        &cells,
        std::vector<dealii::Point<dim>> &reference_points) const;

    private:
      const BackgroundGrid<dim>     &grid;
      const std::vector<ActiveCell> &owned; // grid.owned_cells()
      dealii::Point<dim>             lo, hi;
      double                         size = 0;
      std::array<unsigned int, dim>  n;
      /// Owned cells (indices into owned) of bucket b, ascending:
      /// bucket_cells[bucket_start[b] .. bucket_start[b+1]).
      std::vector<unsigned int> bucket_start, bucket_cells;
    };

    /// Bounding box of the owned cells of this rank (empty: lower > upper).
    std::pair<dealii::Point<dim>, dealii::Point<dim>>
    owned_bounding_box() const;

    /// The scalar partitioner (one entry per node).
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner>
    node_partitioner() const
    {
      return partitioner;
    }

  private:
    struct NodeConstraint
    {
      unsigned int                            n_normals = 0;
      std::array<dealii::Tensor<1, dim>, dim> normals;
    };

    /// Ghost nodes get their owner's constraint and moving-boundary flag
    /// (complete: the owner sees every cell at the node).
    void
    take_owners_constraints();

    MPI_Comm                                                   comm;
    std::unique_ptr<dealii::Triangulation<dim>>                tria;
    std::unique_ptr<dealii::Mapping<dim>>                      mapping_ptr;
    dealii::FE_Q<dim>                                          fe;
    dealii::DoFHandler<dim>                                    dofs;
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner;
    std::vector<shape_functions::Q1Cell<dim>>                  cell_geometry;
    std::vector<ActiveCell>                                    owned_cell_list;
    mutable ParticleIndex<dim>                                 index;
    std::vector<unsigned int>                                  cell_nodes;
    std::vector<unsigned int>                                  neighbors;
    std::vector<double>                                        cell_heights;
    std::vector<dealii::Point<dim>>                            node_positions;
    std::vector<unsigned int>   constraint_of_node;
    std::vector<NodeConstraint> constraints;
    std::vector<char>           moving_node; ///< on_moving_boundary()
    unsigned int                n_owned = 0, n_ghost = 0;
    bool                        cartesian = false;
  };
} // namespace mpm
