#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace mpm
{
  namespace contact
  {
    /// The contact force at one grid node (MultiFieldContact::forces()).
    template <int dim>
    struct NodalContactForce
    {
      /// the node's index among this rank's owned nodes, and its position
      unsigned int       node = 0;
      dealii::Point<dim> position;
      /// the force the contact exerted on the node's deformable field of
      /// the lowest number [N; in 2D per unit thickness]
      dealii::Tensor<1, dim> force;
    };

    /// The contact forces of a step at this rank's nodes.
    template <int dim>
    using NodalContactForces = std::vector<NodalContactForce<dim>>;
  } // namespace contact
} // namespace mpm
