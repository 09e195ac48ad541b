#pragma once

#include <mpm/materials/material.h>

namespace mpm
{
  namespace materials
  {
    /**
     * The material of a body that moves as prescribed (`Prescribed
     * velocity` of the body): it carries no stress and adds no stiffness;
     * the nodes it reaches follow its motion (doc/theory/implicit.md,
     * "Prescribed motion"). Only its density (the mass that marks those nodes)
     * is used.
     */
    class Rigid : public Material
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &)
      {}

      std::string
      name() const override
      {
        return "rigid";
      }

      bool
      supports(const KinematicAssumption) const override
      {
        return true;
      }

      void
      parse_parameters(dealii::ParameterHandler &) override
      {}

      /// The stress stays zero.
      void
      update_stress(const PointKinematics &,
                    SymmetricTensor<2, 3> &,
                    const ArrayView<double> &) const override
      {}

      /// Zero: the body adds no stiffness.
      bool
      stress_tangent(const PointKinematics &,
                     const SymmetricTensor<2, 3> &,
                     const ArrayView<const double> &,
                     Tensor<4, 3> &tangent) const override
      {
        tangent = 0;
        return true;
      }

      bool
      has_symmetric_tangent() const override
      {
        return true;
      }

      double
      strain_energy_density(const SymmetricTensor<2, 3> &,
                            const Tensor<2, 3> &,
                            const ArrayView<const double> &) const override
      {
        return 0;
      }

      /// No waves: the body's motion is prescribed.
      double
      wave_speed(const Tensor<2, 3> &) const override
      {
        return 0;
      }
    };
  } // namespace materials
} // namespace mpm
