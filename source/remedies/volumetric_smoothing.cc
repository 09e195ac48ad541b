#include <mpm/remedies/assumed_stress_remedy.h>
#include <mpm/remedies/volumetric_smoothing.h>

namespace mpm
{
  namespace remedies
  {
    namespace
    {
      /// The body's `Volumetric smoothing` (null: none).
      template <int dim>
      const VolumetricSmoothingSettings *
      settings_of(const Body<dim> &body)
      {
        return body.prm.locking_remedies
          .template find<VolumetricSmoothingSettings>();
      }

      template <int dim>
      VolumeAverage
      average_of(const Body<dim> &body)
      {
        const auto *choice = settings_of(body);
        return choice ? choice->average : VolumeAverage::none;
      }
    } // namespace

    template <int dim>
    VolumetricSmoothing<dim>::VolumetricSmoothing(
      const std::vector<Body<dim>> &bodies)
      : averages(bodies.size())
      , keeps_volume(bodies.size())
      , over_cell(bodies.size())
      , cell_sums(bodies.size())
    {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          averages[b]          = average_of(bodies[b]);
          const auto *settings = settings_of(bodies[b]);
          keeps_volume[b] =
            bodies[b].material->state_is_volume_ratio() ||
            (settings && settings->average == VolumeAverage::cell &&
             settings->keeps_smoothed_volume);
          over_cell[b]  = pressure_over_cell(bodies[b]);
          any_cell      = any_cell || averages[b] == VolumeAverage::cell;
          any_node      = any_node || averages[b] == VolumeAverage::node;
          any_over_cell = any_over_cell || over_cell[b];
        }
    }

    template <int dim>
    bool
    VolumetricSmoothing<dim>::pressure_over_cell(const Body<dim> &body)
    {
      // a filtered body's stress is the filter's, at its particles
      const bool filtered =
        dim > 1 &&
        body.prm.locking_remedies.template find<AssumedStressSettings>();
      return average_of(body) == VolumeAverage::cell &&
             body.material->state_is_volume_ratio() && !filtered;
    }

    template <int dim>
    bool
    VolumetricSmoothing<dim>::through_nodes(
      const std::vector<Body<dim>> &bodies)
    {
      for (const auto &body : bodies)
        if (average_of(body) == VolumeAverage::node)
          return true;
      return false;
    }

    template class VolumetricSmoothing<1>;
    template class VolumetricSmoothing<2>;
    template class VolumetricSmoothing<3>;
  } // namespace remedies
} // namespace mpm
