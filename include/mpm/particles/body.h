#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <mpm/materials/material.h>
#include <mpm/parameters/parameters.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/utilities/expression.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * A body at run time: its material and the expressions for its initial
   * state and loads. Loads are functions of the current position x, the
   * material coordinate X and time.
   */
  template <int dim>
  struct Body
  {
    unsigned int                         index = 0;
    Parameters::Body<dim>                prm;
    std::unique_ptr<materials::Material> material;
    Expression<dim>                      initial_velocity;
    Expression<dim>                      initial_stress;
    Expression<2 * dim>                  body_force;
    Expression<2 * dim>                  traction;
    /// of t (at the origin); only for a rigid body
    Expression<dim> prescribed_velocity;

    /// Whether the body moves as prescribed (Material/Model = rigid).
    bool
    is_rigid() const
    {
      return !prm.prescribed_velocity.empty();
    }

    /// Evaluate b(x, X, t) per unit mass.
    void
    body_force_at(const dealii::Point<dim> &x,
                  const double             *X,
                  const double              t,
                  double                   *out) const
    {
      if (body_force.is_constant())
        return body_force.value({}, t, out);
      dealii::Point<2 * dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        {
          p[d]       = x[d];
          p[dim + d] = X[d];
        }
      body_force.value(p, t, out);
    }

    /// Evaluate the traction t(x, X, t).
    void
    traction_at(const dealii::Point<dim> &x,
                const double             *X,
                const double              t,
                double                   *out) const
    {
      if (traction.is_constant())
        return traction.value({}, t, out);
      dealii::Point<2 * dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        {
          p[d]       = x[d];
          p[dim + d] = X[d];
        }
      traction.value(p, t, out);
    }

    bool
    has_body_force() const;

    /// Whether some of the body's particles carry a traction.
    bool
    has_traction() const
    {
      return !prm.traction_boundary_ids.empty();
    }

    /// Where the traction of a particle acts: prop[face_offset_slot] holds
    /// the offset X_face - X_p of its loaded face's centroid in the
    /// reference configuration (ParticleLayout::traction_offset(); 0: none
    /// stored, the traction acts at the particle).
    unsigned int face_offset_slot = 0;

    /// The body force m b(x, X, t) on a particle (@p loaded:
    /// has_body_force(), cached by the caller).
    void
    body_force_on(const dealii::Point<dim> &x,
                  const double             *X,
                  const double              mass,
                  const double              t,
                  const bool                loaded,
                  double                   *out) const
    {
      for (unsigned int d = 0; d < dim; ++d)
        out[d] = 0;
      if (loaded)
        {
          body_force_at(x, X, t, out);
          for (unsigned int d = 0; d < dim; ++d)
            out[d] *= mass;
        }
    }

    /// The traction force A t on the loaded face a particle carries
    /// (@p prop: its properties), evaluated at the face, and the face's
    /// current offset from the particle, d = F (X_face - X_p). The caller
    /// spreads the force as a force at x + d, not at the particle, which
    /// would shorten its lever arm by half a particle spacing. Returns
    /// false, with out = 0, for a particle without a loaded face.
    bool
    traction_force_on(const dealii::Point<dim> &x,
                      const double             *prop,
                      const double              t,
                      double                   *out,
                      dealii::Tensor<1, dim>   &d) const
    {
      using L           = ParticleLayout<dim>;
      const double area = prop[L::traction_area];
      d                 = dealii::Tensor<1, dim>();
      if (!(area > 0))
        {
          for (unsigned int k = 0; k < dim; ++k)
            out[k] = 0;
          return false;
        }
      dealii::Point<dim> x_face = x;
      double             X_face[dim];
      for (unsigned int i = 0; i < dim; ++i)
        X_face[i] = prop[L::X + i];
      if (face_offset_slot > 0)
        {
          const double *D = prop + face_offset_slot;
          for (unsigned int i = 0; i < dim; ++i)
            {
              X_face[i] += D[i];
              for (unsigned int j = 0; j < dim; ++j)
                d[i] += prop[L::F + i * dim + j] * D[j];
            }
          x_face += d;
        }
      traction_at(x_face, X_face, t, out);
      for (unsigned int k = 0; k < dim; ++k)
        out[k] *= area;
      return true;
    }
  };

  /// Variable names of the spatial coordinates ("x,y") and with the
  /// material coordinates ("x,y,X,Y").
  std::string
  spatial_variables(const int dim);
  std::string
  load_variables(const int dim);

  /// The particle domain a body-mesh sub-cell gives: centre, volume, the
  /// half-vectors of its parallelogram approximation and the area of the
  /// body boundary it carries traction on.
  template <int dim>
  struct ParticleSeed
  {
    dealii::Point<dim>     position;
    double                 volume = 0;
    dealii::Tensor<2, dim> domain; // column i = half-vector r_i
    /// The sub-cell's vertices (deal.II order), for CPDI2.
    std::array<dealii::Point<dim>, (1u << dim)> corners;
    double                                      traction_area = 0;
    /// Centroid of the loaded face part less the position (reference).
    dealii::Tensor<1, dim> traction_offset;
  };

  /// Build the body mesh (box, ball or file) on every rank.
  template <int dim>
  void
  create_body_mesh(dealii::Triangulation<dim>  &body_mesh,
                   const Parameters::Body<dim> &prm,
                   const std::string           &input_folder,
                   const std::string           &where);

  /**
   * Split body cells into n^dim sub-cells (in the cell's reference
   * coordinates) and return one seed per sub-cell, for the cells with
   * index in [first_cell, end_cell) (so that set-up can go in chunks).
   * seed_ids receive cell_index * n^dim + sub-cell index.
   */
  template <int dim>
  void
  split_body_cells(const dealii::Triangulation<dim>              &body_mesh,
                   const unsigned int                             n,
                   const std::vector<dealii::types::boundary_id> &traction_ids,
                   const unsigned int                             first_cell,
                   const unsigned int                             end_cell,
                   std::vector<ParticleSeed<dim>>                &seeds,
                   std::vector<unsigned long long>               &seed_ids);

  /**
   * Only the positions of the seeds split_body_cells() gives for the same
   * cells (appended to @p positions, the same values and order): enough to
   * count the particles a rank owns, at a fraction of the cost.
   */
  template <int dim>
  void
  split_body_cell_positions(const dealii::Triangulation<dim> &body_mesh,
                            const unsigned int                n,
                            const unsigned int                first_cell,
                            const unsigned int                end_cell,
                            std::vector<dealii::Point<dim>>  &positions);
} // namespace mpm
