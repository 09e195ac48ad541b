#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>
#include <mpm/particles/body.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/remedies/assumed_stress.h>

#include <memory>
#include <vector>

namespace mpm
{
  namespace remedies
  {
    /**
     * The assumed-stress filter of the bodies with `Stress filter =
     * assumed stress`, one cell at a time: the in-plane stresses of one
     * body's particles in the cell (the particles the cell holds) are
     * replaced by their projection onto the assumed-stress field of the
     * cell (AssumedStressProjection), whose coefficients are returned for
     * the force. The out-of-plane stress of 2D models is left as the
     * material computed it.
     *
     * The internal-force computation (transfer::particle_to_grid) calls
     * it for every cell, so the field that makes the force is the
     * projection over the particles the cell holds at that moment; output
     * calls apply() so that what is written is that same state (the
     * projection is idempotent, so this changes nothing for the dynamics).
     *
     * A body with `Filtered stress = force only` is projected the same way
     * but nothing is written back: the field makes the force only, and
     * cartesian_field() gives the projected stress at a particle (for the
     * domain families, whose force is per particle).
     *
     * There is one projection path: the cell's moments are summed particle
     * by particle (add_particle(), fused into the P2G loop) and solved once
     * (finish_cell()); filter_cell() runs the same three steps for one body
     * of one cell.
     */
    template <int dim>
    class StressFilter
    {
    public:
      using Result = typename AssumedStressProjection<dim>::Result;
      static constexpr unsigned int n_beta =
        AssumedStressProjection<dim>::n_beta;

      explicit StressFilter(const std::vector<Body<dim>> &bodies);

      /// Whether body @p b is filtered.
      bool
      filtered(const unsigned int b) const
      {
        return b < metric.size() && is_filtered[b];
      }

      bool
      any() const
      {
        return any_filtered;
      }

      /// Whether body @p b's projected stresses replace its particles'.
      bool
      writes_back(const unsigned int b) const
      {
        return write_back[b];
      }

      /**
       * Filter body @p b's particles among @p particles_in_cell (a cell
       * whose Jacobian at its centre is @p J0): begin, add and finish for
       * that body alone. The field's coefficients go to @p beta, its
       * monomial form to cartesian_field(b).
       */
      template <typename ParticleRange>
      Result
      filter_cell(const dealii::Tensor<2, dim> &J0,
                  const ParticleRange          &particles_in_cell,
                  const unsigned int            b,
                  double                       *beta);

      /**
       * The same projection fused into a particle loop: begin_cell() for
       * a cell whose Jacobian at its centre is @p J0, add_particle() for
       * each particle of a filtered body (properties @p prop), then
       * finish_cell() per filtered body with particles in the cell: it
       * solves, writes the projected stresses back (unless force only) and
       * says whether the field is the full one, the constant fallback or
       * left unchanged (nothing to project onto).
       */
      void
      begin_cell(const dealii::Tensor<2, dim> &J0);
      void
      add_particle(const unsigned int        b,
                   const dealii::Point<dim> &xi,
                   const double             *prop)
      {
        if constexpr (dim > 1)
          {
            using L         = ParticleLayout<dim>;
            const auto full = load_stress(prop + L::stress);
            dealii::SymmetricTensor<2, dim> s;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                s[i][j] = full[i][j];
            projections[b]->add(sums[b], xi, weight(b, prop), s);
          }
      }
      /// The weight of the particle of body @p b with properties @p prop
      /// in the projection: m_p (mass metric) or V_p (compliance).
      double
      weight(const unsigned int b, const double *prop) const
      {
        using L = ParticleLayout<dim>;
        return metric[b] == Metric::mass ? prop[L::mass] : prop[L::volume];
      }

      template <typename ParticleRange>
      Result
      finish_cell(const ParticleRange &particles_in_cell,
                  const unsigned int   b,
                  double              *beta);

      /// The monomial coefficients of body b's field of the last
      /// finish_cell() (valid unless it returned unchanged).
      const typename AssumedStressProjection<dim>::CartesianField &
      cartesian_field(const unsigned int b) const
      {
        return fields[b];
      }

      /// The projection (and field) of body b's last cell.
      const AssumedStressProjection<dim> &
      projection(const unsigned int b) const
      {
        return *projections[b];
      }

      /// Filter every owned cell (for output).
      void
      apply(const BackgroundGrid<dim>               &grid,
            dealii::Particles::ParticleHandler<dim> &particles);

      /// Cells that fell back to constant stress, on this rank, so far.
      unsigned int n_fallbacks = 0;

    private:
      /// Make projections[b] the projection of a cell with Jacobian J0.
      void
      use_geometry(const dealii::Tensor<2, dim> &J0, const unsigned int b);

      /// begin_cell() for body b alone: its geometry, its sums cleared.
      void
      begin_body(const dealii::Tensor<2, dim> &J0, const unsigned int b);

      /// Replace the in-plane stress of the particle @p prop of body @p b
      /// by @p s (the material makes it admissible).
      void
      write_stress(const unsigned int                     b,
                   double                                *prop,
                   const dealii::SymmetricTensor<2, dim> &s) const;

      std::vector<char>                                          is_filtered;
      bool                                                       any_filtered;
      std::vector<Metric>                                        metric;
      std::vector<dealii::SymmetricTensor<4, dim>>               compliance;
      std::vector<std::unique_ptr<AssumedStressProjection<dim>>> projections;
      std::vector<char> enriched;   ///< Filter field = enriched, per body
      std::vector<char> write_back; ///< not Filtered stress = force only
      /// the Jacobian of the last cell, and as rounded for its projection
      std::vector<dealii::Tensor<2, dim>> last_J0, last_rounded_J0;
      /// The fused projection's sums of the current cell, per body.
      std::vector<typename AssumedStressProjection<dim>::Moments> sums;
      std::vector<typename AssumedStressProjection<dim>::CartesianField>
        fields; ///< of the last finish_cell(), per body
      std::vector<const materials::Material *> material;
      std::vector<unsigned int>                n_history; ///< per body
      /// Poisson's ratio for the out-of-plane stress of plane strain, or
      /// 0 (plane stress, 3D, or no elastic moduli).
      std::vector<double> out_of_plane_nu;
    };

    template <int dim>
    template <typename ParticleRange>
    typename StressFilter<dim>::Result
    StressFilter<dim>::filter_cell(const dealii::Tensor<2, dim> &J0,
                                   const ParticleRange &particles_in_cell,
                                   const unsigned int   b,
                                   double              *beta)
    {
      using L = ParticleLayout<dim>;
      begin_body(J0, b);
      bool any = false;
      for (auto &p : particles_in_cell)
        {
          const double *prop = p.get_properties().data();
          if (static_cast<unsigned int>(prop[L::body]) != b)
            continue;
          add_particle(b, p.get_reference_location(), prop);
          any = true;
        }
      if (!any)
        return Result::unchanged;
      return finish_cell(particles_in_cell, b, beta);
    }

    template <int dim>
    template <typename ParticleRange>
    typename StressFilter<dim>::Result
    StressFilter<dim>::finish_cell(const ParticleRange &particles_in_cell,
                                   const unsigned int   b,
                                   double              *beta)
    {
      if constexpr (dim == 1)
        {
          (void)particles_in_cell, (void)b, (void)beta;
          return Result::unchanged;
        }
      else
        {
          using L             = ParticleLayout<dim>;
          const Result result = projections[b]->solve(sums[b], beta);
          if (result != Result::full)
            ++n_fallbacks;
          if (result == Result::unchanged)
            return result;
          const auto &sigma = fields[b] = projections[b]->cartesian_field(beta);
          if (!write_back[b])
            return result;
          for (auto &p : particles_in_cell)
            {
              double *prop = p.get_properties().data();
              if (static_cast<unsigned int>(prop[L::body]) == b)
                write_stress(b, prop, sigma.value(p.get_reference_location()));
            }
          return result;
        }
    }
  } // namespace remedies
} // namespace mpm
