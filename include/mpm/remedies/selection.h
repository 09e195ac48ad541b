#pragma once

#include <mpm/remedies/remedy.h>

#include <memory>
#include <vector>

namespace mpm
{
  namespace remedies
  {
    /**
     * The locking remedies one body chose, with their settings, in the
     * order of the slots (registry.h); a slot set to `none` adds nothing.
     * Copies share the (immutable) remedies.
     */
    class Selection
    {
    public:
      void
      add(std::shared_ptr<const Remedy> remedy)
      {
        chosen.push_back(std::move(remedy));
      }

      /// The settings @p S (AssumedStressSettings, ...) of a chosen
      /// remedy, or null if none has them: the step-side classes ask once
      /// per body.
      template <typename S>
      const S *
      find() const
      {
        for (const auto &remedy : chosen)
          if (const auto *settings = dynamic_cast<const S *>(remedy.get()))
            return settings;
        return nullptr;
      }

      /// Every chosen remedy's check, in slot order.
      void
      check(const Context &context) const
      {
        for (const auto &remedy : chosen)
          remedy->check(context);
      }

    private:
      std::vector<std::shared_ptr<const Remedy>> chosen;
    };
  } // namespace remedies
} // namespace mpm
