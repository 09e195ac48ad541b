#pragma once

#include <deal.II/base/parameter_handler.h>

#include <mpm/remedies/remedy.h>
#include <mpm/remedies/selection.h>

#include <memory>
#include <string>

namespace mpm
{
  namespace remedies
  {
    /**
     * Registry of the locking remedies. A remedy registers itself once with
     * MPM_REGISTER_REMEDY in its source file, under the slot that chooses
     * it (`Stress filter` or `Volumetric smoothing`, one remedy per slot
     * and body) and the name the slot's selection offers.
     */
    struct RemedyEntry
    {
      std::string slot;
      std::string name;
      /// Its part of the slot's documentation ("name: what it does.").
      std::string description;
      /// Its own entries, next to the slot.
      void (*declare_parameters)(dealii::ParameterHandler &prm);
      std::unique_ptr<Remedy> (*create)();
    };

    /// Add a remedy to the registry (called at static initialisation).
    bool
    register_remedy(const RemedyEntry &entry);

    /**
     * Declare, in the current subsection (a body's `Locking remedies`),
     * each slot as a selection of `none` and its registered remedies, and
     * every remedy's own entries.
     */
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /// The remedies chosen in the current subsection, their entries parsed.
    Selection
    parse_selection(dealii::ParameterHandler &prm);
  } // namespace remedies
} // namespace mpm

#define MPM_REGISTER_REMEDY(classname, slot, remedy_name, remedy_description) \
  namespace                                                                   \
  {                                                                           \
    const bool registered_##classname = mpm::remedies::register_remedy(       \
      {slot,                                                                  \
       remedy_name,                                                           \
       remedy_description,                                                    \
       &classname::declare_parameters,                                        \
       []() -> std::unique_ptr<mpm::remedies::Remedy> {                       \
         return std::make_unique<classname>();                                \
       }});                                                                   \
  }
