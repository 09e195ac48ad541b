#include <mpm/remedies/cell_pressure_force.h>
#include <mpm/remedies/volumetric_smoothing.h>

namespace mpm
{
  namespace remedies
  {
    template <int dim>
    CellPressureForce<dim>::CellPressureForce(
      const std::vector<Body<dim>> &bodies)
      : over_cell(bodies.size())
    {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          over_cell[b] =
            VolumetricSmoothing<dim>::pressure_over_cell(bodies[b]);
          any_body = any_body || over_cell[b];
        }
    }

    template class CellPressureForce<1>;
    template class CellPressureForce<2>;
    template class CellPressureForce<3>;
  } // namespace remedies
} // namespace mpm
