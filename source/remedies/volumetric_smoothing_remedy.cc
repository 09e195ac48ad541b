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
        declare_parameters(dealii::ParameterHandler &prm)
        {
          if (where != VolumeAverage::cell)
            return;
          prm.declare_entry(
            "Particle volume",
            "own",
            dealii::Patterns::Selection("own|smoothed"),
            "What a solid's particles keep after a step with Volumetric "
            "smoothing = cell. own: each its own compatible F and volume "
            "(only the stress sees the cell's volume change). smoothed: the "
            "smoothed F_bar = (J_bar/J)^(1/d) F and V = J_bar V0, as a "
            "fluid's particles always do, so that no particle loses volume "
            "that no pressure acts on (doc/theory/volumetric_smoothing.md). "
            "Ignored with Volumetric smoothing = node.");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm) override
        {
          if (where == VolumeAverage::cell)
            keeps_smoothed_volume = prm.get("Particle volume") == "smoothed";
        }

        /// Both averages are linearized for the implicit step
        /// (LinearizedCellSmoothing, LinearizedNodeSmoothing).
        void
        check(const Context &) const override
        {}
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
                          "bodies mix at shared nodes).")
    } // namespace
  }   // namespace remedies
} // namespace mpm
