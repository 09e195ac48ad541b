#include <mpm/particles/cell_loop.h>
#include <mpm/remedies/assumed_stress_remedy.h>
#include <mpm/remedies/stress_filter.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace mpm
{
  namespace remedies
  {
    using namespace dealii;

    namespace
    {
      /// J0 rounded to about 40 significant bits of its largest entry: the
      /// cells of a uniform grid, whose Jacobians differ in round-off,
      /// share one projection, and the round-off off-diagonal entries of a
      /// box's Jacobian become the zeros that decouple its stress
      /// components (AssumedStressProjection). A function of the cell
      /// alone, so runs stay reproducible on any number of ranks.
      template <int dim>
      Tensor<2, dim>
      rounded_jacobian(const Tensor<2, dim> &J0)
      {
        double largest = 0;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            largest = std::max(largest, std::abs(J0[i][j]));
        if (!(largest > 1e-300 && largest < 1e300))
          return J0;
        // c = 2^(e + 12) for largest in [2^e, 2^(e+1)): x + c keeps the
        // bits of x down to 2^(e - 40) (this runs once per cell and pass,
        // so without calls to libm)
        std::uint64_t bits;
        std::memcpy(&bits, &largest, sizeof bits);
        bits = (bits & 0x7ff0000000000000ULL) + (std::uint64_t(12) << 52);
        double c;
        std::memcpy(&c, &bits, sizeof c);
        Tensor<2, dim> rounded;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            rounded[i][j] = (J0[i][j] + c) - c;
        return rounded;
      }
    } // namespace

    template <int dim>
    StressFilter<dim>::StressFilter(const std::vector<Body<dim>> &bodies)
      : is_filtered(bodies.size(), 0)
      , any_filtered(false)
      , metric(bodies.size(), Metric::mass)
      , compliance(bodies.size())
      , projections(bodies.size())
      , enriched(bodies.size(), 0)
      , write_back(bodies.size(), 1)
      , last_J0(bodies.size())
      , last_rounded_J0(bodies.size())
      , sums(bodies.size())
      , fields(bodies.size())
      , material(bodies.size())
      , n_history(bodies.size(), 0)
      , out_of_plane_nu(bodies.size(), 0.)
    {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const auto *choice =
            bodies[b]
              .prm.locking_remedies.template find<AssumedStressSettings>();
          material[b]  = bodies[b].material.get();
          n_history[b] = material[b]->n_history();
          if (choice)
            {
              is_filtered[b] = 1;
              any_filtered   = true;
              enriched[b]    = choice->enriched;
              write_back[b]  = choice->write_back;
              metric[b]      = choice->metric;
            }
          double E = 0, nu = 0;
          if (dim == 2 && bodies[b].material->elastic_moduli(E, nu) &&
              bodies[b].material->kinematic_assumption() ==
                KinematicAssumption::plane_strain)
            out_of_plane_nu[b] = nu;
          if constexpr (dim > 1)
            if (bodies[b].material->elastic_moduli(E, nu))
              compliance[b] = isotropic_compliance<dim>(
                E,
                nu,
                bodies[b].material->kinematic_assumption() ==
                  KinematicAssumption::plane_stress);
        }
    }

    template <int dim>
    void
    StressFilter<dim>::use_geometry(const Tensor<2, dim> &J0,
                                    const unsigned int    b)
    {
      if constexpr (dim > 1)
        {
          // Cells of a uniform grid share J0: build the projection only
          // when the geometry changes (the rounding only when J0 does).
          if (projections[b] && J0 == last_J0[b])
            return;
          last_J0[b]             = J0;
          const Tensor<2, dim> J = rounded_jacobian(J0);
          if (!projections[b] || !(J == last_rounded_J0[b]))
            {
              projections[b] = std::make_unique<AssumedStressProjection<dim>>(
                J, metric[b], compliance[b], enriched[b]);
              last_rounded_J0[b] = J;
            }
        }
    }

    template <int dim>
    void
    StressFilter<dim>::begin_cell(const Tensor<2, dim> &J0)
    {
      for (unsigned int b = 0; b < is_filtered.size(); ++b)
        if (is_filtered[b])
          begin_body(J0, b);
    }

    template <int dim>
    void
    StressFilter<dim>::begin_body(const Tensor<2, dim> &J0,
                                  const unsigned int    b)
    {
      use_geometry(J0, b);
      sums[b].clear();
    }

    template <int dim>
    void
    StressFilter<dim>::write_stress(const unsigned int             b,
                                    double                        *prop,
                                    const SymmetricTensor<2, dim> &s) const
    {
      using L          = ParticleLayout<dim>;
      double *const st = prop + L::stress; // Voigt xx yy zz yz xz xy
      if (n_history[b] == 0 && dim == 2)
        {
          // plane strain: keep the elastic out-of-plane strain
          st[2] += out_of_plane_nu[b] *
                   (s[0][0] - st[0] + s[dim - 1][dim - 1] - st[1]);
          st[0] = s[0][0];
          st[1] = s[dim - 1][dim - 1];
          st[5] = s[0][dim - 1];
          return;
        }
      auto full = load_stress(st);
      full[2][2] +=
        out_of_plane_nu[b] *
        (s[0][0] - full[0][0] + s[dim - 1][dim - 1] - full[dim - 1][dim - 1]);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          full[i][j] = s[i][j];
      // The material makes the stress consistent with its internal
      // variables (plastic models return it to the yield surface).
      if (n_history[b] > 0)
        material[b]->make_admissible(full,
                                     ArrayView<double>(prop + L::history,
                                                       n_history[b]));
      store_stress(full, prop + L::stress);
    }

    template <int dim>
    void
    StressFilter<dim>::apply(const BackgroundGrid<dim>       &grid,
                             Particles::ParticleHandler<dim> &particles)
    {
      if (!any_filtered)
        return;
      double     beta[n_beta];
      Point<dim> centre;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = 0.5;
      for_each_cell_with_particles(
        grid, particles, [&](const auto &cell, const auto &pic) {
          const Tensor<2, dim> J0 = grid.geometry(cell).jacobian(centre);
          for (unsigned int b = 0; b < is_filtered.size(); ++b)
            if (is_filtered[b] && write_back[b])
              filter_cell(J0, pic, b, beta);
        });
    }

    template class StressFilter<1>;
    template class StressFilter<2>;
    template class StressFilter<3>;
  } // namespace remedies
} // namespace mpm
