#include <mpm/remedies/convection_correction.h>
#include <mpm/remedies/convection_correction_remedy.h>
#include <mpm/remedies/force_pass_hook.h>

namespace mpm
{
  namespace remedies
  {
    template <int dim>
    std::vector<std::unique_ptr<ForcePassHook<dim>>>
    create_force_pass_hooks(const std::vector<Body<dim>> &bodies)
    {
      std::vector<std::unique_ptr<ForcePassHook<dim>>> hooks;
      for (const auto &body : bodies)
        if (body.prm.locking_remedies
              .template find<ConvectionCorrectionSettings>())
          {
            hooks.push_back(
              std::make_unique<ConvectionCorrection<dim>>(bodies));
            break;
          }
      return hooks;
    }

    template std::vector<std::unique_ptr<ForcePassHook<1>>>
    create_force_pass_hooks<1>(const std::vector<Body<1>> &);
    template std::vector<std::unique_ptr<ForcePassHook<2>>>
    create_force_pass_hooks<2>(const std::vector<Body<2>> &);
    template std::vector<std::unique_ptr<ForcePassHook<3>>>
    create_force_pass_hooks<3>(const std::vector<Body<3>> &);
  } // namespace remedies
} // namespace mpm
