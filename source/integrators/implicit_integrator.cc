#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <mpm/grid/nodal_layout.h>
#include <mpm/integrators/implicit_integrator.h>
#include <mpm/materials/lame_moduli.h>
#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/remedies/assumed_stress_force.h>
#include <mpm/remedies/stress_filter.h>
#include <mpm/shape_functions/family_registry.h>
#include <mpm/solver/stress_update.h>
#include <mpm/transfer/grid_to_particle.h>
#include <mpm/transfer/particle_to_grid.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace mpm
{
  using namespace dealii;

  template <int dim>
  ImplicitIntegrator<dim>::ImplicitIntegrator(SimulationState<dim> &s)
    : TimeIntegrator<dim>(s)
    , dynamic(s.params.time.integrator ==
              Parameters::TimeStepping::Integrator::newmark)
    , beta(s.params.time.newmark_beta)
    , gamma(s.params.time.newmark_gamma)
    , damping(dynamic ? s.params.time.damping : 0.)
    , ghost_penalty(s.params.implicit.ghost_penalty > 0 ?
                      s.params.implicit.ghost_penalty *
                        GhostPenalty<dim>::youngs_modulus(s.bodies) :
                      0.)
    , smoothing(std::make_unique<Smoothing>(s.bodies))
    , node_smoothing(std::make_unique<NodeSmoothing>(s.bodies))
  {
    using LinearSolver    = Parameters::ImplicitSolver::LinearSolver;
    const auto &p         = state.params;
    bool        symmetric = true;
    with_inertia          = dynamic;
    for (unsigned int b = 0; b < state.bodies.size(); ++b)
      {
        // (the remedies refuse the integrator themselves)
        const auto  &body     = state.bodies[b];
        const auto   section  = "Bodies/" + Parameters::body_section(b);
        const auto  &material = *body.material;
        Tensor<4, 3> tangent;
        materials::PointKinematics at_rest;
        at_rest.F  = unit_symmetric_tensor<3>();
        at_rest.dt = 1;
        std::vector<double> history(material.n_history());
        if (!material.stress_tangent(at_rest,
                                     SymmetricTensor<2, 3>(),
                                     ArrayView<const double>(history),
                                     tangent))
          throw InputError(section + "/Material/Model = " + material.name() +
                           " has no tangent for Time stepping/Integrator = " +
                           name() + "; use the explicit integrator");
        if (p.implicit.small_strain && !body.is_rigid() &&
            !material.small_strain_increment())
          throw InputError(
            section + "/Material/Model = " + material.name() +
            " has no small-strain form for Implicit solver/Geometry = small "
            "strain, which takes the rate-form models (linear elastic, von "
            "Mises plasticity) with Strain increment = start of step; use "
            "Geometry = fixed");
        if (!dynamic && !material.has_static_shear_stiffness())
          throw InputError(section + "/Material/Model = " + material.name() +
                           " has no shear stiffness at rest, so a "
                           "quasi-static step has no equilibrium to find; "
                           "use Time stepping/Integrator = Newmark");
        // F-bar, the rate form's B-bar and the filter (G^T H^-1 G_C with
        // G_C != G) couple a cell's particles without symmetry
        symmetric = symmetric && material.has_symmetric_tangent() &&
                    !smoothing->smooths(b) && !node_smoothing->smooths(b) &&
                    !s.stress_filter->filtered(b);
        if (node_smoothing->smooths(b) && s.stress_filter->filtered(b))
          throw InputError(section +
                           ": Volumetric smoothing = node with a Stress "
                           "filter has no linearized form for Time "
                           "stepping/Integrator = " +
                           name() +
                           "; use Volumetric smoothing = cell with the "
                           "filter, or the explicit integrator");
        rigid_index.push_back(body.is_rigid() ? int(rigid_bodies.size()) : -1);
        if (body.is_rigid())
          rigid_bodies.push_back(b);
        has_body_force.push_back(body.has_body_force());
      }
    // (parameters.cc refuses it for the other integrators)
    if (!p.boundary.moving.empty())
      {
        boundary_velocity = std::make_unique<Expression<dim>>(
          p.boundary.moving_velocity,
          dim,
          spatial_variables(dim),
          p.constants,
          true,
          "Boundary conditions/Moving boundary velocity");
      }
    linear_solver = p.implicit.linear_solver;
    // automatic: the Krylov method here, the direct solver per solve when
    // the system is small enough (solve_equilibrium())
    if (linear_solver == LinearSolver::automatic)
      {
        linear_solver = symmetric ? LinearSolver::cg : LinearSolver::gmres;
        if (p.implicit.preconditioner ==
            Parameters::ImplicitSolver::Preconditioner::amg)
          direct_limit = p.implicit.direct_limit[dim - 1];
      }
    if (linear_solver == LinearSolver::cg && !symmetric)
      throw InputError(
        "Implicit solver/Linear solver = CG needs a symmetric tangent, but "
        "a material of the bodies is not hyperelastic: use GMRES (or "
        "automatic)");
    set_up_cell_pressure();
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::set_up_cell_pressure()
  {
    using Preconditioner = Parameters::ImplicitSolver::Preconditioner;
    const auto &p        = state.params;
    split_lambda.assign(state.bodies.size(), 0.);
    split_rest_modulus.assign(state.bodies.size(), 0.);
    if (p.implicit.preconditioner != Preconditioner::amg_cell_pressure)
      return;
    const std::string name =
      "Implicit solver/Preconditioner = AMG with cell pressure";
    if (linear_solver == Parameters::ImplicitSolver::LinearSolver::direct)
      throw InputError(name + " preconditions an iterative solver, but "
                              "Implicit solver/Linear solver = direct");
    if (dim == 1)
      throw InputError(name + " is for 2D and 3D: in 1D the volume change "
                              "is the whole strain, nothing locks, and AMG "
                              "alone takes a seventh of its iterations");
    bool any = false;
    for (unsigned int b = 0; b < state.bodies.size(); ++b)
      {
        const auto &body = state.bodies[b];
        double      E = 0, nu = 0;
        // (a filtered body's force is the projection's, whose volumetric
        // part is not the theta-bar one: the split would leave the rest
        // of its stiffness indefinite)
        if (!smoothing->smooths(b) || body.is_rigid() ||
            state.stress_filter->filtered(b) ||
            !body.material->elastic_moduli(E, nu))
          continue;
        const materials::LameModuli moduli(E, nu, state.params.kinematics);
        const double                gamma = p.implicit.cell_pressure_gamma;
        const double lambda_s             = moduli.lambda - gamma * moduli.mu;
        if (!(lambda_s > 0) || !std::isfinite(lambda_s))
          continue;
        split_lambda[b]       = lambda_s;
        split_rest_modulus[b] = (gamma + 1) * moduli.mu;
        any                   = true;
      }
    if (!any)
      throw InputError(
        name + " splits the cells of nearly incompressible bodies "
               "(Volumetric smoothing = cell without a Stress filter, "
               "elastic moduli with lambda > Cell pressure gamma times mu, "
               "i.e. nu > 0.455 in 3D and plane strain at the default 10), "
               "and no body is one: use Preconditioner = AMG");
    system.split_cell_pressure(true);
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::initialize()
  {
    // No stability limit: the step is the load step.
    state.stable_dt = std::numeric_limits<double>::max();
    if (dynamic)
      {
        const double limit =
          Utilities::MPI::min(stable_time_step(state.background,
                                               state.particle_handler,
                                               state.bodies),
                              state.comm);
        state.pcout << "  Newmark step " << state.params.time.time_step << " = "
                    << state.params.time.time_step / limit
                    << " times the explicit stability limit " << limit
                    << " of the initial state" << std::endl;
      }
  }

  template <int dim>
  double
  ImplicitIntegrator<dim>::next_step_length() const
  {
    return state.params.time.time_step;
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::compute_nodal_fields()
  {
    const transfer::P2GContext<dim> context{{state.background,
                                             state.particle_handler,
                                             state.domain_functions.get(),
                                             0},
                                            state.bodies,
                                            *state.stress_filter,
                                            state.current_time,
                                            transfer::P2GContent::mass_momentum,
                                            state.p2g};
    state.local_error.record(transfer::particle_to_grid(context));
    state.p2g.update_ghost_values();
  }

  namespace
  {
    /// The order of convergence of the last three residuals above the
    /// round-off floor (1e-12 relative), log(r_k / r_k-1) /
    /// log(r_k-1 / r_k-2): 2 for quadratic convergence; 0 if fewer.
    double
    convergence_rate(const std::vector<double> &residuals)
    {
      std::vector<double> r;
      for (const double x : residuals)
        if (x > 1e-12)
          r.push_back(x);
      const std::size_t n = r.size();
      if (n < 3 || r[n - 2] == r[n - 3])
        return 0.;
      return std::log(r[n - 1] / r[n - 2]) / std::log(r[n - 2] / r[n - 3]);
    }
  } // namespace

  template <int dim>
  std::vector<std::string>
  ImplicitIntegrator<dim>::statistics_columns() const
  {
    std::vector<std::string> c = {"newton_iterations",
                                  "linear_iterations",
                                  "step_cuts",
                                  "relative_residual",
                                  "convergence_rate"};
    if (!rigid_bodies.empty())
      for (unsigned int d = 0; d < dim; ++d)
        c.push_back(std::string("reaction_") + "xyz"[d]);
    if (boundary_velocity)
      for (unsigned int d = 0; d < dim; ++d)
        c.push_back(std::string("boundary_reaction_") + "xyz"[d]);
    return c;
  }

  template <int dim>
  std::vector<double>
  ImplicitIntegrator<dim>::statistics_values() const
  {
    std::vector<double> v = {double(last.iterations),
                             double(last.linear_iterations),
                             double(last_cuts),
                             last.residuals.empty() ? 0. :
                                                      last.residuals.back(),
                             convergence_rate(last.residuals)};
    if (!rigid_bodies.empty())
      for (unsigned int d = 0; d < dim; ++d)
        v.push_back(reaction[d]);
    if (boundary_velocity)
      for (unsigned int d = 0; d < dim; ++d)
        v.push_back(boundary_reaction[d]);
    return v;
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::advance(const double dt)
  {
    const auto &p = state.params.implicit;
    if (partition != state.background.node_partitioner())
      {
        TimerOutput::Scope t(state.timer, "implicit set-up");
        partition = state.background.node_partitioner();
        ghost_penalty.reinit(state.background);
        face_groups = ghost_penalty.couplings(state.background);
        system.reinit(state.background, state.comm, face_groups);
        stencils = CellStencils<dim>(state.background.n_local_nodes());
        // int N_a = |cell| / 2^dim from each cell at the node (exact on
        // parallelograms)
        state.background.initialize_vector(support, 1);
        state.background.initialize_vector(full_support, 1);
        for (const auto &cell : state.background.owned_cells())
          for (unsigned int v = 0; v < BackgroundGrid<dim>::n_vertices; ++v)
            full_support.local_element(state.background.nodes(cell)[v]) +=
              cell->measure() / BackgroundGrid<dim>::n_vertices;
        full_support.compress(VectorOperation::add);
        full_support.update_ghost_values();
        state.background.initialize_vector(increment, dim);
        state.background.initialize_vector(internal_force, dim);
        state.background.initialize_vector(external_force, dim);
        if (!rigid_bodies.empty())
          state.background.initialize_vector(rigid_mass, rigid_bodies.size());
        if (dynamic)
          {
            state.background.initialize_vector(velocity_n, dim);
            state.background.initialize_vector(acceleration_n, dim);
          }
      }
    // Sub-steps: halved when Newton fails, doubled again (up to dt) when
    // it converges in few iterations.
    double       t         = state.current_time;
    const double t_end     = t + dt;
    double       sub       = dt;
    unsigned int depth     = 0;
    last_cuts              = 0;
    unsigned int total_its = 0, total_linear = 0;
    while (t_end - t > 1e-12 * dt)
      {
        const double h = std::min(sub, t_end - t);
        find_unknowns(t, h);
        // The stencils are those of the start of the step: a domain that
        // cannot be evaluated (outside the grid, collapsed) stays so in
        // every cut, so the run stops with its message at once.
        if (Utilities::MPI::max(state.local_error.empty() ? 0 : 1,
                                state.comm) == 1)
          return;
        if (dynamic && !start_motion(t, h))
          return;
        last = solve_equilibrium(t + h, h);
        total_its += last.iterations;
        total_linear += last.linear_iterations;
        if (!last.converged)
          {
            if (depth == p.max_step_cuts)
              {
                std::ostringstream s;
                s << "Newton's method failed at t = " << t + h << " after "
                  << depth << " step cuts (Implicit solver/Maximum step cuts): "
                  << last.error << "; relative residuals:";
                for (const double r : last.residuals)
                  s << ' ' << std::setprecision(3) << r;
                // Newton's increments not reducing the residual at all:
                // the tangent is singular in the loaded direction.
                if (last.residuals.size() > 2 &&
                    *std::min_element(last.residuals.begin() + 1,
                                      last.residuals.end()) >
                      0.99 * last.residuals.front())
                  s << ". The residual never decreased: the tangent is "
                       "singular, most likely because a body is not held "
                       "(a quasi-static step needs walls (Boundary "
                       "conditions) or rigid bodies of prescribed motion "
                       "that hold every body in every direction, since "
                       "there is no inertia)";
                state.local_error.record(s.str());
                return;
              }
            sub = h / 2;
            ++depth;
            ++last_cuts;
            state.pcout << "  Newton failed (" << last.error
                        << "): step cut to " << sub << std::endl;
            continue;
          }
        compute_reaction(h);
        commit(t, h);
        t += h;
        if (last.iterations <= 4 && depth > 0)
          {
            sub *= 2;
            --depth;
          }
      }
    last.iterations        = total_its;
    last.linear_iterations = total_linear;
    std::ostringstream s;
    s << "  Newton: " << total_its << " iterations, " << total_linear
      << " linear iterations";
    if (last_cuts > 0)
      s << ", " << last_cuts << " step cuts";
    s << "; relative residuals";
    for (const double r : last.residuals)
      s << ' ' << std::scientific << std::setprecision(2) << r;
    state.pcout << s.str() << std::endl;
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::find_unknowns(const double t, const double dt)
  {
    // The particles moved since the stencils were built (the domains'
    // stencils of this step are those at its start).
    if (state.domain_functions)
      state.domain_functions->forget_stencils();
    // Nodes without mass (no particle reaches them) are not unknowns.
    compute_nodal_fields();
    scan_stencils();
    using P          = transfer::P2GLayout<dim>;
    const auto &grid = state.background;
    // Newmark's inertia holds the nodes that slivers reach (their mass
    // and stiffness vanish together); the threshold is quasi-static only.
    const double fraction =
      dynamic ? 0. : state.params.implicit.min_nodal_support;
    active.assign(grid.n_local_nodes(), 0);
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      active[i] =
        state.p2g.local_element(i * P::n_components + P::mass) >
          state.min_nodal_mass &&
        support.local_element(i) >= fraction * full_support.local_element(i);
    ghost_penalty.select_faces(grid, active, support, full_support);
    find_prescribed_nodes();
    std::vector<Tensor<1, dim>> values(grid.n_local_nodes());
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      {
        // (the boundary's motion wins over a rigid body's)
        if (moves_with_boundary(i) && active[i])
          prescribed[i] = (1u << dim) - 1;
        if (!prescribed[i])
          continue;
        // the midpoint rule, as rigid_displacement()
        double v[dim];
        prescribed_velocity(i, t + dt / 2, v);
        for (unsigned int c = 0; c < dim; ++c)
          values[i][c] = v[c] * dt;
      }
    system.build_constraints(grid, active, prescribed, values);
    increment = 0.;
  }

  template <int dim>
  Tensor<1, dim>
  ImplicitIntegrator<dim>::rigid_displacement(const unsigned int r,
                                              const double       t,
                                              const double       dt) const
  {
    double v[dim];
    state.bodies[rigid_bodies[r]].prescribed_velocity.value(Point<dim>(),
                                                            t + dt / 2,
                                                            v);
    Tensor<1, dim> u;
    for (unsigned int c = 0; c < dim; ++c)
      u[c] = v[c] * dt;
    return u;
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::scan_stencils()
  {
    // One pass over the stencils of the start of the step: the particles'
    // volume at the nodes (support), the rigid bodies' mass there, and for
    // a domain family the nodes each cell's particles reach, all of which
    // couple (the sparsity; the cell average of the smoothing couples them
    // all).
    using L                 = ParticleLayout<dim>;
    const unsigned int n_r  = rigid_bodies.size();
    const bool         wide = state.domain_functions != nullptr;
    support                 = 0.;
    if (n_r > 0)
      rigid_mass = 0.;
    stencil_groups.clear();
    const bool node_average = node_smoothing->any();
    node_cell_vertices.clear();
    node_cell_reach.clear();
    double     *V = support.begin();
    double     *m = n_r > 0 ? rigid_mass.begin() : nullptr;
    std::string error;
    with_cell_weights([&](const auto &cell, const auto &pic, auto &weights) {
      stencils.begin_cell();
      bool node_smoothed = false;
      for (const auto &particle : pic)
        {
          if (!weights.evaluate(particle, wide, error))
            return false;
          const double *prop = particle.get_properties().data();
          node_smoothed =
            node_smoothed ||
            node_smoothing->smooths(static_cast<unsigned int>(prop[L::body]));
          const int r = rigid_index[static_cast<unsigned int>(prop[L::body])];
          for (unsigned int a = 0; a < weights.size(); ++a)
            {
              V[weights.node(a)] += prop[L::volume] * weights.value(a);
              if (r >= 0)
                m[weights.node(a) * n_r + r] +=
                  prop[L::mass] * weights.value(a);
            }
          if (wide)
            stencils.add(weights, nullptr);
        }
      if (wide)
        {
          stencil_groups.nodes.insert(stencil_groups.nodes.end(),
                                      stencils.nodes(),
                                      stencils.nodes() + stencils.n_nodes());
          stencil_groups.close_group();
        }
      if (node_smoothed)
        {
          // the node average couples the cell's vertices with its reach
          const unsigned int *corners = state.background.nodes(cell);
          node_cell_vertices.insert(node_cell_vertices.end(),
                                    corners,
                                    corners + Smoothing::nv);
          if (wide)
            node_cell_reach.nodes.insert(node_cell_reach.nodes.end(),
                                         stencils.nodes(),
                                         stencils.nodes() + stencils.n_nodes());
          else
            node_cell_reach.nodes.insert(node_cell_reach.nodes.end(),
                                         corners,
                                         corners + Smoothing::nv);
          node_cell_reach.close_group();
        }
      return true;
    });
    state.local_error.record(error);
    support.compress(VectorOperation::add);
    support.update_ghost_values();
    if (n_r > 0)
      {
        rigid_mass.compress(VectorOperation::add);
        rigid_mass.update_ghost_values();
      }
    if (wide)
      // (the ghost penalty's faces couple beyond the stencils)
      stencil_groups.append(face_groups);
    if (node_average)
      {
        node_smoothing->begin_step(state.background,
                                   state.comm,
                                   node_cell_vertices,
                                   node_cell_reach.nodes,
                                   node_cell_reach.start);
        system.couple(wide ? stencil_groups : system.cell_groups(),
                      &node_smoothing->node_coupling());
      }
    else if (wide)
      system.couple(stencil_groups);
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::find_prescribed_nodes()
  {
    const auto        &grid = state.background;
    const unsigned int n_r  = rigid_bodies.size();
    prescribed.assign(grid.n_local_nodes(), 0);
    prescribed_by.assign(grid.n_local_nodes(), 0);
    if (n_r == 0)
      return;
    // A node follows the rigid body of most mass there: in its Prescribed
    // directions if it also carries another body, in every direction if
    // not (no other stiffness holds it).
    using P                  = transfer::P2GLayout<dim>;
    const unsigned int all   = (1u << dim) - 1;
    const double       m_min = state.min_nodal_mass;
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      {
        double       rigid = 0, largest = 0;
        unsigned int which = 0;
        for (unsigned int r = 0; r < n_r; ++r)
          {
            const double mr = rigid_mass.local_element(i * n_r + r);
            rigid += mr;
            if (mr > largest)
              {
                largest = mr;
                which   = r;
              }
          }
        if (!(largest > m_min))
          continue;
        const double total =
          state.p2g.local_element(i * P::n_components + P::mass);
        prescribed_by[i] = which;
        prescribed[i] =
          total - rigid > m_min ?
            state.bodies[rigid_bodies[which]].prm.prescribed_directions :
            all;
      }
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::compute_reaction(const double dt)
  {
    reaction          = 0;
    boundary_reaction = 0;
    const auto &grid  = state.background;
    for (unsigned int i = 0; i < grid.n_owned_nodes(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        if (prescribed[i] & (1u << c))
          {
            const unsigned int k = i * dim + c;
            // Newmark: the force also accelerates the node's mass
            const double inertia =
              dynamic ?
                deformable_mass(i) * (new_acceleration(k, dt) +
                                      damping * (velocity_n.local_element(k) +
                                                 velocity_change(k, dt))) :
                0.;
            (moves_with_boundary(i) ? boundary_reaction : reaction)[c] +=
              internal_force.local_element(k) -
              external_force.local_element(k) + inertia;
          }
    reaction          = Utilities::MPI::sum(reaction, state.comm);
    boundary_reaction = Utilities::MPI::sum(boundary_reaction, state.comm);
  }

  template <int dim>
  typename ImplicitIntegrator<dim>::NewtonResult
  ImplicitIntegrator<dim>::solve_equilibrium(const double t, const double dt)
  {
    const auto  &p = state.params.implicit;
    NewtonResult result;
    Residual     r;
    // With prescribed motion the predictor assembles its own matrix: the
    // first assembly gives only the residual at the start.
    const bool predict = system.has_prescribed_motion();
    if (!assemble(t, dt, !predict, r, result.error))
      return result;
    TrilinosWrappers::MPI::Vector delta;
    // One linear solve into delta; false (and the error set) if it fails.
    const auto solve = [&]() {
      TimerOutput::Scope timer(state.timer, "implicit linear solve");
      const auto         solved =
        system.solve(state.background,
                     p,
                     direct_limit > 0 && system.n_unknowns() <= direct_limit ?
                       Parameters::ImplicitSolver::LinearSolver::direct :
                       linear_solver,
                     delta);
      result.linear_iterations += solved.iterations;
      result.error = solved.error;
      return solved.error.empty();
    };
    double     first_energy = 0;
    const auto relative     = [](const Residual &r) {
      return r.reference > 0 ? r.norm / r.reference : r.norm;
    };
    const auto small_residual = [&p](const Residual &r) {
      return r.norm <= p.residual_tolerance * r.reference ||
             r.norm <= p.absolute_residual_tolerance;
    };
    result.residuals.push_back(relative(r));
    if (predict)
      {
        // Predictor: the rigid bodies' motion as the values of their
        // nodes in a linear solve with the tangent at the start, so the
        // nodes next to them follow too (starting from the motion at
        // their nodes alone would crush the cells between).
        system.prescribe_motion(true);
        Residual   with_motion;
        const bool solved =
          assemble(t, dt, true, with_motion, result.error) && solve();
        system.prescribe_motion(false);
        if (!solved)
          return result;
        ++result.iterations;
        first_energy = std::abs(delta * system.right_hand_side());
        add_to_increment(delta, 1.);
        if (!assemble(t, dt, true, r, result.error))
          return result;
        result.residuals.push_back(relative(r));
        if (small_residual(r))
          {
            result.converged = true;
            return result;
          }
      }
    for (;;)
      {
        if (small_residual(r) && result.iterations == 0)
          {
            result.converged = true;
            return result;
          }
        if (result.iterations == p.max_iterations)
          {
            result.error = "no convergence in " +
                           std::to_string(p.max_iterations) + " iterations";
            return result;
          }
        if (!solve())
          return result;
        ++result.iterations;
        const double energy = std::abs(delta * system.right_hand_side());
        if (first_energy == 0)
          first_energy = energy;
        // Backtracking: halve the increment until the residual decreases.
        const double previous = r.norm;
        double       alpha    = 1;
        add_to_increment(delta, alpha);
        bool assembled = assemble(t, dt, true, r, result.error);
        for (unsigned int k = 0;
             p.line_search && k < 6 && (!assembled || r.norm > previous);
             ++k)
          {
            add_to_increment(delta, -alpha / 2);
            alpha /= 2;
            result.error.clear();
            assembled = assemble(t, dt, false, r, result.error);
          }
        if (!assembled)
          return result;
        if (alpha < 1 && !assemble(t, dt, true, r, result.error))
          return result;
        result.residuals.push_back(relative(r));
        // The energy criterion compares this increment with the first; an
        // increment that is the first leaves the residual to decide.
        const bool small_energy =
          result.iterations == 1 || energy <= p.energy_tolerance * first_energy;
        if (small_residual(r) && small_energy)
          {
            result.converged = true;
            return result;
          }
      }
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::add_to_increment(
    const TrilinosWrappers::MPI::Vector &delta,
    const double                         alpha)
  {
    const unsigned int n = dim * state.background.n_owned_nodes();
    const double      *d = delta.begin();
    for (unsigned int k = 0; k < n; ++k)
      increment.local_element(k) += alpha * d[k];
    increment.update_ghost_values();
  }


  template <int dim>
  template <typename Function>
  bool
  ImplicitIntegrator<dim>::with_cell_weights(const Function &f)
  {
    bool ok = true;
    shape_functions::with_family(
      state.params.shape_functions.family, [&](const auto family) {
        using Weights = typename decltype(family)::template Weights<dim>;
        Weights weights(state.background, state.domain_functions.get());
        weights.begin_pass(state.particle_handler.n_locally_owned_particles());
        for_each_cell_with_particles(state.background,
                                     state.particle_handler,
                                     [&](const auto &cell, const auto &pic) {
                                       if (!ok)
                                         return;
                                       weights.begin_cell(cell);
                                       ok = f(cell, pic, weights);
                                     });
        weights.end_pass(ok);
      });
    return ok;
  }

  template <int dim>
  template <typename Weights, typename Particles>
  bool
  ImplicitIntegrator<dim>::gather_cell(Weights         &weights,
                                       const Particles &pic,
                                       const double     t,
                                       std::string     &error)
  {
    // The trial kinematics of the cell's particles: h = sum_a u_a (x) G_a,
    // the step's displacement gradient with respect to the configuration
    // at the start of the step; their loads; and the cell sums of the
    // volumetric smoothing.
    using L                 = ParticleLayout<dim>;
    using Point             = typename Smoothing::Point;
    const bool small_strain = state.params.implicit.small_strain;
    stencils.begin_cell();
    points.clear();
    loads.clear();
    for (const auto &particle : pic)
      {
        const double *prop = particle.get_properties().data();
        if (!weights.evaluate(particle, true, error))
          return false;
        Point q;
        q.body           = static_cast<unsigned int>(prop[L::body]);
        const auto &body = state.bodies[q.body];
        PointLoads  load;
        body.body_force_on(particle.get_location(),
                           prop + L::X,
                           prop[L::mass],
                           t,
                           has_body_force[q.body],
                           load.body);
        double         S_face[Weights::n_entries];
        Tensor<1, dim> d_face;
        load.has_face =
          body.has_traction() && body.traction_force_on(particle.get_location(),
                                                        prop,
                                                        t,
                                                        load.traction,
                                                        d_face);
        if (load.has_face)
          weights.face_values(d_face, S_face);
        stencils.add(weights, load.has_face ? S_face : nullptr);
        loads.push_back(load);
        if (body.is_rigid())
          {
            // no strain, no stress: only its loads
            q.j     = 1;
            q.f     = unit_symmetric_tensor<dim>();
            q.f_inv = q.f;
            q.F     = q.f;
            q.V_n   = 0;
            points.push_back(q);
            continue;
          }
        const unsigned int  p     = stencils.n_particles() - 1;
        const unsigned int *nodes = stencils.nodes();
        for (unsigned int e = stencils.begin(p); e < stencils.end(p); ++e)
          for (unsigned int i = 0; i < dim; ++i)
            q.h[i] +=
              increment.local_element(nodes[stencils.node(e)] * dim + i) *
              stencils.gradient(e);
        q.f = unit_symmetric_tensor<dim>();
        // small strain: the strain increment sym(h), no rotation, and no
        // change of shape or volume (f = I exactly, so j = 1 and F = F_n)
        if (small_strain)
          q.h = symmetrize(q.h);
        else
          q.f += q.h;
        q.j = determinant(q.f);
        if (!(q.j > 0 && std::isfinite(q.j)))
          {
            std::ostringstream s;
            s << "the trial increment inverts particle " << particle.get_id()
              << " at (" << particle.get_location() << ") (det f = " << q.j
              << ")";
            error = s.str();
            return false;
          }
        q.f_inv = invert(q.f);
        q.F     = q.f * load_matrix<dim>(prop + L::F);
        q.V_n   = prop[L::volume];
        q.V0    = prop[L::volume0];
        points.push_back(q);
      }
    stencils.make_dense();
    smoothing->reset(stencils.n_nodes());
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        Point &q = points[p];
        q.G      = stencils.dense_gradients(p);
        if (smoothing->smooths(q.body) && !state.bodies[q.body].is_rigid())
          smoothing->add(q);
      }
    return true;
  }

  namespace
  {
    /// The material's stress change T : @p dh_eff (in-plane) for its
    /// tangent @p T = d sigma / d h.
    template <int dim>
    Tensor<2, dim>
    material_change(const Tensor<4, 3> &T, const Tensor<2, dim> &dh_eff)
    {
      Tensor<2, dim> ds;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int m = 0; m < dim; ++m)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              ds[i][m] += T[i][m][k][l] * dh_eff[k][l];
      return ds;
    }

    /**
     * The change of P = j sigma f^-T (in-plane) by a change @p dh of the
     * step's displacement gradient that changes the material's increment
     * by @p dh_eff (the same without volumetric smoothing): the geometric
     * terms from d j = j tr(f^-1 dh) and d f^-1 = -f^-1 dh f^-1, the
     * material's through its tangent @p T = d sigma / d h. In a @p fixed
     * geometry the force takes P = j sigma (no push-forward), and so does
     * its change. With @p small_strain the force is sigma on the initial
     * volume and the material sees sym(dh_eff): no geometric term.
     */
    template <int dim>
    Tensor<2, dim>
    first_piola_change(const Tensor<2, dim> &s,
                       const double          j,
                       const Tensor<2, dim> &f_inv,
                       const Tensor<4, 3>   &T,
                       const Tensor<2, dim> &dh,
                       const Tensor<2, dim> &dh_eff,
                       const bool            fixed,
                       const bool            small_strain)
    {
      if (small_strain)
        return material_change(T, Tensor<2, dim>(symmetrize(dh_eff)));
      const Tensor<2, dim> ds = material_change(T, dh_eff);
      if (fixed)
        return (j * trace(f_inv * dh)) * s + j * ds;
      const Tensor<2, dim> f_inv_T = transpose(f_inv);
      const Tensor<2, dim> d_f_inv = -f_inv * dh * f_inv;
      return (j * trace(f_inv * dh)) * s * f_inv_T + j * ds * f_inv_T +
             j * s * transpose(d_f_inv);
    }

    /// The change of the Kirchhoff stress tau = j sigma of the step (the
    /// in-plane part) by @p dh, with @p dh_eff, @p T and @p small_strain
    /// as above.
    template <int dim>
    SymmetricTensor<2, dim>
    kirchhoff_change(const Tensor<2, dim> &s,
                     const double          j,
                     const Tensor<2, dim> &f_inv,
                     const Tensor<4, 3>   &T,
                     const Tensor<2, dim> &dh,
                     const Tensor<2, dim> &dh_eff,
                     const bool            small_strain)
    {
      if (small_strain)
        return symmetrize(
          material_change(T, Tensor<2, dim>(symmetrize(dh_eff))));
      return symmetrize(j * trace(f_inv * dh) * s +
                        j * material_change(T, dh_eff));
    }

  } // namespace

  template <int dim>
  template <typename CellIterator, typename Particles>
  bool
  ImplicitIntegrator<dim>::add_cell_system(const CellIterator &cell,
                                           const Particles    &pic,
                                           const double        dt,
                                           const bool          with_matrix,
                                           std::string        &error)
  {
    using L                     = ParticleLayout<dim>;
    const unsigned int  n_nodes = stencils.n_nodes();
    const unsigned int *nodes   = stencils.nodes();
    const unsigned int  n       = n_nodes * dim;
    if (with_matrix)
      cell_matrix.reinit(n, n);
    cell_rhs.reinit(n);
    double *const f_int          = internal_force.begin();
    double *const f_ext          = external_force.begin();
    const bool    fixed_geometry = state.params.implicit.fixed_geometry;
    const bool    small_strain   = state.params.implicit.small_strain;
    materials::PointKinematics kinematics, tangent_kinematics;
    kinematics.dt         = dt;
    tangent_kinematics.dt = dt;
    unsigned int p        = 0;
    filtered_taus.assign(points.size(), SymmetricTensor<2, dim>());
    if (with_matrix && state.stress_filter->any())
      filtered_changes.assign(points.size() * n, SymmetricTensor<2, dim>());
    bool any_filtered = false;
    // the node average: the cell's rows of D
    const unsigned int *corners   = state.background.nodes(cell);
    const bool          node_rows = with_matrix && node_smoothing->any();
    bool                any_node  = false;
    double              N[Smoothing::nv];
    if (node_rows)
      node_smoothing->begin_cell(n_nodes);
    for (const auto &particle : pic)
      {
        const double *prop     = particle.get_properties().data();
        auto         &q        = points[p];
        const auto   &load     = loads[p];
        const auto   &body     = state.bodies[q.body];
        const auto   &material = *body.material;
        const bool    smoothed = smoothing->smooths(q.body);
        const bool    total    = material.stress_from_deformation_gradient();

        // What the material sees (as in the explicit stress update), and
        // the increment its tangent is the derivative by.
        Tensor<2, dim> h_rate = q.h, F = q.F, h_eff = q.h;
        if (smoothed)
          smoothing->material_increment(q, total, h_rate, F, h_eff);
        double J_bar = 0, theta_bar = 0, S = 0;
        bool   node_smoothed = false;
        if (node_smoothing->smooths(q.body))
          {
            state.background.geometry(cell).values(
              particle.get_reference_location(), N);
            node_smoothed =
              node_smoothing->averages(corners, N, J_bar, theta_bar, S);
          }
        if (node_smoothed)
          {
            Smoothing::smoothed_increment(
              q, total, J_bar, theta_bar, h_rate, F, h_eff);
          }
        kinematics.velocity_gradient         = embed<dim>(h_rate / dt, 0.);
        kinematics.F                         = embed<dim>(F, 1.);
        tangent_kinematics.velocity_gradient = embed<dim>(h_eff / dt, 0.);
        tangent_kinematics.F                 = kinematics.F;

        const SymmetricTensor<2, 3> stress_n = load_stress(prop + L::stress);
        SymmetricTensor<2, 3>       sigma    = stress_n;
        history_scratch.assign(prop + L::history,
                               prop + L::history + material.n_history());
        try
          {
            material.update_stress(kinematics,
                                   sigma,
                                   ArrayView<double>(history_scratch));
          }
        catch (const std::exception &e)
          {
            error = "the material of particle " +
                    std::to_string(particle.get_id()) + " failed: " + e.what();
            return false;
          }
        Tensor<2, dim> s; // in-plane Cauchy stress
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int k = 0; k < dim; ++k)
            s[i][k] = sigma[i][k];
        // A filtered body's force comes from the cell's projection of
        // its particles' tau = j sigma (add_filtered_force()).
        const bool filtered = state.stress_filter->filtered(q.body);
        any_filtered        = any_filtered || filtered;
        if (filtered)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int k = i; k < dim; ++k)
              filtered_taus[p][i][k] = q.j * s[i][k];
        // First Piola-Kirchhoff stress with respect to the start of the
        // step, P = j sigma f^-T: f_int,a = V_n P G_a. A fixed geometry
        // takes the Kirchhoff stress j sigma on the undeformed grid, so that
        // its equilibrium is that of the next step's start (f^-T = I + O(h)
        // there would leave each step out of balance by O(h) sigma).
        const Tensor<2, dim> P =
          fixed_geometry ? q.j * s : q.j * s * transpose(q.f_inv);
        for (unsigned int e = stencils.begin(p); e < stencils.end(p); ++e)
          {
            const unsigned int   a = stencils.node(e);
            const Tensor<1, dim> fa =
              filtered ? Tensor<1, dim>() : q.V_n * (P * stencils.gradient(e));
            for (unsigned int i = 0; i < dim; ++i)
              {
                const double ext = stencils.value(e) * load.body[i];
                cell_rhs(a * dim + i) += ext - fa[i];
                f_int[nodes[a] * dim + i] += fa[i];
                f_ext[nodes[a] * dim + i] += ext;
              }
          }
        if (load.has_face)
          for (unsigned int e = stencils.begin(p); e < stencils.end(p); ++e)
            for (unsigned int i = 0; i < dim; ++i)
              {
                const unsigned int a = stencils.node(e);
                const double       f = stencils.face(e) * load.traction[i];
                cell_rhs(a * dim + i) += f;
                f_ext[nodes[a] * dim + i] += f;
              }
        // (a rigid body adds no stiffness)
        if (!with_matrix || body.is_rigid())
          {
            ++p;
            continue;
          }

        // K_ai,bk = V_n (dP / du_bk) G_a. With smoothing, u_bk also
        // changes the other particles' share of the cell average, so
        // every node of the cell's list has a column.
        Tensor<4, 3> T;
        material.stress_tangent(tangent_kinematics,
                                stress_n,
                                ArrayView<const double>(prop + L::history,
                                                        material.n_history()),
                                T);
        if (node_smoothed)
          {
            // Particle p's force by its J_bar (total: d h_eff = alpha f /
            // (d J_bar) dJ_bar) or theta_bar (rate: I / d dtheta_bar), the
            // material's part of the stress change alone.
            Tensor<2, dim> by_average = unit_symmetric_tensor<dim>() / dim;
            if (total)
              by_average = q.alpha / (dim * J_bar) * q.f;
            const Tensor<2, dim> dP = first_piola_change(s,
                                                         q.j,
                                                         q.f_inv,
                                                         T,
                                                         Tensor<2, dim>(),
                                                         by_average,
                                                         fixed_geometry,
                                                         small_strain);
            node_force_derivative.assign(n, 0.);
            for (unsigned int e = stencils.begin(p); e < stencils.end(p); ++e)
              {
                const Tensor<1, dim> column =
                  q.V_n * (dP * stencils.gradient(e));
                for (unsigned int i = 0; i < dim; ++i)
                  node_force_derivative[stencils.node(e) * dim + i] +=
                    column[i];
              }
            node_smoothing->add_force_derivative(
              corners, N, S, total, node_force_derivative);
            any_node = true;
          }
        for (unsigned int b = 0; b < n_nodes; ++b)
          {
            if (!smoothed && !stencils.reaches(p, b))
              continue;
            for (unsigned int k = 0; k < dim; ++k)
              {
                Tensor<2, dim> dh;
                dh[k] = q.G[b];
                const Tensor<2, dim> dh_eff =
                  smoothed ?
                    smoothing->derivative(q, total, b, k) :
                    // (the nodal averages' change is the coupling part)
                    node_smoothed ?
                    Smoothing::increment_derivative(q, total, b, k, 0.) :
                    dh;
                if (filtered)
                  {
                    filtered_changes[p * n + b * dim + k] = kirchhoff_change(
                      s, q.j, q.f_inv, T, dh, dh_eff, small_strain);
                    continue;
                  }
                const Tensor<2, dim> dP = first_piola_change(
                  s, q.j, q.f_inv, T, dh, dh_eff, fixed_geometry, small_strain);
                for (unsigned int e = stencils.begin(p); e < stencils.end(p);
                     ++e)
                  {
                    const unsigned int   a = stencils.node(e);
                    const Tensor<1, dim> column =
                      q.V_n * (dP * stencils.gradient(e));
                    for (unsigned int i = 0; i < dim; ++i)
                      cell_matrix(a * dim + i, b * dim + k) += column[i];
                  }
              }
          }
        ++p;
      }
    if (any_filtered && !add_filtered_force(cell, pic, with_matrix, error))
      return false;
    system.node_indices(nodes, n_nodes, cell_dofs);
    if (any_node)
      node_smoothing->finish_force_cell(corners,
                                        cell_dofs,
                                        system.constraints());
    if (with_matrix && system.splits_cell_pressure())
      {
        // each split body's stiff volumetric part, lambda_s g b^T / V
        cell_pressures.clear();
        for (unsigned int b = 0; b < split_lambda.size(); ++b)
          if (split_lambda[b] > 0)
            {
              typename NodalLinearSystem<dim>::CellPressure q;
              const bool                                    total =
                state.bodies[b].material->stress_from_deformation_gradient();
              if (!smoothing->volume_gradient(
                    b, total, fixed_geometry, q.g, q.b, q.volume))
                continue;
              q.lambda       = split_lambda[b];
              q.rest_modulus = split_rest_modulus[b];
              cell_pressures.push_back(std::move(q));
            }
        system.add_cell(cell_matrix, cell_rhs, cell_dofs, cell_pressures);
      }
    else if (with_matrix)
      system.add_cell(cell_matrix, cell_rhs, cell_dofs);
    else
      system.add_cell_rhs(cell_rhs, cell_dofs);
    return true;
  }

  template <int dim>
  template <typename CellIterator, typename Particles>
  bool
  ImplicitIntegrator<dim>::add_filtered_force(const CellIterator &cell,
                                              const Particles    &pic,
                                              const bool          with_matrix,
                                              std::string        &error)
  {
    if constexpr (dim == 1)
      {
        (void)cell, (void)pic, (void)with_matrix, (void)error;
        return true;
      }
    else
      {
        // The explicit step's filtered force as a function of the trial
        // increment: the particles' tau = j sigma projected onto the
        // cell's assumed-stress field (weights and places of the start of
        // the step), and the field's force. Standard MPM integrates the
        // field over the particle domains of the start of the step
        // (IntegratedFieldForce); a domain family takes the field at each
        // particle with its stencil's gradients, V_p sigma*(xi_p) grad
        // S_ap (ProjectedStressForce). Either is linear in tau, so the
        // tangent's column is the same map of the columns' tau changes:
        // K = G^T H^-1 G_C, with G the field's work on the nodal motions,
        // H the projection's metric and G_C that of the material's stress
        // changes.
        using L                             = ParticleLayout<dim>;
        constexpr unsigned int nv           = shape_functions::n_q1<dim>;
        const auto            &grid         = state.background;
        const unsigned int    *nodes        = stencils.nodes();
        const unsigned int     n            = stencils.n_nodes() * dim;
        auto                  &filter       = *state.stress_filter;
        const auto            &geo          = grid.geometry(cell);
        const unsigned int    *corners      = grid.nodes(cell);
        const bool             per_particle = state.domain_functions != nullptr;
        // (the standard family: the cell's list is its vertices in order)
        if (!per_particle)
          for (unsigned int v = 0; v < nv; ++v)
            if (v >= stencils.n_nodes() || nodes[v] != corners[v])
              {
                error = "the assumed-stress filter of the implicit step "
                        "needs the cell's vertices as its node list";
                return false;
              }
        Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = 0.5;
        const Tensor<2, dim> J0 = geo.jacobian(centre);
        filter.begin_cell(J0);
        filtered_force.resize(per_particle ? n : nv * dim);
        double *const f = filtered_force.data();
        for (unsigned int b = 0; b < state.bodies.size(); ++b)
          {
            if (!filter.filtered(b))
              continue;
            // The body's particles in the cell, and whether they fill it
            // (AssumedStressForce::fills).
            unsigned int count = 0;
            double       V     = 0;
            unsigned int p     = 0;
            for (const auto &particle : pic)
              {
                if (points[p++].body == b)
                  {
                    ++count;
                    V += particle.get_properties()[L::volume];
                  }
              }
            if (count == 0)
              continue;
            const auto                       &projection = filter.projection(b);
            remedies::AssumedStressForce<dim> force;
            force.clear();
            if (!per_particle)
              {
                const bool fills = remedies::AssumedStressForce<dim>::fills(
                  count, V, std::abs(determinant(J0)));
                const Tensor<2, dim> J0_inverse = invert(J0);
                p                               = 0;
                for (const auto &particle : pic)
                  {
                    const double *prop = particle.get_properties().data();
                    if (points[p++].body != b)
                      continue;
                    force.add_particle(particle.get_reference_location(),
                                       fills ?
                                         Tensor<2, dim>(
                                           J0_inverse *
                                           load_matrix<dim>(prop + L::F) *
                                           load_matrix<dim>(prop + L::domain)) :
                                         Tensor<2, dim>(),
                                       prop[L::volume]);
                  }
              }
            // f = -(the field's internal force) of stresses tau(p)
            const auto field_force = [&](const auto &tau) {
              typename remedies::AssumedStressProjection<dim>::Moments sums;
              sums.clear();
              unsigned int q = 0;
              for (const auto &particle : pic)
                {
                  if (points[q].body == b)
                    projection.add(
                      sums,
                      particle.get_reference_location(),
                      filter.weight(b, particle.get_properties().data()),
                      tau(q));
                  ++q;
                }
              double beta[remedies::AssumedStressProjection<dim>::n_beta];
              std::fill(filtered_force.begin(), filtered_force.end(), 0.);
              if (projection.solve(sums, beta) ==
                  remedies::AssumedStressProjection<dim>::Result::unchanged)
                return;
              if (!per_particle)
                {
                  force.add_internal_force(geo, projection, beta, f);
                  return;
                }
              q = 0;
              for (const auto &particle : pic)
                {
                  if (points[q].body == b)
                    {
                      const Tensor<2, dim> sigma =
                        projection.field(particle.get_reference_location(),
                                         beta);
                      for (unsigned int e = stencils.begin(q);
                           e < stencils.end(q);
                           ++e)
                        {
                          const Tensor<1, dim> fa =
                            points[q].V_n * (sigma * stencils.gradient(e));
                          for (unsigned int i = 0; i < dim; ++i)
                            f[stencils.node(e) * dim + i] -= fa[i];
                        }
                    }
                  ++q;
                }
            };
            field_force([&](const unsigned int q) { return filtered_taus[q]; });
            double *const f_int = internal_force.begin();
            for (unsigned int r = 0; r < filtered_force.size(); ++r)
              {
                cell_rhs(r) += f[r];
                f_int[nodes[r / dim] * dim + r % dim] -= f[r];
              }
            if (!with_matrix)
              continue;
            for (unsigned int col = 0; col < n; ++col)
              {
                field_force([&](const unsigned int q) {
                  return filtered_changes[q * n + col];
                });
                for (unsigned int r = 0; r < filtered_force.size(); ++r)
                  cell_matrix(r, col) -= f[r];
              }
          }
        return true;
      }
  }

  template <int dim>
  bool
  ImplicitIntegrator<dim>::add_node_sums(const double t,
                                         const bool   with_matrix,
                                         std::string &error)
  {
    // The node average's first pass: every node-smoothed particle's trial
    // J and tr h to the nodes (and its row of C), before any particle's
    // stress can be updated.
    using L          = ParticleLayout<dim>;
    const auto &grid = state.background;
    node_smoothing->begin_assembly(with_matrix);
    double     N[Smoothing::nv];
    const bool ok =
      with_cell_weights([&](const auto &cell, const auto &pic, auto &weights) {
        if (!gather_cell(weights, pic, t, error))
          return false;
        const unsigned int *corners = grid.nodes(cell);
        const auto         &geo     = grid.geometry(cell);
        bool                any     = false;
        unsigned int        p       = 0;
        node_smoothing->begin_cell(stencils.n_nodes());
        for (const auto &particle : pic)
          {
            const auto &q = points[p++];
            if (!node_smoothing->smooths(q.body))
              continue;
            any = true;
            geo.values(particle.get_reference_location(), N);
            node_smoothing->add_state(corners,
                                      N,
                                      particle.get_properties()[L::mass],
                                      determinant(q.F),
                                      trace(q.h),
                                      with_matrix,
                                      transpose(q.f_inv),
                                      q.G);
          }
        if (any && with_matrix)
          {
            system.node_indices(stencils.nodes(),
                                stencils.n_nodes(),
                                cell_dofs);
            node_smoothing->finish_state_cell(corners,
                                              cell_dofs,
                                              system.constraints());
          }
        return true;
      });
    // (collective, whatever happened here)
    node_smoothing->finish_sums(with_matrix);
    return ok;
  }

  template <int dim>
  bool
  ImplicitIntegrator<dim>::assemble(const double t,
                                    const double dt,
                                    const bool   with_matrix,
                                    Residual    &residual,
                                    std::string &error)
  {
    TimerOutput::Scope timer(state.timer, "implicit assembly");
    system.begin_assembly(with_matrix);
    internal_force          = 0.;
    external_force          = 0.;
    const bool node_average = node_smoothing->any();
    bool       ok = !node_average || add_node_sums(t, with_matrix, error);
    ok            = ok && with_cell_weights(
                 [&](const auto &cell, const auto &pic, auto &weights) {
                   return gather_cell(weights, pic, t, error) &&
                          add_cell_system(cell, pic, dt, with_matrix, error);
                 });
    if (ok && ghost_penalty.enabled())
      {
        TimerOutput::Scope penalty_timer(state.timer, "ghost penalty");
        ghost_penalty.add_to_system(increment,
                                    with_matrix,
                                    system,
                                    internal_force);
      }
    const double inertia = with_inertia ? add_inertia(dt, with_matrix) : 0.;
    // Every rank takes part in the exchanges, whatever happened here.
    if (node_average && with_matrix)
      {
        node_smoothing->finish_matrix(node_coupling, node_coupling_rhs);
        system.finish_assembly(with_matrix,
                               node_coupling.get(),
                               &node_coupling_rhs);
      }
    else
      system.finish_assembly(with_matrix);
    internal_force.compress(VectorOperation::add);
    external_force.compress(VectorOperation::add);
    const bool all_ok = Utilities::MPI::min(ok ? 1 : 0, state.comm) == 1;
    if (!all_ok && error.empty())
      error = "a particle of another rank failed in the trial increment";
    residual.norm = system.rhs_norm();
    residual.reference =
      std::max({internal_force.l2_norm(),
                external_force.l2_norm(),
                std::sqrt(Utilities::MPI::sum(inertia, state.comm))});
    return all_ok;
  }

  template <int dim>
  double
  ImplicitIntegrator<dim>::deformable_mass(const unsigned int i) const
  {
    using P  = transfer::P2GLayout<dim>;
    double m = state.p2g.local_element(i * P::n_components + P::mass);
    const unsigned int n_r = rigid_bodies.size();
    for (unsigned int r = 0; r < n_r; ++r)
      m -= rigid_mass.local_element(i * n_r + r);
    return m;
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::prescribed_velocity(const unsigned int i,
                                               const double       t,
                                               double            *v) const
  {
    if (moves_with_boundary(i))
      boundary_velocity->value(state.background.node_position(i), t, v);
    else
      state.bodies[rigid_bodies[prescribed_by[i]]].prescribed_velocity.value(
        Point<dim>(), t, v);
  }

  template <int dim>
  bool
  ImplicitIntegrator<dim>::start_motion(const double t, const double dt)
  {
    // The nodes' velocity and mass are those of the deformable bodies: a
    // rigid body's particles move as prescribed, and its mass would
    // otherwise resist the free directions of the nodes it shares.
    using P                  = transfer::P2GLayout<dim>;
    const auto         &grid = state.background;
    const unsigned int  n_r  = rigid_bodies.size();
    std::vector<double> v_rigid(n_r * dim);
    for (unsigned int r = 0; r < n_r; ++r)
      state.bodies[rigid_bodies[r]].prescribed_velocity.value(
        Point<dim>(), t, &v_rigid[r * dim]);
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      {
        const double m = deformable_mass(i);
        for (unsigned int c = 0; c < dim; ++c)
          {
            double p =
              state.p2g.local_element(i * P::n_components + P::momentum + c);
            for (unsigned int r = 0; r < n_r; ++r)
              p -= rigid_mass.local_element(i * n_r + r) * v_rigid[r * dim + c];
            velocity_n.local_element(i * dim + c) =
              m > state.min_nodal_mass ? p / m : 0.;
          }
      }
    // a_n from the balance of the stresses, loads and damping at the
    // start (the increment is zero): what the particles carry needs no
    // acceleration of its own.
    Residual    r;
    std::string error;
    with_inertia = false;
    if (!assemble(t, dt, false, r, error))
      {
        state.local_error.record("Newmark: the start of the step at t = " +
                                 std::to_string(t) + ": " + error);
        return false;
      }
    with_inertia   = true;
    acceleration_n = 0.;
    for (unsigned int i = 0; i < grid.n_owned_nodes(); ++i)
      {
        const double m = deformable_mass(i);
        if (m > state.min_nodal_mass)
          for (unsigned int c = 0; c < dim; ++c)
            acceleration_n.local_element(i * dim + c) =
              (external_force.local_element(i * dim + c) -
               internal_force.local_element(i * dim + c)) /
                m -
              damping * velocity_n.local_element(i * dim + c);
      }
    acceleration_n.update_ghost_values();
    system.apply_homogeneous_constraints(grid, velocity_n);
    system.apply_homogeneous_constraints(grid, acceleration_n);
    // The prescribed directions of a moving boundary's or a rigid body's
    // nodes start from its velocity, and from the acceleration that its
    // midpoint velocity implies, so that Newmark's v_n+1 of the
    // prescribed increment is its velocity at the end.
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      if (prescribed[i])
        {
          double v[dim], v_mid[dim];
          prescribed_velocity(i, t, v);
          prescribed_velocity(i, t + dt / 2, v_mid);
          for (unsigned int c = 0; c < dim; ++c)
            if (prescribed[i] & (1u << c))
              {
                velocity_n.local_element(i * dim + c) = v[c];
                acceleration_n.local_element(i * dim + c) =
                  2 * (v_mid[c] - v[c]) / dt;
              }
        }
    return true;
  }

  template <int dim>
  double
  ImplicitIntegrator<dim>::add_inertia(const double dt, const bool with_matrix)
  {
    // The lumped mass's force m (a_n+1 + c v_n+1) and its derivative
    // m (1 / (beta dt^2) + c gamma / (beta dt)) by the increment, on the
    // owned nodes (each once).
    const double stiffness =
      1 / (beta * dt * dt) + damping * gamma / (beta * dt);
    double             norm2 = 0;
    unsigned int       node[1];
    FullMatrix<double> matrix(dim, dim);
    Vector<double>     rhs(dim);
    for (unsigned int i = 0; i < state.background.n_owned_nodes(); ++i)
      {
        if (!active[i])
          continue;
        const double m = deformable_mass(i);
        for (unsigned int c = 0; c < dim; ++c)
          {
            const unsigned int k = i * dim + c;
            const double       v =
              velocity_n.local_element(k) + velocity_change(k, dt);
            const double f = m * (new_acceleration(k, dt) + damping * v);
            rhs(c)         = -f;
            matrix(c, c)   = m * stiffness;
            norm2 += f * f;
          }
        node[0] = i;
        system.node_indices(node, 1, cell_dofs);
        if (with_matrix)
          system.add_cell(matrix, rhs, cell_dofs);
        else
          system.add_cell_rhs(rhs, cell_dofs);
      }
    return norm2;
  }

  template <int dim>
  void
  ImplicitIntegrator<dim>::commit(const double t, const double dt)
  {
    // The converged increment as a grid velocity u / dt: the explicit
    // stress update then gives F = (I + h) F_n and the material's stress
    // of exactly the converged state, and G2P moves the particles by
    // sum_a N_a u_a. Their velocity changes by the kinematics vector's
    // increment: Newmark's v_n+1 - v_n (FLIP), nothing when quasi-static.
    using K          = KinematicsLayout<dim>;
    const auto &grid = state.background;
    for (unsigned int i = 0; i < grid.n_local_nodes(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        {
          const unsigned int k              = i * dim + c;
          state.kinematics.local_element(i * K::n_components + K::velocity +
                                         c) = increment.local_element(k) / dt;
          state.kinematics.local_element(i * K::n_components + K::increment +
                                         c) =
            dynamic ? velocity_change(k, dt) : 0.;
        }
    // A rigid body moves as prescribed, not with the grid; with a fixed
    // geometry no particle moves.
    using L          = ParticleLayout<dim>;
    const bool fixed = state.params.implicit.fixed_geometry;
    const auto rigid = [&](const auto &p) {
      return state
        .bodies[static_cast<unsigned int>(p.get_properties()[L::body])]
        .is_rigid();
    };
    std::vector<Point<dim>> start;
    if (fixed || !rigid_bodies.empty())
      for (const auto &p : state.particle_handler)
        if (fixed || rigid(p))
          start.push_back(p.get_location());
    // G2P and the stress update see the domains of the start of the step
    // (the stress update changes F, from which cpGIMP and CPDI take them).
    {
      TimerOutput::Scope timer(state.timer, "G2P");
      state.local_error.record(
        transfer::grid_to_particle(transfer::G2PContext<dim>{
          {grid, state.particle_handler, state.domain_functions.get(), 0},
          state.kinematics,
          dt,
          1.,
          nullptr}));
    }
    state.update_particle_stress(dt);
    // A filtered body keeps the field that made the converged force, as
    // the explicit step's projection writes it back (the cells and places
    // are still those of the start of the step).
    if (state.stress_filter->any())
      {
        TimerOutput::Scope timer(state.timer, "stress filter");
        state.stress_filter->apply(grid, state.particle_handler);
      }
    if (fixed || !rigid_bodies.empty())
      {
        std::vector<Tensor<1, dim>> u(state.bodies.size());
        for (unsigned int r = 0; r < rigid_bodies.size(); ++r)
          u[rigid_bodies[r]] = rigid_displacement(r, t, dt);
        unsigned int k = 0;
        for (auto &p : state.particle_handler)
          {
            if (!fixed && !rigid(p))
              continue;
            double            *prop = p.get_properties().data();
            const unsigned int b    = static_cast<unsigned int>(prop[L::body]);
            p.set_location(fixed ? start[k++] : start[k++] + u[b]);
            if (!state.bodies[b].is_rigid())
              continue;
            // (Newmark: the velocity at the end of the step, which the
            // next step's nodal momentum takes out again)
            double v_end[dim];
            if (dynamic)
              state.bodies[b].prescribed_velocity.value(Point<dim>(),
                                                        t + dt,
                                                        v_end);
            for (unsigned int c = 0; c < dim; ++c)
              prop[L::velocity + c] = dynamic ? v_end[c] : u[b][c] / dt;
          }
      }
    // (a fixed geometry is back where the step started: nothing to move
    // or relocate)
    if (fixed)
      return;
    TimerOutput::Scope timer(state.timer, "position update");
    if (shape_functions::family_traits(state.params.shape_functions.family)
          .tracks_corners)
      state.local_error.record(
        transfer::move_domain_corners(grid,
                                      state.particle_handler,
                                      state.kinematics,
                                      dt,
                                      *state.domain_functions));
    state.relocate_moved_particles();
  }

  template class ImplicitIntegrator<1>;
  template class ImplicitIntegrator<2>;
  template class ImplicitIntegrator<3>;
} // namespace mpm
