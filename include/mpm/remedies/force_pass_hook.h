#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>
#include <mpm/particles/body.h>

#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  namespace remedies
  {
    /**
     * A remedy that acts around each P2G pass with forces, for every body
     * that chose it at once (the 1D convection correction): it may change
     * the particles for the pass and must put them back after it.
     */
    template <int dim>
    class ForcePassHook
    {
    public:
      /// @p name: the name of its timer section.
      explicit ForcePassHook(const std::string &name)
        : timer_section(name)
      {}
      virtual ~ForcePassHook() = default;

      const std::string &
      name() const
      {
        return timer_section;
      }

      /// Just before the pass. Between the two calls no particle may move
      /// or be added.
      virtual void
      before_force_pass(const BackgroundGrid<dim>               &grid,
                        dealii::Particles::ParticleHandler<dim> &particles,
                        const std::vector<Body<dim>>            &bodies,
                        const double                             time) = 0;

      /// Just after it; @p p2g: the pass's nodal vector (P2GLayout).
      virtual void
      after_force_pass(NodalVector &p2g) = 0;

    private:
      std::string timer_section;
    };

    /// The hooks of the remedies @p bodies chose (empty if none needs one).
    template <int dim>
    std::vector<std::unique_ptr<ForcePassHook<dim>>>
    create_force_pass_hooks(const std::vector<Body<dim>> &bodies);
  } // namespace remedies
} // namespace mpm
