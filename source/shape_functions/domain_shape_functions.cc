#include <mpm/particles/particle_layout.h>
#include <mpm/shape_functions/domain_shape_functions.h>
#include <mpm/shape_functions/gimp.h>

#include <cmath>
#include <sstream>

namespace mpm
{
  namespace shape_functions
  {
    using namespace dealii;

    template <int dim>
    DomainShapeFunctions<dim>::DomainShapeFunctions(
      const BackgroundGrid<dim> &grid,
      const Family               family,
      const bool                 clamp,
      const unsigned int         corner_offset,
      const bool                 cache_stencils)
      : grid(grid)
      , which(family)
      , clamp(clamp)
      , corner_offset(corner_offset)
      , cache_on(cache_stencils)
    {}

    template <int dim>
    Tensor<1, dim>
    DomainShapeFunctions<dim>::gimp_half_widths(const Tensor<2, dim> &R0)
    {
      Tensor<1, dim> b;
      double         box = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          for (unsigned int k = 0; k < dim; ++k)
            b[d] += std::abs(R0[d][k]);
          box *= b[d];
        }
      // same volume as the parallelogram: |det R0| = product of l_d
      // (sqrt, cbrt: std::pow was 7% of a uGIMP run)
      const double ratio = std::abs(determinant(R0)) / box;
      return b * (dim == 1 ? ratio :
                  dim == 2 ? std::sqrt(ratio) :
                             std::cbrt(ratio));
    }

    namespace
    {
      /**
       * Reference coordinates of x in the distorted cell @p geo, good
       * enough to steer a walk. Outside a distorted cell the bilinear map,
       * extended beyond the cell, can fold, and Newton then finds no
       * preimage (inverse_map says so with xi[0] = inf, which alone would
       * send the walk across the upper x face whatever the direction of
       * x). The affine map at the centre still points the way to x; x is
       * not in this cell, so such a point never counts as inside. Out of
       * line: kept out of the box path of locate().
       */
      template <int dim>
      [[gnu::noinline]] Point<dim>
      distorted_reference(const Q1Cell<dim> &geo,
                          const Point<dim>  &x,
                          const Point<dim>  &guess)
      {
        Point<dim> r = geo.inverse_map(x, guess);
        if (std::isfinite(r[0]))
          return r;
        Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = 0.5;
        r = centre + invert(geo.jacobian(centre)) * (x - geo.map(centre));
        if (Q1Cell<dim>::is_inside(r))
          {
            unsigned int far = 0;
            for (unsigned int d = 1; d < dim; ++d)
              if (std::abs(r[d] - 0.5) > std::abs(r[far] - 0.5))
                far = d;
            r[far] = r[far] < 0.5 ? -1e-6 : 1 + 1e-6;
          }
        return r;
      }
    } // namespace

    template <int dim>
    typename DomainShapeFunctions<dim>::Status
    DomainShapeFunctions<dim>::locate(unsigned int      cell,
                                      const Point<dim> &x,
                                      const Point<dim> &start,
                                      unsigned int     &found,
                                      Point<dim>       &xi) const
    {
      using Grid = BackgroundGrid<dim>;
      // Reference coordinates of x in cell c, good enough to steer the
      // walk. Boxes map directly (inlined: the hot path of CPDI).
      auto to_reference = [&](const unsigned int c, const Point<dim> &guess) {
        const auto &geo = grid.geometry(c);
        if (!geo.is_box)
          return distorted_reference(geo, x, guess);
        Point<dim> r;
        for (unsigned int d = 0; d < dim; ++d)
          r[d] = (x[d] - geo.vertices[0][d]) * geo.inverse_extent[d];
        return r;
      };
      xi = to_reference(cell, start);
      for (unsigned int hop = 0; hop <= 4 * dim; ++hop)
        {
          if (Q1Cell<dim>::is_inside(xi))
            {
              found = cell;
              return Status::ok;
            }
          const unsigned int face = Q1Cell<dim>::most_violated_face(xi);
          if (face == numbers::invalid_unsigned_int) // xi not a number
            return Status::lost_corner;
          const unsigned int next = grid.face_neighbor(cell, face);
          if (next == Grid::outside_grid)
            {
              if (!clamp)
                return Status::outside_grid;
              // Keep walking along the boundary if the point is also
              // beyond another face; at the last cell, clip onto it.
              bool other = false;
              for (unsigned int d = 0; d < dim; ++d)
                if (d != face / 2 && (xi[d] < -1e-12 || xi[d] > 1 + 1e-12))
                  {
                    const unsigned int f2 = xi[d] < 0 ? 2 * d : 2 * d + 1;
                    const unsigned int n2 = grid.face_neighbor(cell, f2);
                    if (n2 != Grid::outside_grid && n2 != Grid::unknown_cell)
                      {
                        cell  = n2;
                        xi    = to_reference(cell, xi);
                        other = true;
                        break;
                      }
                  }
              if (other)
                continue;
              for (unsigned int d = 0; d < dim; ++d)
                xi[d] = std::min(1., std::max(0., xi[d]));
              found = cell;
              return Status::ok;
            }
          if (next == Grid::unknown_cell)
            return Status::beyond_ghosts;
          cell = next;
          Point<dim> centre;
          for (unsigned int d = 0; d < dim; ++d)
            centre[d] = 0.5;
          xi = to_reference(cell, centre);
        }
      return Status::lost_corner;
    }

    template <int dim>
    typename DomainShapeFunctions<dim>::Status
    DomainShapeFunctions<dim>::evaluate_gimp(const unsigned int cell,
                                             const Point<dim>  &x,
                                             const double      *prop,
                                             Stencil<dim>      &s) const
    {
      using L          = ParticleLayout<dim>;
      using Grid       = BackgroundGrid<dim>;
      Tensor<1, dim> l = gimp_half_widths(load_matrix<dim>(prop + L::domain));
      if (which == Family::cpgimp)
        {
          // follow the stretch of the fibre that was along axis d
          const Tensor<2, dim> F = load_matrix<dim>(prop + L::F);
          for (unsigned int d = 0; d < dim; ++d)
            {
              double n2 = 0;
              for (unsigned int i = 0; i < dim; ++i)
                n2 += F[i][d] * F[i][d];
              l[d] *= std::sqrt(n2);
            }
        }

      const auto &own = grid.geometry(cell);
      Point<dim>  lower, upper;
      // reach[d]: the neighbour layers needed below (bit 0) / above (bit 1)
      unsigned int reach[dim];
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d]         = x[d] - l[d];
          upper[d]         = x[d] + l[d];
          const double a   = own.vertices[0][d];
          const double b   = a + own.extent[d];
          const double tol = 1e-10 * own.extent[d];
          reach[d]         = 0;
          for (unsigned int side = 0; side < 2; ++side)
            {
              double      &end    = side ? upper[d] : lower[d];
              const double bound  = side ? b : a;
              const bool   beyond = side ? end > b + tol : end < a - tol;
              if (!beyond)
                {
                  // a box ending on the face (up to round-off) ends there
                  if (side ? end > b : end < a)
                    end = bound;
                  continue;
                }
              const unsigned int n = grid.face_neighbor(cell, 2 * d + side);
              if (n == Grid::outside_grid)
                {
                  if (!clamp)
                    return Status::outside_grid;
                  end = bound;
                  continue;
                }
              if (n == Grid::unknown_cell)
                return Status::beyond_ghosts;
              const auto  &next = grid.geometry(n);
              const double na   = next.vertices[0][d];
              if (side ? end > na + next.extent[d] + tol : end < na - tol)
                return Status::too_wide;
              reach[d] |= 1u << side;
            }
        }
      double volume = 1;
      for (unsigned int d = 0; d < dim; ++d)
        volume *= upper[d] - lower[d];
      const double inverse_volume = 1. / volume;

      // Every cell of the block: offsets -1, 0, +1 where needed.
      s.n = 0;
      for (unsigned int k = 0; k < Utilities::fixed_power<dim>(3u); ++k)
        {
          unsigned int c    = cell;
          bool         skip = false;
          for (unsigned int d = 0, r = k; d < dim; ++d, r /= 3)
            {
              const unsigned int o = r % 3; // 0: own, 1: below, 2: above
              if (o == 0)
                continue;
              if (!(reach[d] & (1u << (o - 1))))
                {
                  skip = true;
                  break;
                }
              c = grid.face_neighbor(c, 2 * d + (o - 1));
              if (c == Grid::outside_grid || c == Grid::unknown_cell)
                return c == Grid::outside_grid ? Status::outside_grid :
                                                 Status::beyond_ghosts;
            }
          if (!skip)
            add_gimp_cell<dim>(
              grid.geometry(c), grid.nodes(c), lower, upper, inverse_volume, s);
        }
      return Status::ok;
    }

    template <int dim>
    typename DomainShapeFunctions<dim>::Status
    DomainShapeFunctions<dim>::evaluate(const unsigned int  cell,
                                        const Point<dim>   &xi,
                                        const double       *prop,
                                        Stencil<dim>       &s,
                                        CornerWeights<dim> *corners) const
    {
      using L            = ParticleLayout<dim>;
      const Point<dim> x = grid.geometry(cell).map(xi);
      if (is_gimp(which))
        return evaluate_gimp(cell, x, prop, s);

      CornerWeights<dim>  local;
      CornerWeights<dim> &cw = corners ? *corners : local;
      if (which == Family::cpdi)
        cpdi1_corners<dim>(x,
                           load_matrix<dim>(prop + L::F) *
                             load_matrix<dim>(prop + L::domain),
                           cw);
      else
        {
          for (unsigned int c = 0; c < CornerWeights<dim>::n_corners; ++c)
            for (unsigned int d = 0; d < dim; ++d)
              cw.x[c][d] = prop[corner_offset + c * dim + d];
          cpdi2_weights<dim>(cw);
        }
      if (!(cw.quality > min_domain_quality))
        return Status::collapsed;

      constexpr unsigned int nv        = n_q1<dim>;
      constexpr unsigned int n_corners = CornerWeights<dim>::n_corners;
      s.n                              = 0;
      // A corner in a cell that an earlier corner was in adds to that
      // cell's entries, the ones add() would find, without searching.
      unsigned int seen_cell[n_corners];
      unsigned int seen_entry[n_corners][nv];
      unsigned int n_seen = 0;
      for (unsigned int c = 0; c < n_corners; ++c)
        {
          unsigned int corner_cell;
          Point<dim>   corner_xi;
          const Status status =
            locate(cell, cw.x[c], xi, corner_cell, corner_xi);
          if (status != Status::ok)
            return status;
          double N[nv];
          Q1Cell<dim>::values(corner_xi, N);
          unsigned int j = 0;
          while (j < n_seen && seen_cell[j] != corner_cell)
            ++j;
          if (j < n_seen)
            for (unsigned int v = 0; v < nv; ++v)
              s.add_to_entry(seen_entry[j][v], cw.w[c] * N[v], N[v] * cw.g[c]);
          else
            {
              const unsigned int *nodes = grid.nodes(corner_cell);
              seen_cell[n_seen]         = corner_cell;
              for (unsigned int v = 0; v < nv; ++v)
                seen_entry[n_seen][v] =
                  s.add(nodes[v], cw.w[c] * N[v], N[v] * cw.g[c]);
              ++n_seen;
            }
        }
      return Status::ok;
    }

    template <int dim>
    typename DomainShapeFunctions<dim>::Status
    DomainShapeFunctions<dim>::move_corners(const unsigned int cell,
                                            const Point<dim>  &xi,
                                            double            *prop,
                                            const double      *velocity,
                                            const unsigned int stride,
                                            const double       dt) const
    {
      constexpr unsigned int nv = n_q1<dim>;
      Point<dim>             moved[1u << dim];
      for (unsigned int c = 0; c < (1u << dim); ++c)
        {
          for (unsigned int d = 0; d < dim; ++d)
            moved[c][d] = prop[corner_offset + c * dim + d];
          unsigned int corner_cell;
          Point<dim>   corner_xi;
          const Status status =
            locate(cell, moved[c], xi, corner_cell, corner_xi);
          if (status != Status::ok)
            return status;
          double N[nv];
          Q1Cell<dim>::values(corner_xi, N);
          const unsigned int *nodes = grid.nodes(corner_cell);
          for (unsigned int v = 0; v < nv; ++v)
            for (unsigned int d = 0; d < dim; ++d)
              moved[c][d] += dt * N[v] * velocity[nodes[v] * stride + d];
        }
      for (unsigned int c = 0; c < (1u << dim); ++c)
        for (unsigned int d = 0; d < dim; ++d)
          prop[corner_offset + c * dim + d] = moved[c][d];
      return Status::ok;
    }

    template <int dim>
    std::string
    DomainShapeFunctions<dim>::message(const Status             status,
                                       const unsigned long long id,
                                       const Point<dim>        &x) const
    {
      std::ostringstream s;
      s << "the " << family_name(which) << " domain of particle " << id
        << " at (" << x << ") ";
      switch (status)
        {
          case Status::ok:
            s << "is fine";
            break;
          case Status::outside_grid:
            s << "reaches outside the grid (enlarge the grid, or set Shape "
                 "functions/Domain outside the grid = clamp to cut domains "
                 "at the grid boundary)";
            break;
          case Status::beyond_ghosts:
            s << "reaches beyond the ghost cells of this MPI rank (the "
                 "domain is larger than a cell: refine less, or use more "
                 "particles per cell)";
            break;
          case Status::too_wide:
            s << "is wider than the neighbouring cell (GIMP domains may "
                 "overlap at most one neighbour per direction)";
            break;
          case Status::collapsed:
            s << "is inverted or collapsed (a corner angle with sine below "
              << min_domain_quality << ")";
            break;
          case Status::lost_corner:
            s << "has a corner that was not found within " << 4 * dim
              << " cells of the particle";
            break;
        }
      return s.str();
    }

    template class DomainShapeFunctions<1>;
    template class DomainShapeFunctions<2>;
    template class DomainShapeFunctions<3>;
  } // namespace shape_functions
} // namespace mpm
