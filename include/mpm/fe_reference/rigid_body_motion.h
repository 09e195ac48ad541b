#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/numerics/vector_tools.h>

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
        if (c >= dim)
          return 0;
        if (k < dim)
          return c == k ? 1. : 0.;
        // rotation about axis a: e_a x x
        const unsigned int   a = dim == 2 ? 2 : k - dim;
        dealii::Tensor<1, 3> x3, axis;
        for (unsigned int d = 0; d < dim; ++d)
          x3[d] = x[d];
        axis[a] = 1;
        return dealii::cross_product_3d(axis, x3)[c];
      }

    private:
      const unsigned int k;
    };

    /// The static problem's message when constraints_admit_rigid_motion().
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
      const unsigned int      n_rigid = dim * (dim + 1) / 2;
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

    /// Whether some rigid-body motion satisfies every constraint (then K
    /// is singular and statics has no unique solution).
    template <int dim, typename VectorType>
    bool
    constraints_admit_rigid_motion(
      const dealii::Mapping<dim>              &mapping,
      const dealii::DoFHandler<dim>           &dofs,
      const dealii::AffineConstraints<double> &constraints,
      const VectorType                        &prototype)
    {
      return n_admissible_rigid_motions(mapping, dofs, constraints, prototype) >
             0;
    }
  } // namespace fe_reference
} // namespace mpm
