#include <mpm/utilities/elasticity_amg.h>

#include <memory>

#include <Teuchos_ParameterList.hpp>

namespace mpm
{
  void
  initialize_elasticity_amg(dealii::TrilinosWrappers::PreconditionAMG    &amg,
                            const dealii::TrilinosWrappers::SparseMatrix &A,
                            Epetra_MultiVector                           &modes,
                            const int  pde_equations,
                            const bool higher_order)
  {
    dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = higher_order;
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = 1e-4;
    Teuchos::ParameterList              ml;
    std::unique_ptr<Epetra_MultiVector> unused;
    data.set_parameters(ml, unused, A);
    ml.set("PDE equations", pde_equations);
    ml.set("null space: type", "pre-computed");
    ml.set("null space: dimension", modes.NumVectors());
    ml.set("null space: vectors", modes.Values());
    amg.initialize(A, ml);
  }
} // namespace mpm
