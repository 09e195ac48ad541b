#include <mpm/remedies/convection_correction_remedy.h>
#include <mpm/remedies/registry.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  namespace remedies
  {
    namespace
    {
      /// `Stress filter = convection correction`: the 1D correction of the
      /// cell-crossing error, derived for standard MPM.
      class ConvectionCorrectionRemedy : public Remedy,
                                         public ConvectionCorrectionSettings
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          prm.declare_entry(
            "Body force correction",
            "true",
            dealii::Patterns::Bool(),
            "With Stress filter = convection correction: integrate the body "
            "force the same way, the least-squares line of the particles' "
            "force per length integrated exactly against the shape functions "
            "over the occupied part of each cell, consistently with the "
            "stress; the body's total load stays sum_p m_p b_p "
            "(doc/theory/convection_correction.md).");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm) override
        {
          body_force = prm.get_bool("Body force correction");
        }

        void
        check(const Context &context) const override
        {
          require_explicit_integrator(context,
                                      "Stress filter = convection correction");
          if (context.dimension != 1)
            throw InputError(context.where +
                             ": Locking remedies/Stress filter = convection "
                             "correction is the 1D correction of the "
                             "cell-crossing error and needs Dimension 1 (in "
                             "2D and 3D use assumed stress)");
          if (context.family != shape_functions::Family::standard)
            throw InputError(std::string("Shape functions/Family = ") +
                             shape_functions::family_name(context.family) +
                             " cannot be combined with Locking remedies/"
                             "Stress filter = convection correction, which "
                             "is derived for standard MPM");
        }
      };

      MPM_REGISTER_REMEDY(
        ConvectionCorrectionRemedy,
        "Stress filter",
        "convection correction",
        "convection correction: the internal force of each cell integrates "
        "the least-squares line of its particles' stresses exactly over the "
        "part of the cell the body occupies (the seed's correction of the "
        "cell-crossing error, doc/theory/convection_correction.md); the "
        "stored stresses are not changed. A cell with one particle takes "
        "the line through it and the nearest particle of the body in a "
        "neighbouring cell. 1D only, with Shape functions/Family = standard "
        "and Integrator = explicit (refused otherwise).")
    } // namespace
  }   // namespace remedies
} // namespace mpm
