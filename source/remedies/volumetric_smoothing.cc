#include <mpm/remedies/volumetric_smoothing.h>

namespace mpm
{
  namespace remedies
  {
    namespace
    {
      template <int dim>
      VolumeAverage
      average_of(const Body<dim> &body)
      {
        const auto *choice = body.prm.locking_remedies
                               .template find<VolumetricSmoothingSettings>();
        return choice ? choice->average : VolumeAverage::none;
      }
    } // namespace

    template <int dim>
    VolumetricSmoothing<dim>::VolumetricSmoothing(
      const std::vector<Body<dim>> &bodies)
      : averages(bodies.size())
      , keeps_volume(bodies.size())
      , cell_sums(bodies.size())
    {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          averages[b]     = average_of(bodies[b]);
          keeps_volume[b] = bodies[b].material->state_is_volume_ratio();
          any_cell        = any_cell || averages[b] == VolumeAverage::cell;
          any_node        = any_node || averages[b] == VolumeAverage::node;
        }
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
