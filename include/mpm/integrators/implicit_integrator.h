#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <mpm/integrators/cell_stencils.h>
#include <mpm/integrators/ghost_penalty.h>
#include <mpm/integrators/nodal_linear_system.h>
#include <mpm/integrators/time_integrator.h>
#include <mpm/remedies/linearized_cell_smoothing.h>
#include <mpm/remedies/linearized_node_smoothing.h>
#include <mpm/utilities/expression.h>

#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * The implicit step (doc/theory/implicit.md): each step solves the
   * equilibrium f_int(u) = f_ext(t_n+1) (quasi-static) or the equation of
   * motion M a_n+1(u) + f_int(u) = f_ext(t_n+1) (Newmark, lumped nodal
   * mass) for the nodal displacement increment u by Newton's method, with
   * updated-Lagrangian kinematics at the particles. Phases of one step:
   *   nodal mass (which nodes are unknowns) -> constraints ->
   *   [Newmark: the nodes' v_n and a_n] ->
   *   Newton: assemble residual and tangent -> AMG-preconditioned Krylov
   *           solve -> line search -> converged?
   *   -> stress update with the converged increment -> particle motion
   *      (and, Newmark, the particles' velocity change).
   * A step whose Newton iteration fails is cut in half (at most Maximum
   * step cuts times); the halves grow back once Newton converges in few
   * iterations. The particles' F, stress and history change only with a
   * converged increment.
   *
   * Every shape-function family takes part: the weights of a particle are
   * those of its domain at the start of the step (the step's cached
   * stencils), so a domain family's tangent couples the nodes its
   * particles reach, and the sparsity follows them every step.
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
      return dynamic ? "Newmark" : "quasi-static";
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
    /// `Preconditioner = AMG with cell pressure`: which bodies' cells are
    /// split, with which moduli; refuses a run where it cannot apply.
    void
    set_up_cell_pressure();
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
    /**
     * f(cell, particles, weights) for every owned cell with particles,
     * with the weights of the run's family (begin_cell() done; every
     * particle must be evaluated, in order, for the stencil cache); f
     * returns false (and sets its error) to stop. Returns whether every
     * call returned true.
     */
    template <typename Function>
    bool
    with_cell_weights(const Function &f);
    /// The node average's first pass over the cells (its nodal sums, and
    /// C with @p with_matrix) at the trial increment of time @p t.
    bool
    add_node_sums(const double t, const bool with_matrix, std::string &error);
    /// The trial kinematics of a cell's particles at the current
    /// increment (points, loads, stencils, the smoothing's cell sums).
    template <typename Weights, typename Particles>
    bool
    gather_cell(Weights         &weights,
                const Particles &particles,
                const double     t,
                std::string     &error);
    /// A cell's residual (and tangent) from gather_cell()'s state, added
    /// to the system and the force vectors.
    template <typename CellIterator, typename Particles>
    bool
    add_cell_system(const CellIterator &cell,
                    const Particles    &particles,
                    const double        dt,
                    const bool          with_matrix,
                    std::string        &error);
    /// The force (and tangent) of the cell's filtered bodies from their
    /// particles' filtered_taus (and filtered_changes), added to the
    /// cell's system (add_cell_system()).
    template <typename CellIterator, typename Particles>
    bool
    add_filtered_force(const CellIterator &cell,
                       const Particles    &particles,
                       const bool          with_matrix,
                       std::string        &error);
    /// One pass over the stencils of the start of the step: support,
    /// rigid_mass, and for a domain family the sparsity of the nodes its
    /// stencils couple.
    void
    scan_stencils();
    void
    commit(const double t, const double dt);

    /// Newmark: the nodes' velocity v_n (the particles' momentum) and
    /// acceleration a_n = M^-1 (f_ext(t) - f_int) of the start of the
    /// step, both as the walls admit; false (and the run's error) if the
    /// stresses cannot be evaluated.
    bool
    start_motion(const double t, const double dt);
    /// Newmark: the inertia M (a_n+1 + c v_n+1) of the owned unknowns at
    /// the current increment (and its tangent), added to the system;
    /// returns the squared norm of that force on this rank.
    double
    add_inertia(const double dt, const bool with_matrix);
    /// Newmark's a_n+1 of nodal entry k (node-local index * dim + c) for
    /// the increment's value there.
    double
    new_acceleration(const unsigned int k, const double dt) const
    {
      const double u = increment.local_element(k);
      return (u - dt * velocity_n.local_element(k)) / (beta * dt * dt) -
             (0.5 / beta - 1) * acceleration_n.local_element(k);
    }
    /// Newmark's v_n+1 - v_n of nodal entry k for the increment's value
    /// there.
    double
    velocity_change(const unsigned int k, const double dt) const
    {
      return dt * ((1 - gamma) * acceleration_n.local_element(k) +
                   gamma * new_acceleration(k, dt));
    }

    /// Newmark: the mass of the deformable bodies at node @p i
    /// (node-local), without the rigid bodies'.
    double
    deformable_mass(const unsigned int i) const;
    /// Whether node @p i (node-local) is a moving boundary's: its
    /// prescribed directions follow the boundary, not a rigid body.
    bool
    moves_with_boundary(const unsigned int i) const
    {
      return boundary_velocity && state.background.on_moving_boundary(i);
    }
    /// The velocity at time @p t of what prescribes node @p i's motion
    /// (its moving boundary or its rigid body, prescribed_by).
    void
    prescribed_velocity(const unsigned int i, const double t, double *v) const;

    /// The displacement of rigid body @p r (index into rigid_bodies) from
    /// t to t + dt (midpoint rule).
    dealii::Tensor<1, dim>
    rigid_displacement(const unsigned int r,
                       const double       t,
                       const double       dt) const;
    /// The nodes the rigid bodies reach (rigid_mass of scan_stencils()):
    /// prescribed, prescribed_by.
    void
    find_prescribed_nodes();
    /// The force the prescribed nodes exert on the other bodies,
    /// f_int - f_ext there, summed over the ranks: the rigid bodies'
    /// (reaction) and the moving boundary's (boundary_reaction), with
    /// Newmark's inertia of their nodes over the step @p dt.
    void
    compute_reaction(const double dt);

    /// The increment += alpha * delta (owned entries), ghosts updated.
    void
    add_to_increment(const dealii::TrilinosWrappers::MPI::Vector &delta,
                     const double                                 alpha);

    const bool   dynamic; ///< Newmark, not quasi-static
    const double beta, gamma, damping;
    /// Newmark: the nodes' v_n and a_n (dim components per node)
    NodalVector velocity_n, acceleration_n;
    /// Newmark: assemble() adds the inertia (not for a_n itself)
    bool                                     with_inertia = false;
    Parameters::ImplicitSolver::LinearSolver linear_solver;
    /// Linear solver = automatic: solves of at most this many unknowns go
    /// to the direct solver (0 with a split preconditioner or another
    /// choice: none)
    dealii::types::global_dof_index direct_limit = 0;
    NodalLinearSystem<dim>          system;
    /// The partition the system was built for.
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partition;
    NodalVector increment; ///< u, dim components per node
    NodalVector internal_force, external_force;
    /// per node-local index: an unknown (mass, and Minimum nodal support)
    std::vector<char> active;
    /// sum_p S_ap V_p per node, and int N_a over the grid (its support)
    NodalVector               support, full_support;
    NewtonResult              last; ///< of the last sub-step
    unsigned int              last_cuts = 0;
    std::vector<double>       history_scratch;
    std::vector<unsigned int> rigid_bodies; ///< bodies of prescribed motion
    std::vector<int>          rigid_index; ///< per body: its place there, or -1
    NodalVector               rigid_mass;  ///< per rigid body, per node
    /// per node-local index: the directions (bits) it follows a rigid
    /// body in, and which one (index into rigid_bodies)
    std::vector<unsigned char> prescribed;
    std::vector<unsigned int>  prescribed_by;
    dealii::Tensor<1, dim>     reaction; ///< of the last sub-step
    /// Boundary conditions/Moving boundary velocity (if Moving boundary
    /// ids), and the force of its nodes on the bodies in the last sub-step
    std::unique_ptr<Expression<dim>> boundary_velocity;
    dealii::Tensor<1, dim>           boundary_reaction;
    using Smoothing = remedies::LinearizedCellSmoothing<dim>;
    /// `Implicit solver/Ghost penalty`, and the nodes of the faces it may
    /// assemble (added to every sparsity)
    GhostPenalty<dim>                           ghost_penalty;
    typename NodalLinearSystem<dim>::NodeGroups face_groups;
    /// `Volumetric smoothing = cell` of the trial increments
    std::unique_ptr<Smoothing> smoothing;
    using NodeSmoothing = remedies::LinearizedNodeSmoothing<dim>;
    std::unique_ptr<NodeSmoothing>        node_smoothing;
    std::unique_ptr<Epetra_CrsMatrix>     node_coupling;
    dealii::TrilinosWrappers::MPI::Vector node_coupling_rhs;
    std::vector<double>                   node_force_derivative;
    /// per cell with node-smoothed particles: its vertices and reach
    std::vector<unsigned int>                   node_cell_vertices;
    typename NodalLinearSystem<dim>::NodeGroups node_cell_reach;
    std::vector<typename Smoothing::Point>      points; ///< of one cell
    /// The loads of a point of the cell: body force (its nodal weight
    /// applied per entry) and the traction on its loaded face.
    struct PointLoads
    {
      double body[dim];
      bool   has_face;
      double traction[dim];
    };
    std::vector<PointLoads>                     loads;          ///< of one cell
    std::vector<char>                           has_body_force; ///< per body
    CellStencils<dim>                           stencils;       ///< of one cell
    typename NodalLinearSystem<dim>::NodeGroups stencil_groups; ///< per cell
    /// per particle of the cell: tau = j sigma of a filtered body, and
    /// its change for each column of the cell's matrix
    std::vector<dealii::SymmetricTensor<2, dim>> filtered_taus;
    std::vector<dealii::SymmetricTensor<2, dim>> filtered_changes;
    /// the filtered force of one body in one cell (add_filtered_force())
    std::vector<double> filtered_force;
    /// `Preconditioner = AMG with cell pressure`: per body, the lambda_s
    /// its cells' stiff part is split with (0: not split) and the
    /// volumetric stiffness (gamma + 1) mu the rest keeps; the parts of
    /// one cell
    std::vector<double> split_lambda, split_rest_modulus;
    std::vector<typename NodalLinearSystem<dim>::CellPressure> cell_pressures;
    dealii::FullMatrix<double>                                 cell_matrix;
    dealii::Vector<double>                                     cell_rhs;
    std::vector<dealii::types::global_dof_index>               cell_dofs;
  };
} // namespace mpm
