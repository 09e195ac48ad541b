#pragma once

#include <deal.II/base/parameter_handler.h>

#include <mpm/materials/material.h>
#include <mpm/shape_functions/family.h>

#include <string>

namespace mpm
{
  namespace Parameters
  {
    struct TimeStepping;
  }

  namespace remedies
  {
    /**
     * What a remedy of one body is checked against: the body, its
     * material and the run's settings that a remedy may not work with.
     */
    struct Context
    {
      /// The body's section, "Bodies/Body 0": messages start with it.
      std::string                     where;
      unsigned int                    dimension;
      const materials::Material      &material;
      shape_functions::Family         family;
      const Parameters::TimeStepping &time; ///< update scheme, APIC
    };

    /**
     * One body's choice of a locking remedy, with its settings: the body's
     * `subsection Locking remedies` chooses it by name in one of the slots
     * (`Stress filter`, `Volumetric smoothing`; registry.h), and the remedy
     * reads its own entries there. A remedy also derives from the struct
     * of its settings (AssumedStressSettings, ...), which its step-side
     * class (StressFilter, ConvectionCorrection, VolumetricSmoothing) reads
     * per body through Selection::find.
     */
    class Remedy
    {
    public:
      virtual ~Remedy() = default;

      /// Read the remedy's own entries (@p prm is in `Locking remedies`).
      virtual void
      parse_parameters(dealii::ParameterHandler &prm) = 0;

      /// Throw an InputError, naming the body and the parameter, if the
      /// remedy cannot be used in @p context.
      virtual void
      check(const Context &context) const = 0;
    };

    /// Throw an InputError naming the body and @p remedy (its slot and
    /// choice, "Stress filter = assumed stress") if the run integrates
    /// implicitly: for a remedy whose linearization is not built.
    void
    require_explicit_integrator(const Context     &context,
                                const std::string &remedy);
  } // namespace remedies
} // namespace mpm
