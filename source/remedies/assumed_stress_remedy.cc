#include <mpm/parameters/parameters.h>
#include <mpm/remedies/assumed_stress_remedy.h>
#include <mpm/remedies/registry.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  namespace remedies
  {
    namespace
    {
      using dealii::ParameterHandler;
      using dealii::Patterns::Selection;

      /// `Stress filter = assumed stress`, with its variants.
      class AssumedStressRemedy : public Remedy, public AssumedStressSettings
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          prm.declare_entry(
            "Filter metric",
            "mass",
            Selection("mass|compliance"),
            "The inner product of the assumed-stress projection. mass: the "
            "seed's projection (Frobenius inner product, weights m_p). "
            "compliance: the Hellinger-Reissner projection (inner product C^-1 "
            "of the kinematic assumption, weights V_p); it is exact in bending "
            "for every nu (doc/theory/assumed_stress_filter.md), and it also "
            "removes volumetric locking in plane strain, because its metric "
            "barely weighs the mean stress of a nearly incompressible material "
            "(mass does not). compliance needs a material with elastic moduli "
            "(linear elastic, neo-Hookean, von Mises plasticity) and is "
            "refused otherwise.");
          prm.declare_entry(
            "Filter field",
            "Pian-Sumihara",
            Selection("Pian-Sumihara|enriched"),
            "The assumed-stress field of Stress filter = assumed stress. "
            "Pian-Sumihara: the seed's 5-beta (2D) / 18-beta (3D) field. "
            "enriched: adds the linear variation of each normal stress along "
            "its own direction (7 / 21 betas), which does no work on a filled "
            "cell's Q1 velocities but keeps a stress that varies along the "
            "motion of a convecting body "
            "(doc/theory/assumed_stress_filter.md).");
          prm.declare_entry(
            "Filtered stress",
            "written back",
            Selection("written back|force only"),
            "What the assumed-stress projection replaces. written back: the "
            "particles' stresses (the seed; the strains are made consistent). "
            "force only: the projected field makes the internal force, the "
            "particles keep the stresses their material computed, so a smooth "
            "stress the field cannot represent is not cut back every step "
            "(doc/theory/assumed_stress_filter.md). force only needs Time "
            "stepping/Velocity transfer = APIC (with FLIP the stress the "
            "projection does not see grows from the transfer noise until the "
            "step is unstable) and a material without plastic history; the "
            "implicit integrators condense written back into each cell's "
            "tangent and refuse force only.");
        }

        void
        parse_parameters(ParameterHandler &prm) override
        {
          metric     = prm.get("Filter metric") == "compliance" ?
                         Metric::compliance :
                         Metric::mass;
          enriched   = prm.get("Filter field") == "enriched";
          write_back = prm.get("Filtered stress") != "force only";
        }

        /// The projection is of in-plane fields; the compliance metric
        /// needs elastic moduli; force only leaves a plastic state locked
        /// and, without APIC, grows unstable.
        void
        check(const Context &context) const override
        {
          const std::string here = context.where + "/Locking remedies: ";
          if (context.time.integrator !=
                Parameters::TimeStepping::Integrator::explicit_dynamics &&
              !write_back)
            throw InputError(
              here + "Filtered stress = force only has no linearization for "
                     "the implicit Time stepping/Integrator (quasi-static, "
                     "Newmark); use Filtered stress = written back");
          const auto &material = context.material;
          if (context.dimension == 1)
            throw InputError(context.where +
                             ": Locking remedies/Stress filter = assumed "
                             "stress needs Dimension 2 or 3");
          double E = 0, nu = 0;
          if (metric == Metric::compliance && !material.elastic_moduli(E, nu))
            throw InputError(here +
                             "Filter metric = compliance needs a material "
                             "with elastic moduli; '" +
                             material.name() + "' has none");
          if (!write_back && material.n_history() > 0)
            throw InputError(here +
                             "Filtered stress = force only leaves the "
                             "particles' stresses unfiltered, so '" +
                             material.name() +
                             "' would compute its plastic state from a "
                             "locked stress; use Filtered stress = written "
                             "back");
          if (!write_back && !context.time.apic)
            throw InputError(
              here +
              "Filtered stress = force only needs Time stepping/Velocity "
              "transfer = APIC: the stress the projection does not see "
              "accumulates in the particles, and with FLIP's transfer noise "
              "it grows until the step is unstable "
              "(doc/theory/assumed_stress_filter.md); use "
              "Filtered stress = written back");
        }
      };

      MPM_REGISTER_REMEDY(
        AssumedStressRemedy,
        "Stress filter",
        "assumed stress",
        "assumed stress: project the in-plane stresses of this body's "
        "particles in each cell onto the assumed-stress field of the cell "
        "(Filter field; Pian-Sumihara: 5 parameters in 2D, 18 in 3D) where the "
        "next internal force is computed, and integrate that field's force "
        "exactly over the particle domains "
        "(doc/theory/assumed_stress_filter.md). A cell whose particles cannot "
        "determine the linear terms (one particle, particles on a line) takes "
        "their weighted mean stress. 2D and 3D (refused in 1D).")
    } // namespace
  }   // namespace remedies
} // namespace mpm
