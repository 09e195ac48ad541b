#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * How a model of dimension 1 or 2 is embedded in three-dimensional
   * continuum mechanics. Materials always see 3x3 tensors; this tells them
   * which out-of-plane components are constrained and which are free.
   */
  enum class KinematicAssumption
  {
    three_dimensional, ///< 3D models
    plane_strain,      ///< 2D: eps_zz = 0, sigma_zz follows
    plane_stress,      ///< 2D: sigma_zz = 0, eps_zz follows
    uniaxial_strain,   ///< 1D: only eps_xx, lateral stresses follow
    uniaxial_stress    ///< 1D: only sigma_xx (a thin bar)
  };

  std::string
  to_string(const KinematicAssumption k);

  namespace materials
  {
    using dealii::ArrayView;
    using dealii::SymmetricTensor;
    using dealii::Tensor;

    /**
     * Kinematics of one material point over one explicit step, embedded in
     * 3D: rows and columns of out-of-plane directions of L are zero, and
     * the out-of-plane diagonal of F is one.
     */
    struct PointKinematics
    {
      Tensor<2, 3> velocity_gradient; ///< L = grad v (current configuration)
      Tensor<2, 3> F;                 ///< deformation gradient, end of step
      double       dt = 0;            ///< step length

      /// f^-1 of the step's deformation f = I + dt L, for the tangents'
      /// geometric terms (dJ = J tr(f^-1 dh)).
      Tensor<2, 3>
      step_inverse() const
      {
        return dealii::invert(Tensor<2, 3>(dealii::unit_symmetric_tensor<3>()) +
                              dt * velocity_gradient);
      }
    };

    /**
     * A constitutive model. The solver calls update_stress() once per
     * particle and step; everything else is for statistics and the time
     * step. Implementations are stateless: per-particle internal variables
     * live in the particle's history slots.
     */
    class Material
    {
    public:
      virtual ~Material() = default;

      /// Name as written in the parameter file.
      virtual std::string
      name() const = 0;

      /// Whether the model is implemented for this embedding.
      virtual bool
      supports(const KinematicAssumption k) const = 0;

      /// Read the model's own subsection (prm is already inside it).
      virtual void
      parse_parameters(dealii::ParameterHandler &prm) = 0;

      /// Number of per-particle history variables.
      virtual unsigned int
      n_history() const
      {
        return 0;
      }

      /// Names of the history variables, for output.
      virtual std::vector<std::string>
      history_names() const
      {
        return {};
      }

      /// Advance the Cauchy stress over one step.
      virtual void
      update_stress(const PointKinematics   &kinematics,
                    SymmetricTensor<2, 3>   &stress,
                    const ArrayView<double> &history) const = 0;

      /**
       * The tangent of update_stress() for the implicit integrators:
       * tangent[i][j][k][l] = d sigma_ij / d h_kl, with h = dt L the
       * step's displacement gradient (with respect to the configuration at
       * the start of the step), at the kinematics given and from the stress
       * @p stress_n and history @p history_n at the start of the step (the
       * inputs of update_stress()). Only the components of h that the
       * kinematic assumption lets vary are used. False: the model has no
       * tangent, and the implicit integrators refuse it.
       */
      virtual bool
      stress_tangent(const PointKinematics         &kinematics,
                     const SymmetricTensor<2, 3>   &stress_n,
                     const ArrayView<const double> &history_n,
                     Tensor<4, 3>                  &tangent) const
      {
        (void)kinematics;
        (void)stress_n;
        (void)history_n;
        (void)tangent;
        return false;
      }

      /// Whether the stress derives from a stored energy of F (hyperelastic):
      /// the implicit stiffness is then symmetric, and CG solves with it.
      virtual bool
      has_symmetric_tangent() const
      {
        return false;
      }

      /**
       * Whether the stress is a function of F (hyperelastic models, an
       * equation of state) rather than integrated from the rate L. The
       * implicit step linearizes `Volumetric smoothing` accordingly: as
       * F-bar for these, as a B-bar of the rate for the others.
       */
      virtual bool
      stress_from_deformation_gradient() const
      {
        return false;
      }

      /**
       * Whether the model reads a symmetric displacement gradient of the
       * step, h = dt L, as the strain increment h itself, without turning
       * the stress: the linearized kinematics of `Implicit
       * solver/Geometry = small strain`.
       */
      virtual bool
      small_strain_increment() const
      {
        return false;
      }

      /// Stored strain energy per unit reference volume.
      virtual double
      strain_energy_density(const SymmetricTensor<2, 3>   &stress,
                            const Tensor<2, 3>            &F,
                            const ArrayView<const double> &history) const = 0;

      /// Largest wave speed of the current state (for the CFL condition).
      virtual double
      wave_speed(const Tensor<2, 3> &F) const = 0;

      /**
       * Small-strain isotropic moduli, if the model has them: the
       * compliance metric of the assumed-stress filter needs them.
       */
      virtual bool
      elastic_moduli(double &youngs_modulus, double &poissons_ratio) const
      {
        (void)youngs_modulus;
        (void)poissons_ratio;
        return false;
      }

      /**
       * Make a stress that a filter has replaced consistent with the
       * internal variables (the assumed-stress filter calls it for every
       * stress it writes). Elastic models need nothing: their stress is
       * their state. Plastic models return it to the elastic domain,
       * with the plastic flow that implies. @p stress is the full 3x3
       * Cauchy stress.
       */
      virtual void
      make_admissible(SymmetricTensor<2, 3>   &stress,
                      const ArrayView<double> &history) const
      {
        (void)stress;
        (void)history;
      }

      /**
       * The volume ratio J = det F at which the model's own stress has
       * the pressure of the initial stress @p stress (-tr/3). Models that
       * compute the stress from F alone and would otherwise overwrite an
       * `Initial stress` at the first update (the fluid's equation of
       * state) return it, and the particle starts with the isotropic F of
       * that J, so the initial pressure persists. 1 (the default): the
       * model keeps the initial stress itself, or ignores it. NaN if no
       * such J exists (set-up reports a non-finite initial state).
       */
      virtual double
      initial_jacobian(const SymmetricTensor<2, 3> &stress) const
      {
        (void)stress;
        return 1.;
      }

      /**
       * Whether the model's whole state is its volume ratio J (a fluid:
       * the equation of state sees nothing else). With `Volumetric
       * smoothing` such a particle then takes the smoothed J as its own
       * (its F is scaled to it), instead of only computing its stress from
       * it: a particle that kept its own J would carry a volume no
       * pressure ever acted on into the next cell's average, and in the
       * water column that grows into a cell-to-cell checkerboard that
       * stops the run (doc/benchmarks/water_column.md,
       * doc/theory/volumetric_smoothing.md).
       */
      virtual bool
      state_is_volume_ratio() const
      {
        return false;
      }

      /// Whether the model resists a shear at rest. A fluid does not: its
      /// only shear stress is viscous, so a quasi-static step (no
      /// inertia) has no equilibrium to find for it.
      virtual bool
      has_static_shear_stiffness() const
      {
        return true;
      }

      /// Reference mass density rho_0.
      double
      reference_density() const
      {
        return density;
      }

      KinematicAssumption
      kinematic_assumption() const
      {
        return kinematics;
      }

      /// Called by the factory before parse_parameters().
      void
      set_common(const double rho0, const KinematicAssumption k)
      {
        density    = rho0;
        kinematics = k;
      }

    protected:
      double              density    = 1.0;
      KinematicAssumption kinematics = KinematicAssumption::three_dimensional;
    };

    /**
     * Registry of material models. A model registers itself once with
     * MPM_REGISTER_MATERIAL in its source file; the parameter file chooses
     * it by name in `subsection Material / set Model = ...`.
     */
    struct MaterialEntry
    {
      std::string                                     name;
      std::string                                     description;
      std::function<void(dealii::ParameterHandler &)> declare_parameters;
      std::function<std::unique_ptr<Material>()>      create;
    };

    /// Add a model to the registry (called at static initialisation).
    bool
    register_material(const MaterialEntry &entry);

    /// All registered models, sorted by name.
    std::vector<MaterialEntry>
    registered_materials();

    /**
     * Declare `Model`, `Density` and one subsection per registered model in
     * the current subsection of @p prm.
     */
    void
    declare_material_parameters(dealii::ParameterHandler &prm);

    /**
     * Create the model chosen in the current subsection of @p prm and parse
     * its parameters. Throws mpm::InputError naming @p where if the model
     * does not support the kinematic assumption.
     */
    std::unique_ptr<Material>
    create_material(dealii::ParameterHandler &prm,
                    const KinematicAssumption k,
                    const std::string        &where);

    /// The section name used for a model in the parameter file.
    std::string
    subsection_name(const std::string &model_name);
  } // namespace materials
} // namespace mpm

#define MPM_REGISTER_MATERIAL(classname, model_name, model_description)    \
  namespace                                                                \
  {                                                                        \
    const bool registered_##classname = mpm::materials::register_material( \
      {model_name,                                                         \
       model_description,                                                  \
       &classname::declare_parameters,                                     \
       []() -> std::unique_ptr<mpm::materials::Material> {                 \
         return std::make_unique<classname>();                             \
       }});                                                                \
  }
