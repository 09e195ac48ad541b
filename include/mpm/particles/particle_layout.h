#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/numerics/data_component_interpretation.h>

#include <string>
#include <vector>

namespace mpm
{
  /**
   * Where each particle quantity lives in the property array that
   * Particles::ParticleHandler stores per particle. The offsets are
   * compile-time constants for each dimension so that hot loops index
   * directly; only the material history slots at the end vary at run time
   * (their number is the largest any body's material needs).
   *
   * | slot          | size        | meaning                                  |
   * |---------------|-------------|------------------------------------------|
   * | mass          | 1           | m_p [kg] (per unit thickness in 2D)      |
   * | volume0       | 1           | reference volume V0_p                    |
   * | volume        | 1           | current volume V_p = det(F) V0_p         |
   * | body          | 1           | body index (material id)                 |
   * | velocity      | dim         | v_p                                      |
   * | X             | dim         | material coordinate (initial position)   |
   * | stress        | 6           | Cauchy stress xx yy zz yz xz xy (3D)     |
   * | F             | dim*dim     | deformation gradient, row-major          |
   * | domain        | dim*dim     | half-vectors r_i of the particle domain  |
   * |               |             | in the reference configuration (column i)|
   * | traction_area | 1           | body-boundary area carrying traction     |
   * | history       | n_history   | material internal variables              |
   * | corners       | 2^dim dim   | CPDI2 only: current domain corners       |
   * | affine        | dim*dim     | APIC only: affine velocity C_p           |
   * | traction_     | dim         | bodies with traction only: reference     |
   * |   offset      |             | offset X_face - X_p of the loaded face   |
   *
   * Stress is always stored with six components: 2D and 1D models keep the
   * out-of-plane normal stress that plane strain and uniaxial strain need.
   */
  template <int dim>
  struct ParticleLayout
  {
    static constexpr unsigned int mass          = 0;
    static constexpr unsigned int volume0       = 1;
    static constexpr unsigned int volume        = 2;
    static constexpr unsigned int body          = 3;
    static constexpr unsigned int velocity      = 4;
    static constexpr unsigned int X             = velocity + dim;
    static constexpr unsigned int stress        = X + dim;
    static constexpr unsigned int n_stress      = 6;
    static constexpr unsigned int F             = stress + n_stress;
    static constexpr unsigned int domain        = F + dim * dim;
    static constexpr unsigned int traction_area = domain + dim * dim;
    static constexpr unsigned int history       = traction_area + 1;

    unsigned int n_history           = 0;
    bool         has_corners         = false;
    bool         has_affine          = false;
    bool         has_traction_offset = false;

    static constexpr unsigned int n_corner_values = (1u << dim) * dim;

    /// Start of the CPDI2 corners (corner c, component d at c * dim + d).
    unsigned int
    corners() const
    {
      return history + n_history;
    }

    /// Start of APIC's affine velocity C_p (row-major), 0 without APIC.
    unsigned int
    affine() const
    {
      return has_affine ? corners() + (has_corners ? n_corner_values : 0) : 0;
    }

    /// Start of the loaded-face offset (only when some body carries a
    /// traction), 0 otherwise.
    unsigned int
    traction_offset() const
    {
      return has_traction_offset ?
               history + n_history + (has_corners ? n_corner_values : 0) +
                 (has_affine ? dim * dim : 0) :
               0;
    }

    unsigned int
    n_properties() const
    {
      return history + n_history + (has_corners ? n_corner_values : 0) +
             (has_affine ? dim * dim : 0) + (has_traction_offset ? dim : 0);
    }

    /// Names for output, one per slot (vector components share a name).
    std::vector<std::string>
    names(const std::vector<std::string> &history_names) const;

    /// How ParaView should read each slot.
    std::vector<
      dealii::DataComponentInterpretation::DataComponentInterpretation>
    interpretations() const;

    /// Column headers for the CSV table (one per slot).
    std::vector<std::string>
    csv_headers(const std::vector<std::string> &history_names) const;
  };

  /// Voigt order of the stored stress: xx yy zz yz xz xy.
  inline __attribute__((always_inline)) void
  store_stress(const dealii::SymmetricTensor<2, 3> &s, double *p)
  {
    p[0] = s[0][0];
    p[1] = s[1][1];
    p[2] = s[2][2];
    p[3] = s[1][2];
    p[4] = s[0][2];
    p[5] = s[0][1];
  }

  inline __attribute__((always_inline)) dealii::SymmetricTensor<2, 3>
  load_stress(const double *p)
  {
    dealii::SymmetricTensor<2, 3> s;
    s[0][0] = p[0];
    s[1][1] = p[1];
    s[2][2] = p[2];
    s[1][2] = p[3];
    s[0][2] = p[4];
    s[0][1] = p[5];
    return s;
  }

  /// The dim x dim (in-plane) part of the stored Voigt stress.
  template <int dim>
  inline __attribute__((always_inline)) dealii::Tensor<2, dim>
  in_plane_stress(const double *s)
  {
    dealii::Tensor<2, dim> sigma;
    sigma[0][0] = s[0];
    if constexpr (dim >= 2)
      {
        sigma[1][1] = s[1];
        sigma[0][1] = sigma[1][0] = s[5];
      }
    if constexpr (dim == 3)
      {
        sigma[2][2] = s[2];
        sigma[1][2] = sigma[2][1] = s[3];
        sigma[0][2] = sigma[2][0] = s[4];
      }
    return sigma;
  }

  template <int dim>
  inline __attribute__((always_inline)) dealii::Tensor<2, dim>
  load_matrix(const double *p)
  {
    dealii::Tensor<2, dim> t;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        t[i][j] = p[i * dim + j];
    return t;
  }

  template <int dim>
  inline __attribute__((always_inline)) void
  store_matrix(const dealii::Tensor<2, dim> &t, double *p)
  {
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        p[i * dim + j] = t[i][j];
  }

  /// Embed a dim x dim tensor in 3x3 with @p diagonal on the added diagonal.
  template <int dim>
  inline __attribute__((always_inline)) dealii::Tensor<2, 3>
  embed(const dealii::Tensor<2, dim> &t, const double diagonal)
  {
    dealii::Tensor<2, 3> out;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        out[i][j] = (i < dim && j < dim) ? t[i][j] : (i == j ? diagonal : 0.);
    return out;
  }
} // namespace mpm
