#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>
#include <mpm/particles/body.h>
#include <mpm/particles/field_selection.h>

#include <string>
#include <vector>

namespace mpm::shape_functions
{
  template <int dim>
  class DomainShapeFunctions;
}

namespace mpm
{
  /// What the stress update learns about the state on the way.
  struct StressUpdateResult
  {
    /// min_p h_cell / (c_p + |v_p|): the stability limit of the next step
    double      stable_time_step = std::numeric_limits<double>::max();
    std::string error; ///< first non-finite particle, if any
  };

  /**
   * Stress update of every owned particle: the velocity gradient
   * L_p = sum_i v_i (x) grad N_ip from the nodal velocities in
   * @p kinematics (KinematicsLayout), F_p <- (I + dt L_p) F_p,
   * V_p = det(F_p) V0_p, and the material's stress update. Also measures
   * the stable time step of the new state.
   *
   * Bodies with Volumetric smoothing hand their material a smoothed
   * volume change (remedies::VolumetricSmoothing): averaged over the
   * body's particles in the cell, or through the nodes, for which
   * @p volume_scratch (3 components per node) must be given.
   *
   * With @p domains (GIMP, CPDI) L_p comes from the family's gradients;
   * the node average keeps the Q1 functions of the particle's cell.
   * Only the particles @p only selects are updated (contact: one velocity
   * field per pass, @p kinematics and @p volume_scratch that field's).
   * With @p pressure_over_cell (the explicit step) the bodies whose cell
   * pressure P2G applies over the cell (remedies::CellPressureForce) take
   * the cell's exact volume change. With @p small_strain (Implicit
   * solver/Geometry = small strain) the materials see the symmetric part
   * of the velocity gradient, and F and the volumes stay.
   */
  template <int dim>
  StressUpdateResult
  update_stress(
    const BackgroundGrid<dim>                        &grid,
    dealii::Particles::ParticleHandler<dim>          &particles,
    const std::vector<Body<dim>>                     &bodies,
    const NodalVector                                &kinematics,
    const double                                      dt,
    NodalVector                                      *volume_scratch = nullptr,
    const shape_functions::DomainShapeFunctions<dim> *domains        = nullptr,
    const FieldSelection                             &only           = {},
    bool pressure_over_cell                                          = false,
    bool small_strain                                                = false);

  /// The stability limit of the current state (no update).
  template <int dim>
  double
  stable_time_step(const BackgroundGrid<dim>               &grid,
                   dealii::Particles::ParticleHandler<dim> &particles,
                   const std::vector<Body<dim>>            &bodies);

  /**
   * The particle of this rank with the smallest stability limit
   * h/(c + |v|) (or the first whose limit is not a positive number), as
   * "particle ID of body B at (x): h = .., wave speed c = .., |v| = ..";
   * empty without particles. For the message of a step that cannot
   * advance; not for the hot loop.
   */
  template <int dim>
  std::pair<double, std::string>
  limiting_particle(const BackgroundGrid<dim>               &grid,
                    dealii::Particles::ParticleHandler<dim> &particles,
                    const std::vector<Body<dim>>            &bodies);
} // namespace mpm
