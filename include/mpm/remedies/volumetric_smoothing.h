#pragma once

#include <deal.II/base/tensor.h>

#include <mpm/particles/body.h>
#include <mpm/particles/particle_index.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/remedies/volumetric_smoothing_remedy.h>
#include <mpm/shape_functions/q1_cell.h>

#include <cmath>
#include <vector>

namespace mpm
{
  namespace remedies
  {
    /**
     * Replace the volumetric part of one particle's kinematics by the
     * smoothed one, for both kinds of material:
     * - rate (the seed's theta-bar in rate form): L <- L + (theta_bar -
     *   tr L)/d I, theta_bar the average of tr L, so the volume-change
     *   rate that sets the pressure is the smoothed one; for models that
     *   integrate a stress rate (linear elastic, von Mises). With a linear
     *   elastic law the pressure grows by K theta_bar dt per step: p = K
     *   theta_bar of the seed, summed over the steps.
     * - total (F-bar): F <- (J_bar/J)^(1/d) F, so det F = J_bar, for
     *   models that compute stress from F (neo-Hookean, the fluid's
     *   equation of state).
     * d is the model dimension (in-plane for 2D, as in de Souza Neto's
     * plane-strain F-bar). L and F are what the material sees; the
     * particle keeps its own compatible F and volume unless it keeps the
     * smoothed ones (fluids, `Particle volume = smoothed`).
     */
    template <int dim>
    inline void
    smooth_volume_change(dealii::Tensor<2, dim> &L,
                         dealii::Tensor<2, dim> &F,
                         const double            J,
                         const double            J_bar,
                         const double            theta_bar)
    {
      // the d-th root without pow (which costs about 120 instructions)
      const double ratio = J_bar / J;
      if constexpr (dim == 1)
        F *= ratio;
      else if constexpr (dim == 2)
        F *= std::sqrt(ratio);
      else
        F *= std::cbrt(ratio);
      const double l = (theta_bar - dealii::trace(L)) / dim;
      for (unsigned int d = 0; d < dim; ++d)
        L[d][d] += l;
    }

    /**
     * The volumetric-locking remedy in the stress update, for the bodies
     * with `Volumetric smoothing` (the seed's theta-bar): the volume change
     * that sets the pressure is an average over a neighbourhood instead of
     * the particle's own, the deviatoric part stays the particle's.
     *
     * The stress update calls it in two places: with a node average,
     * add_to_nodes() for each node-smoothed particle in a pass before the
     * update; then update_cell() for each cell (if any()), which computes
     * every particle's kinematics, smooths them and updates the particle,
     * through the stress update's own callables, so the per-particle work
     * is inlined as without smoothing.
     */
    template <int dim>
    class VolumetricSmoothing
    {
    public:
      /// Nodal sums of the node-smoothed particles: m, m J, m tr L.
      static constexpr unsigned int n_node_sums = 3;

      explicit VolumetricSmoothing(const std::vector<Body<dim>> &bodies);

      /// Whether a body of @p bodies averages through the nodes (the
      /// stress update then needs n_node_sums components per node).
      static bool
      through_nodes(const std::vector<Body<dim>> &bodies);

      /// Whether some body smooths.
      bool
      any() const
      {
        return any_cell || any_node;
      }

      /// Whether some body averages through the nodes.
      bool
      any_node_average() const
      {
        return any_node;
      }

      /**
       * Whether @p body's cell pressure acts over the cell in the explicit
       * step (CellPressureForce): a cell average of a model whose state is
       * J alone (the fluid), without the assumed-stress filter.
       */
      static bool
      pressure_over_cell(const Body<dim> &body);

      /// Whether some body's cell pressure acts over the cell.
      bool
      any_pressure_over_cell() const
      {
        return any_over_cell;
      }

      /// The average of the body with index @p b.
      VolumeAverage
      average(const unsigned int b) const
      {
        return averages[b];
      }

      /**
       * The node average's first pass: the share of one particle (mass
       * @p m, new kinematics @p grad_v, @p F; Q1 values @p N at it) in the
       * nodal sums @p sums of the nodes @p nodes of its cell.
       */
      void
      add_to_nodes(double                       *sums,
                   const unsigned int           *nodes,
                   const double                 *N,
                   const double                  m,
                   const dealii::Tensor<2, dim> &grad_v,
                   const dealii::Tensor<2, dim> &F) const
      {
        const double J = determinant(F);
        for (unsigned int v = 0; v < shape_functions::n_q1<dim>; ++v)
          {
            double *node = sums + nodes[v] * n_node_sums;
            node[0] += N[v] * m;
            node[1] += N[v] * m * J;
            node[2] += N[v] * m * trace(grad_v);
          }
      }

      /// The cell's exact mean velocity gradient <grad v>
      /// (cell_mean_velocity_gradient) and the volume growth det(I + dt
      /// <grad v>) of the step, for the bodies whose pressure acts over
      /// the cell.
      struct CellRate
      {
        dealii::Tensor<2, dim> mean_grad_v;
        double                 volume_growth = 1;
      };

      /**
       * Update the particles @p pic of one cell (nodes @p nodes; the node
       * average's sums @p node_sums, null without one; @p cell_rate, null
       * unless the pressure of some body acts over the cell: their volume
       * change is then the cell's, J_bar = sum V_old det(I + dt <grad v>) /
       * sum V0 and theta_bar = tr <grad v>, whose power is that of
       * CellPressureForce's force):
       * `kinematics(p, ordinal, prop, grad_v, F)` gives a particle's
       * velocity gradient and new F (false for a bad particle; it fills
       * @p N, the Q1 values at the particle, for the node average);
       * `update(p, prop, grad_v, F)` runs the material with what this
       * makes of them. F and V of the particle itself are its own,
       * except where it keeps the smoothed volume (keep_smoothed_volume()).
       */
      template <typename ParticleRange, typename Kinematics, typename Update>
      void
      update_cell(ParticleRange      &pic,
                  const unsigned int *nodes,
                  const double       *N,
                  const double       *node_sums,
                  const CellRate     *cell_rate,
                  Kinematics        &&kinematics,
                  Update            &&update);

    private:
      /// Models whose state is J alone (the fluid, Material::
      /// state_is_volume_ratio), and the bodies of `Particle volume =
      /// smoothed`, keep the smoothed F and volume.
      void
      keep_smoothed_volume(double *prop, const dealii::Tensor<2, dim> &F) const
      {
        using L = ParticleLayout<dim>;
        if (keeps_volume[static_cast<unsigned int>(prop[L::body])])
          {
            store_matrix<dim>(F, prop + L::F);
            prop[L::volume] = determinant(F) * prop[L::volume0];
          }
      }

      std::vector<VolumeAverage> averages; ///< per body
      std::vector<char>          keeps_volume, over_cell;
      bool any_cell = false, any_node = false, any_over_cell = false;

      /// Per-body sums of one cell for the cell average.
      struct CellSums
      {
        double V0 = 0, V = 0, V_old = 0, V_old_trL = 0;
      };
      std::vector<CellSums> cell_sums;
      /// The cell's cell-smoothed particles and their kinematics, kept
      /// while the cell's averages are summed, so that the second pass
      /// walks this list, not the cell's particles again.
      struct Buffered
      {
        const ParticleRef<dim> *particle;
        double                 *prop;
        dealii::Tensor<2, dim>  grad_v, F;
        double                  J;
      };
      std::vector<Buffered> buffer;
    };

    template <int dim>
    template <typename ParticleRange, typename Kinematics, typename Update>
    void
    VolumetricSmoothing<dim>::update_cell(ParticleRange      &pic,
                                          const unsigned int *nodes,
                                          const double       *N,
                                          const double       *node_sums,
                                          const CellRate     *cell_rate,
                                          Kinematics        &&kinematics,
                                          Update            &&update)
    {
      using L                        = ParticleLayout<dim>;
      constexpr unsigned int nv      = shape_functions::n_q1<dim>;
      auto                   body_of = [](const double *prop) {
        return static_cast<unsigned int>(prop[L::body]);
      };
      buffer.clear();
      if (any_cell)
        std::fill(cell_sums.begin(), cell_sums.end(), CellSums());
      unsigned int ordinal = 0;
      for (auto p = pic.begin(); p != pic.end(); ++p)
        {
          double                *prop = p->get_properties().data();
          dealii::Tensor<2, dim> grad_v, F;
          // a particle not updated in this pass: another contact field's,
          // a rigid body's or a bad domain's
          if (!kinematics(*p, ordinal++, prop, grad_v, F))
            continue;
          store_matrix<dim>(F, prop + L::F);
          const double J          = determinant(F);
          const double V_old      = prop[L::volume];
          prop[L::volume]         = J * prop[L::volume0];
          const VolumeAverage how = averages[body_of(prop)];
          if (how == VolumeAverage::none)
            update(*p, prop, grad_v, F);
          else if (how == VolumeAverage::node)
            {
              // J and tr L interpolated from the nodal mass averages
              double m = 0, mJ = 0, mtr = 0;
              for (unsigned int v = 0; v < nv; ++v)
                {
                  const double *node = node_sums + nodes[v] * n_node_sums;
                  if (node[0] > 0)
                    {
                      m += N[v];
                      mJ += N[v] * node[1] / node[0];
                      mtr += N[v] * node[2] / node[0];
                    }
                }
              if (m > 0 && J > 0)
                {
                  smooth_volume_change<dim>(grad_v, F, J, mJ / m, mtr / m);
                  keep_smoothed_volume(prop, F);
                }
              update(*p, prop, grad_v, F);
            }
          else
            {
              auto &sum = cell_sums[body_of(prop)];
              sum.V0 += prop[L::volume0];
              sum.V += prop[L::volume];
              sum.V_old += V_old;
              sum.V_old_trL += V_old * trace(grad_v);
              buffer.push_back({p, prop, grad_v, F, J});
            }
        }
      // Cell average: J_bar = sum V / sum V0, theta_bar = sum V tr L /
      // sum V (volumes before the step), per body.
      for (auto &[p, prop, grad_v, F, J] : buffer)
        {
          const unsigned int b   = body_of(prop);
          const auto        &sum = cell_sums[b];
          if (J > 0)
            {
              if (cell_rate && over_cell[b])
                smooth_volume_change<dim>(grad_v,
                                          F,
                                          J,
                                          sum.V_old * cell_rate->volume_growth /
                                            sum.V0,
                                          trace(cell_rate->mean_grad_v));
              else
                smooth_volume_change<dim>(
                  grad_v, F, J, sum.V / sum.V0, sum.V_old_trL / sum.V_old);
              keep_smoothed_volume(prop, F);
            }
          update(*p, prop, grad_v, F);
        }
    }
  } // namespace remedies
} // namespace mpm
