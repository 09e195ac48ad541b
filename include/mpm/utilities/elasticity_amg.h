#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Epetra_MultiVector.h>

namespace mpm
{
  /// Number of rigid-body modes: translations, then rotations.
  template <int dim>
  constexpr unsigned int n_rigid_body_modes = dim == 1 ? 1 :
                                              dim == 2 ? 3 :
                                                         6;

  /**
   * Component @p c of rigid-body mode @p k at the position @p r: the
   * translations along x, y(, z) first, then the rotations e_a x r about
   * z (2D), or about x, y and z (3D).
   */
  template <int dim>
  double
  rigid_body_mode(const unsigned int            k,
                  const unsigned int            c,
                  const dealii::Tensor<1, dim> &r)
  {
    if (k < dim)
      return k == c ? 1. : 0.;
    const unsigned int   a = dim == 2 ? 2 : k - dim; // rotation axis
    dealii::Tensor<1, 3> r3, axis;
    for (unsigned int d = 0; d < dim; ++d)
      r3[d] = r[d];
    axis[a] = 1;
    return dealii::cross_product_3d(axis, r3)[c];
  }

  /**
   * ML for an elasticity matrix with @p modes (the rigid-body modes of its
   * rows, n_rigid_body_modes columns) as near-null space: the aggregates
   * then carry the elastic energy's kernel, and the iteration count stays
   * nearly constant under refinement. @p pde_equations consecutive rows
   * form one node (1 if the numbering does not interleave components);
   * @p higher_order for elements above Q1. @p modes must outlive @p amg's
   * set-up.
   */
  void
  initialize_elasticity_amg(dealii::TrilinosWrappers::PreconditionAMG    &amg,
                            const dealii::TrilinosWrappers::SparseMatrix &A,
                            Epetra_MultiVector                           &modes,
                            const int  pde_equations,
                            const bool higher_order);
} // namespace mpm
