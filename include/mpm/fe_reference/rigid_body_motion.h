#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/numerics/vector_tools.h>

#include <mpm/utilities/elasticity_amg.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace mpm
{
  namespace fe_reference
  {
    /// Rigid-body motion k: translations along x, y(, z), then rotations
    /// about z (2D), or about x, y, z (3D); zero pressure.
    template <int dim>
    class RigidMotion : public dealii::Function<dim>
    {
    public:
      RigidMotion(const unsigned int k, const unsigned int n_components)
        : dealii::Function<dim>(n_components)
        , k(k)
      {}

      double
      value(const dealii::Point<dim> &x, const unsigned int c) const override
      {
        return c < dim ? rigid_body_mode<dim>(k, c, x) : 0.;
      }

    private:
      const unsigned int k;
    };

    /// The static problem's message when n_admissible_rigid_motions() > 0.
    inline constexpr const char *free_body_message =
      "Boundary conditions: the clamped, slip and prescribed boundaries "
      "leave a rigid-body motion free, so the static problem has no "
      "unique solution (clamp a boundary, or add slip boundaries that "
      "hold every translation and rotation)";

    /**
     * How many independent rigid-body motions satisfy every (homogeneous)
     * constraint: the dimension of K's kernel. A motion r is admissible if
     * distribute() leaves it unchanged; the admissible combinations are the
     * null space of the violations V = [r_k - distribute(r_k)], counted
     * through the eigenvalues of the Gram matrix V^T V. @p prototype gives
     * the vector layout (serial, or distributed without ghosts).
     */
    template <int dim, typename VectorType>
    unsigned int
    n_admissible_rigid_motions(
      const dealii::Mapping<dim>              &mapping,
      const dealii::DoFHandler<dim>           &dofs,
      const dealii::AffineConstraints<double> &constraints,
      const VectorType                        &prototype)
    {
      const unsigned int      n_rigid = n_rigid_body_modes<dim>;
      std::vector<VectorType> violation;
      for (unsigned int k = 0; k < n_rigid; ++k)
        {
          VectorType r(prototype);
          dealii::VectorTools::interpolate(
            mapping,
            dofs,
            RigidMotion<dim>(k, dofs.get_fe().n_components()),
            r);
          r /= r.l2_norm();
          VectorType v(r);
          constraints.distribute(v);
          v -= r;
          violation.push_back(v);
        }
      dealii::LAPACKFullMatrix<double> gram(n_rigid, n_rigid);
      for (unsigned int k = 0; k < n_rigid; ++k)
        for (unsigned int l = 0; l < n_rigid; ++l)
          gram(k, l) = violation[k] * violation[l];
      gram.compute_eigenvalues();
      unsigned int n_admissible = 0;
      for (unsigned int k = 0; k < n_rigid; ++k)
        if (std::abs(gram.eigenvalue(k)) < 1e-12)
          ++n_admissible;
      return n_admissible;
    }

  } // namespace fe_reference
} // namespace mpm
