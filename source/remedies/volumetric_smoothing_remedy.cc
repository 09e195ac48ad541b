#include <mpm/remedies/registry.h>
#include <mpm/remedies/volumetric_smoothing_remedy.h>

namespace mpm
{
  namespace remedies
  {
    namespace
    {
      /// `Volumetric smoothing = cell` or `node`: no entries of its own,
      /// and it works with every material, family and scheme of the
      /// explicit step.
      template <VolumeAverage where>
      class VolumetricSmoothingRemedy : public Remedy,
                                        public VolumetricSmoothingSettings
      {
      public:
        VolumetricSmoothingRemedy()
        {
          average = where;
        }

        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        void
        parse_parameters(dealii::ParameterHandler &) override
        {}

        /// The cell average is linearized for the implicit step
        /// (LinearizedCellSmoothing); the node average, which couples
        /// neighbouring cells, is not.
        void
        check(const Context &context) const override
        {
          if (average == VolumeAverage::node)
            require_explicit_integrator(context, "Volumetric smoothing = node");
        }
      };

      using CellSmoothing = VolumetricSmoothingRemedy<VolumeAverage::cell>;
      using NodeSmoothing = VolumetricSmoothingRemedy<VolumeAverage::node>;

      MPM_REGISTER_REMEDY(CellSmoothing,
                          "Volumetric smoothing",
                          "cell",
                          "cell: over this body's particles in the background "
                          "cell (the seed's theta-bar: the volume-weighted "
                          "rate tr L for rate models, F-bar for models of "
                          "F).")
      MPM_REGISTER_REMEDY(NodeSmoothing,
                          "Volumetric smoothing",
                          "node",
                          "node: mass-weighted to the grid nodes and "
                          "interpolated back (averages of all node-smoothed "
                          "bodies mix at shared nodes); refused by the "
                          "implicit integrators.")
    } // namespace
  }   // namespace remedies
} // namespace mpm
