#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/grid/grid_tools.h>

#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_relocation.h>

#include <map>
#include <vector>

namespace mpm
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    using CellIterator = typename Triangulation<dim>::active_cell_iterator;

    /**
     * Starting from @p cell, walk across the face with the largest
     * violation of 0 <= xi <= 1 until x lies inside a cell (at most
     * 2 dim hops). Returns false if the walk leaves the locally known
     * part of the grid (boundary, artificial or refined neighbour).
     */
    template <int dim>
    bool
    find_cell(const BackgroundGrid<dim> &grid,
              CellIterator<dim>          cell,
              const Point<dim>          &x,
              Point<dim>                 xi,
              CellIterator<dim>         &found,
              Point<dim>                &found_xi)
    {
      for (unsigned int hop = 0; hop < 2 * dim; ++hop)
        {
          const unsigned int face =
            shape_functions::Q1Cell<dim>::most_violated_face(xi);
          if (face == numbers::invalid_unsigned_int)
            return false;
          if (cell->at_boundary(face))
            return false;
          const auto next = cell->neighbor(face);
          if (next->has_children() || next->is_artificial())
            return false;
          cell = next;
          xi   = grid.geometry(cell).inverse_map(x, xi);
          if (shape_functions::Q1Cell<dim>::is_inside(xi))
            {
              found    = cell;
              found_xi = xi;
              return true;
            }
        }
      return false;
    }

    /// The locally owned cell that contains @p x (and x's reference
    /// coordinates there), if there is one: a search of the whole local
    /// grid, for the rare particle that moved beyond the ghost layer.
    template <int dim>
    bool
    owned_cell_around(const Triangulation<dim> &tria,
                      const Point<dim>         &x,
                      CellIterator<dim>        &cell,
                      Point<dim>               &xi)
    {
      try
        {
          const auto found = GridTools::find_active_cell_around_point(
            StaticMappingQ1<dim>::mapping, tria, x);
          if (found.first.state() != IteratorState::valid ||
              !found.first->is_locally_owned())
            return false;
          cell = found.first;
          xi   = found.second;
          return true;
        }
      catch (...)
        {
          return false;
        }
    }

    /// A particle on its way to another cell: everything to re-insert it.
    template <int dim>
    struct Moving
    {
      CellIterator<dim>     cell;
      Point<dim>            x, xi;
      types::particle_index id;
      std::vector<double>   properties;
    };
  } // namespace

  template <int dim>
  bool
  relocate_particles(const BackgroundGrid<dim>       &grid,
                     Particles::ParticleHandler<dim> &particles,
                     const MPI_Comm                   comm)
  {
    const unsigned int n_props = particles.n_properties_per_particle();
    std::vector<typename Particles::ParticleHandler<dim>::particle_iterator>
                                                leaving;
    std::vector<Moving<dim>>                    local_moves;
    std::map<unsigned int, std::vector<double>> to_send;
    bool                                        unplaced = false;
    /// particles that left the locally known grid (x, iterator)
    std::vector<
      std::pair<Point<dim>,
                typename Particles::ParticleHandler<dim>::particle_iterator>>
      far;

    for_each_cell_with_particles(
      grid, particles, [&](const auto &cell, const auto &pic) {
        const auto &geo = grid.geometry(cell);
        for (auto it = pic.begin(); it != pic.end(); ++it)
          {
            const Point<dim> x = it->get_location();
            const Point<dim> xi =
              geo.inverse_map(x, it->get_reference_location());
            if (shape_functions::Q1Cell<dim>::is_inside(xi))
              {
                it->set_reference_location(xi);
                continue;
              }
            CellIterator<dim> target;
            Point<dim>        target_xi;
            if (!find_cell(grid, cell, x, xi, target, target_xi))
              {
                far.emplace_back(x, pic.handler_iterator(*it));
                continue;
              }
            const auto props = it->get_properties();
            if (target->is_locally_owned())
              local_moves.push_back(
                {target,
                 x,
                 target_xi,
                 it->get_id(),
                 std::vector<double>(props.begin(), props.end())});
            else
              {
                // Packed as: cell id (binary), id, x, xi, properties.
                auto      &buffer = to_send[target->subdomain_id()];
                const auto cid    = target->id().template to_binary<dim>();
                for (const auto c : cid)
                  buffer.push_back(static_cast<double>(c));
                buffer.push_back(static_cast<double>(it->get_id()));
                for (unsigned int d = 0; d < dim; ++d)
                  buffer.push_back(x[d]);
                for (unsigned int d = 0; d < dim; ++d)
                  buffer.push_back(target_xi[d]);
                buffer.insert(buffer.end(), props.begin(), props.end());
              }
            leaving.push_back(pic.handler_iterator(*it));
          }
      });

    // One reduction for both questions: did a particle leave the locally
    // known grid, and did any change its cell (if none did, the handler is
    // left as it is: its remove_particles() walks all particles to
    // recount them).
    const bool         parallel = Utilities::MPI::n_mpi_processes(comm) > 1;
    const unsigned int mine[2]  = {far.empty() ? 0u : 1u,
                                  leaving.empty() ? 0u : 1u};
    unsigned int status[2] = {mine[0], mine[1]};
    if (parallel)
      Utilities::MPI::max(mine, comm, status);
    // A particle beyond the ghost layer (an implicit step can move one by
    // several cells): every rank looks for the owned cell that contains
    // it, among all such particles of all ranks. Found: it travels there
    // with the others; not found (it left the grid), or serial: the
    // caller's sort deals with it.
    std::map<unsigned int, std::vector<double>> to_send_far;
    if (status[0] != 0)
      {
        if (!parallel)
          return false;
        std::vector<double> mine_x;
        for (const auto &f : far)
          for (unsigned int d = 0; d < dim; ++d)
            mine_x.push_back(f.first[d]);
        const auto all = Utilities::MPI::all_gather(comm, mine_x);
        if (std::any_of(all.begin(), all.end(), [](const auto &v) {
              return !v.empty();
            }))
          {
            const int        me = Utilities::MPI::this_mpi_process(comm);
            std::vector<int> owner;
            std::size_t      my_first = 0;
            for (unsigned int r = 0; r < all.size(); ++r)
              {
                if (int(r) == me)
                  my_first = owner.size();
                for (std::size_t k = 0; k < all[r].size(); k += dim)
                  {
                    Point<dim> x;
                    for (unsigned int d = 0; d < dim; ++d)
                      x[d] = all[r][k + d];
                    CellIterator<dim> c;
                    Point<dim>        c_xi;
                    owner.push_back(
                      owned_cell_around(grid.triangulation(), x, c, c_xi) ? me :
                                                                            -1);
                  }
              }
            std::vector<int> found(owner.size());
            Utilities::MPI::max(ArrayView<const int>(owner),
                                comm,
                                ArrayView<int>(found));
            owner = found;
            for (std::size_t k = 0; k < far.size(); ++k)
              {
                const int o = owner[my_first + k];
                if (o < 0)
                  {
                    unplaced = true;
                    continue;
                  }
                // Packed as: id, x, properties.
                auto &buffer = to_send_far[o];
                auto  it     = far[k].second;
                buffer.push_back(static_cast<double>(it->get_id()));
                for (unsigned int d = 0; d < dim; ++d)
                  buffer.push_back(far[k].first[d]);
                const auto props = it->get_properties();
                buffer.insert(buffer.end(), props.begin(), props.end());
                leaving.push_back(it);
              }
          }
        if (Utilities::MPI::max(unplaced ? 1 : 0, comm) != 0)
          return false;
      }
    else if (status[1] == 0)
      return true;

    particles.remove_particles(leaving);
    for (const auto &m : local_moves)
      particles.insert_particle(
        m.x, m.xi, m.id, m.cell, ArrayView<const double>(m.properties));
    if (parallel)
      {
        const auto received      = Utilities::MPI::some_to_some(comm, to_send);
        using Binary             = CellId::binary_type;
        const unsigned int n_cid = std::tuple_size<Binary>::value;
        const unsigned int n_entry = n_cid + 1 + 2 * dim + n_props;
        for (const auto &[rank, buffer] : received)
          for (std::size_t i = 0; i < buffer.size(); i += n_entry)
            {
              Binary cid;
              for (unsigned int c = 0; c < n_cid; ++c)
                cid[c] =
                  static_cast<typename Binary::value_type>(buffer[i + c]);
              const auto cell =
                grid.triangulation().create_cell_iterator(CellId(cid));
              const auto id =
                static_cast<types::particle_index>(buffer[i + n_cid]);
              Point<dim> x, xi;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  x[d]  = buffer[i + n_cid + 1 + d];
                  xi[d] = buffer[i + n_cid + 1 + dim + d];
                }
              particles.insert_particle(
                x,
                xi,
                id,
                typename Triangulation<dim>::active_cell_iterator(cell),
                ArrayView<const double>(&buffer[i + n_cid + 1 + 2 * dim],
                                        n_props));
            }
        // (a collective only when some rank had such a particle)
        const auto received_far =
          status[0] != 0 ? Utilities::MPI::some_to_some(comm, to_send_far) :
                           std::map<unsigned int, std::vector<double>>();
        const unsigned int n_far_entry = 1 + dim + n_props;
        for (const auto &[rank, buffer] : received_far)
          for (std::size_t i = 0; i < buffer.size(); i += n_far_entry)
            {
              Point<dim> x, xi;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = buffer[i + 1 + d];
              CellIterator<dim> cell;
              owned_cell_around(grid.triangulation(), x, cell, xi);
              particles.insert_particle(
                x,
                xi,
                static_cast<types::particle_index>(buffer[i]),
                cell,
                ArrayView<const double>(&buffer[i + 1 + dim], n_props));
            }
      }
    return true;
  }

  template bool
  relocate_particles<1>(const BackgroundGrid<1> &,
                        Particles::ParticleHandler<1> &,
                        MPI_Comm);
  template bool
  relocate_particles<2>(const BackgroundGrid<2> &,
                        Particles::ParticleHandler<2> &,
                        MPI_Comm);
  template bool
  relocate_particles<3>(const BackgroundGrid<3> &,
                        Particles::ParticleHandler<3> &,
                        MPI_Comm);
} // namespace mpm
