#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <mpm/integrators/nodal_linear_system.h>
#include <mpm/integrators/time_integrator.h>
#include <mpm/remedies/linearized_cell_smoothing.h>

#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * The quasi-static implicit step (doc/implicit.md): each step solves the
   * equilibrium f_int(u) = f_ext(t_n+1) for the nodal displacement
   * increment u by Newton's method, with updated-Lagrangian kinematics at
   * the particles. Phases of one step:
   *   nodal mass (which nodes are unknowns) -> constraints ->
   *   Newton: assemble residual and tangent -> AMG-preconditioned Krylov
   *           solve -> line search -> converged?
   *   -> stress update with the converged increment -> particle motion.
   * A step whose Newton iteration fails is cut in half (at most Maximum
   * step cuts times); the halves grow back once Newton converges in few
   * iterations. The particles' F, stress and history change only with a
   * converged increment.
   */
  template <int dim>
  class ImplicitIntegrator : public TimeIntegrator<dim>
  {
  public:
    /// Refuses (InputError) what the step has no consistent form for.
    explicit ImplicitIntegrator(SimulationState<dim> &state);

    std::string
    name() const override
    {
      return "quasi-static";
    }

    void
    initialize() override;

    double
    next_step_length() const override;

    void
    advance(const double dt) override;

    void
    compute_nodal_fields() override;

    std::vector<std::string>
    statistics_columns() const override;

    std::vector<double>
    statistics_values() const override;

  private:
    using TimeIntegrator<dim>::state;

    /// Norms of one assembly.
    struct Residual
    {
      double norm      = 0; ///< of the free unknowns
      double reference = 0; ///< max(|f_ext|, |f_int|) over all unknowns
    };

    struct NewtonResult
    {
      bool                converged         = false;
      unsigned int        iterations        = 0;
      unsigned int        linear_iterations = 0;
      std::vector<double> residuals; ///< relative, per iteration
      std::string         error;     ///< why it failed (if it did)
    };

    // The phases of one (sub-)step from t to t + dt.
    /// The unknowns (nodes with mass), their constraints, and the
    /// increment's start: the rigid bodies' motion at the nodes they
    /// reach.
    void
    find_unknowns(const double t, const double dt);
    NewtonResult
    solve_equilibrium(const double t, const double dt);
    /// Residual (and tangent) at the current increment; false and
    /// @p error set if a particle inverts or its material fails.
    bool
    assemble(const double t,
             const double dt,
             const bool   with_matrix,
             Residual    &residual,
             std::string &error);
    void
    commit(const double t, const double dt);

    /// The displacement of rigid body @p r (index into rigid_bodies) from
    /// t to t + dt (midpoint rule).
    dealii::Tensor<1, dim>
    rigid_displacement(const unsigned int r,
                       const double       t,
                       const double       dt) const;
    /// The nodes the rigid bodies reach: prescribed, prescribed_by.
    void
    find_prescribed_nodes();
    /// The force the prescribed nodes exert on the other bodies,
    /// f_int - f_ext there, summed over the ranks.
    void
    compute_reaction();

    /// The increment += alpha * delta (owned entries), ghosts updated.
    void
    add_to_increment(const dealii::TrilinosWrappers::MPI::Vector &delta,
                     const double                                 alpha);

    Parameters::ImplicitSolver::LinearSolver linear_solver;
    NodalLinearSystem<dim>                   system;
    /// The partition the system was built for.
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partition;
    NodalVector               increment; ///< u, dim components per node
    NodalVector               internal_force, external_force;
    std::vector<char>         active; ///< per node-local index: has mass
    NewtonResult              last;   ///< of the last sub-step
    unsigned int              last_cuts = 0;
    std::vector<double>       history_scratch;
    std::vector<unsigned int> rigid_bodies; ///< bodies of prescribed motion
    NodalVector               rigid_mass;   ///< per rigid body, per node
    /// per node-local index: the directions (bits) it follows a rigid
    /// body in, and which one (index into rigid_bodies)
    std::vector<unsigned char> prescribed;
    std::vector<unsigned int>  prescribed_by;
    dealii::Tensor<1, dim>     reaction; ///< of the last sub-step
    using Smoothing = remedies::LinearizedCellSmoothing<dim>;
    /// `Volumetric smoothing = cell` of the trial increments
    std::unique_ptr<Smoothing>             smoothing;
    std::vector<typename Smoothing::Point> points; ///< of one cell
  };
} // namespace mpm
