#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/particles/particle_handler.h>

#include <cstddef>
#include <vector>

namespace mpm
{
  /**
   * One particle as the hot loops see it: pointers straight into the
   * storage of deal.II's ParticleHandler (its property pool), so that a
   * loop reads a particle with one load instead of walking the handler's
   * cell list, handle vector and pool on every access. It offers the part
   * of deal.II's ParticleAccessor interface that the loops use. Valid while
   * the handler's particles stay where they are: ParticleIndex rebuilds
   * the references whenever particles may have been moved, inserted or
   * removed.
   */
  template <int dim>
  class ParticleRef
  {
  public:
    ParticleRef(double                             *properties,
                const unsigned int                  n_properties,
                dealii::Point<dim>                 *location,
                dealii::Point<dim>                 *reference_location,
                const dealii::types::particle_index id)
      : properties(properties)
      , location(location)
      , reference_location(reference_location)
      , id(id)
      , n_properties(n_properties)
    {}

    /// The particle's properties (writable: the reference is a handle).
    dealii::ArrayView<double>
    get_properties() const
    {
      return {properties, n_properties};
    }

    const dealii::Point<dim> &
    get_location() const
    {
      return *location;
    }

    void
    set_location(const dealii::Point<dim> &x) const
    {
      *location = x;
    }

    const dealii::Point<dim> &
    get_reference_location() const
    {
      return *reference_location;
    }

    void
    set_reference_location(const dealii::Point<dim> &xi) const
    {
      *reference_location = xi;
    }

    dealii::types::particle_index
    get_id() const
    {
      return id;
    }

  private:
    double                       *properties;
    dealii::Point<dim>           *location;
    dealii::Point<dim>           *reference_location;
    dealii::types::particle_index id;
    unsigned int                  n_properties;
  };

  /**
   * The particles of one cell, in the handler's order: a range of
   * ParticleRef (what the particle loops receive as the cell's
   * particles), and the handler's own iterator to its particle for the
   * few places that need one (removing a particle).
   */
  template <int dim>
  class CellParticles
  {
  public:
    using HandlerIterator =
      typename dealii::Particles::ParticleHandler<dim>::particle_iterator;

    CellParticles(const ParticleRef<dim> *first,
                  const ParticleRef<dim> *last,
                  const HandlerIterator  &handler_first)
      : first(first)
      , last(last)
      , handler_first(handler_first)
    {}

    const ParticleRef<dim> *
    begin() const
    {
      return first;
    }

    const ParticleRef<dim> *
    end() const
    {
      return last;
    }

    std::size_t
    size() const
    {
      return last - first;
    }

    /// deal.II's iterator to the particle @p p of this cell.
    HandlerIterator
    handler_iterator(const ParticleRef<dim> &p) const
    {
      return std::next(handler_first, &p - first);
    }

  private:
    const ParticleRef<dim> *first, *last;
    HandlerIterator         handler_first;
  };

  /**
   * The locally owned particles grouped by cell, cells in active cell
   * index order and particles in the handler's order within each cell:
   * the loop order of for_each_cell_with_particles()
   * (particles/cell_loop.h), which builds it. Rebuilt after the particles
   * may have changed cells, been inserted or removed
   * (BackgroundGrid::particles_changed_cells()); the build walks only the
   * cells that held particles before, unless particles have come into
   * others.
   */
  template <int dim>
  class ParticleIndex
  {
  public:
    using ActiveCell =
      typename dealii::Triangulation<dim>::active_cell_iterator;

    /// Index the particles of @p particles in @p candidate_cells, which
    /// must be in active cell index order. False (and the index empty) if
    /// these cells do not hold every locally owned particle.
    bool
    build(dealii::Particles::ParticleHandler<dim> &particles,
          const std::vector<ActiveCell>           &candidate_cells)
    {
      clear();
      const unsigned int n_properties = particles.n_properties_per_particle();
      for (const auto &cell : candidate_cells)
        {
          const auto pic = particles.particles_in_cell(cell);
          if (pic.begin() == pic.end())
            continue;
          cell_list.push_back(cell);
          first_of_cell.push_back(refs.size());
          handler_first.push_back(pic.begin());
          for (auto &p : pic)
            // the handler stores the locations writable; its accessor
            // hands out const references to them
            refs.emplace_back(
              p.get_properties().data(),
              n_properties,
              const_cast<dealii::Point<dim> *>(&p.get_location()),
              const_cast<dealii::Point<dim> *>(&p.get_reference_location()),
              p.get_id());
        }
      first_of_cell.push_back(refs.size());
      if (refs.size() != particles.n_locally_owned_particles())
        {
          clear();
          return false;
        }
      handler       = &particles;
      handler_count = refs.size();
      handler_start = start_of(particles);
      return true;
    }

    /// Whether the index was built from @p particles and is still valid:
    /// not invalidated since, the same particle count, and the handler's
    /// first particle where the index saw it. The last two are a cheap,
    /// partial guard (a reallocated pool, another handler at the same
    /// address); whatever moves particles between cells at the same count
    /// must call invalidate().
    bool
    up_to_date(dealii::Particles::ParticleHandler<dim> &particles) const
    {
      return handler == &particles &&
             handler_count == particles.n_locally_owned_particles() &&
             handler_start == start_of(particles);
    }

    /// The particles may have changed cells or storage: the next
    /// up_to_date() is false.
    void
    invalidate()
    {
      handler = nullptr;
    }

    void
    clear()
    {
      invalidate();
      handler_start = nullptr;
      cell_list.clear();
      first_of_cell.clear();
      handler_first.clear();
      refs.clear();
    }

    /// The cells that hold particles.
    const std::vector<ActiveCell> &
    cells() const
    {
      return cell_list;
    }

    /// The particles of the @p c-th of cells().
    CellParticles<dim>
    particles_of(const std::size_t c) const
    {
      return {refs.data() + first_of_cell[c],
              refs.data() + first_of_cell[c + 1],
              handler_first[c]};
    }

  private:
    static const double *
    start_of(dealii::Particles::ParticleHandler<dim> &particles)
    {
      return particles.n_locally_owned_particles() == 0 ?
               nullptr :
               particles.begin()->get_properties().data();
    }

    const void              *handler       = nullptr;
    std::size_t              handler_count = 0;
    const double            *handler_start = nullptr;
    std::vector<ActiveCell>  cell_list;
    std::vector<std::size_t> first_of_cell;
    std::vector<typename CellParticles<dim>::HandlerIterator> handler_first;
    std::vector<ParticleRef<dim>>                             refs;
  };
} // namespace mpm
