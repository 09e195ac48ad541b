#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <mpm/grid/background_grid.h>
#include <mpm/integrators/nodal_linear_system.h>
#include <mpm/particles/body.h>

#include <vector>

namespace mpm
{
  /**
   * The ghost penalty of the implicit step (`Implicit solver/Ghost
   * penalty`, doc/theory/implicit.md): the form
   *   g(u, w) = beta E h int_F [[du/dn]] . [[dw/dn]] ds
   * on the faces F between two cells whose nodes are all unknowns, where
   * one of the two has a node covered by less than a quarter of its
   * support (sum_p S_ap V_p < int N_a / 4). u is the step's nodal
   * increment, [[.]] the jump across the face, E the bodies' largest
   * Young's modulus and h = |cell|^(1/d), the mean of the two cells. It
   * adds to the residual and tangent what a cut-cell finite element adds
   * to hold the nodes of cells that the body barely covers, whose
   * stiffness is of the order of the few particles that reach them.
   *
   * Each face is assembled once over the ranks: an owned-owned face by
   * its cell of lower active index, a face to a ghost cell by the rank of
   * the lower subdomain. The faces are integrated with 2^(d-1) Gauss
   * points on any Q1 cell (the normal and measure by Nanson's formula,
   * the point in the neighbour by its inverse map).
   */
  template <int dim>
  class GhostPenalty
  {
  public:
    /// The form's factor beta E (0: off).
    explicit GhostPenalty(const double scale = 0)
      : scale(scale)
    {}

    /// E of the form: the largest Young's modulus of the deformable
    /// bodies; InputError if none has one.
    static double
    youngs_modulus(const std::vector<Body<dim>> &bodies);

    bool
    enabled() const
    {
      return scale > 0;
    }

    /// The faces this rank may assemble on the grid's current partition
    /// (again after every repartition).
    void
    reinit(const BackgroundGrid<dim> &grid);

    /// The nodes of the two cells of every face this rank may assemble:
    /// the couplings the sparsity needs (on top of the cells').
    typename NodalLinearSystem<dim>::NodeGroups
    couplings(const BackgroundGrid<dim> &grid) const;

    /// This step's faces from the unknowns @p active (per node-local
    /// index) and the covered @p support and @p full_support (int N_a)
    /// of each node (ghost values up to date), with their matrices: the
    /// grid does not move during a step, so every assembly of the step
    /// uses them.
    void
    select_faces(const BackgroundGrid<dim> &grid,
                 const std::vector<char>   &active,
                 const NodalVector         &support,
                 const NodalVector         &full_support);

    /// Every face this rank may assemble, with its matrix (tests).
    void
    select_all_faces(const BackgroundGrid<dim> &grid);

    /// Faces selected on this rank.
    unsigned int
    n_faces() const
    {
      return faces.size();
    }

    /// Add the form's force G u (to @p internal_force, and its negative
    /// to the right-hand side) and, if @p with_matrix, its matrix G, for
    /// the increment @p u (dim components per node, ghosts up to date).
    void
    add_to_system(const NodalVector      &u,
                  const bool              with_matrix,
                  NodalLinearSystem<dim> &system,
                  NodalVector            &internal_force) const;

    /// g(u, w) over the selected faces of every rank (collective).
    double
    form(const NodalVector &u, const NodalVector &w, const MPI_Comm comm) const;

  private:
    /// An owned cell and the face (deal.II order) to its neighbour.
    struct Face
    {
      unsigned int cell, face, neighbor;
    };

    /// A selected face's nodes (the cell's vertices, then the
    /// neighbour's others) and the scalar matrix M of g on them (the
    /// vector form is M (x) I).
    struct FaceMatrix
    {
      std::vector<unsigned int>  nodes;
      dealii::FullMatrix<double> M;
    };

    FaceMatrix
    face_matrix(const BackgroundGrid<dim> &grid, const Face &face) const;

    double                  scale = 0;  ///< beta E
    std::vector<Face>       candidates; ///< that this rank assembles
    std::vector<FaceMatrix> faces;      ///< this step's
  };
} // namespace mpm
