#include <mpm/particles/particle_layout.h>

namespace mpm
{
  namespace
  {
    const char *axis[3]  = {"x", "y", "z"};
    const char *voigt[6] = {"xx", "yy", "zz", "yz", "xz", "xy"};
  } // namespace

  template <int dim>
  std::vector<std::string>
  ParticleLayout<dim>::names(
    const std::vector<std::string> &history_names) const
  {
    std::vector<std::string> n(n_properties());
    n[mass]          = "mass";
    n[volume0]       = "volume0";
    n[volume]        = "volume";
    n[body]          = "body";
    n[traction_area] = "traction_area";
    for (unsigned int d = 0; d < dim; ++d)
      {
        n[velocity + d] = "velocity";
        n[X + d]        = "X";
      }
    for (unsigned int c = 0; c < n_stress; ++c)
      n[stress + c] = std::string("stress_") + voigt[c];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          n[F + i * dim + j] = std::string("F_") + axis[i] + axis[j];
          n[domain + i * dim + j] =
            std::string("domain_r") + std::to_string(j) + "_" + axis[i];
        }
    for (unsigned int h = 0; h < n_history; ++h)
      n[history + h] = h < history_names.size() ?
                         history_names[h] :
                         "history_" + std::to_string(h);
    if (has_corners)
      for (unsigned int c = 0; c < (1u << dim); ++c)
        for (unsigned int d = 0; d < dim; ++d)
          n[corners() + c * dim + d] =
            "corner" + std::to_string(c) + "_" + axis[d];
    if (has_affine)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          n[affine() + i * dim + j] = std::string("C_") + axis[i] + axis[j];
    if (has_traction_offset)
      for (unsigned int d = 0; d < dim; ++d)
        n[traction_offset() + d] = std::string("traction_offset_") + axis[d];
    for (auto &s : n)
      for (auto &c : s)
        if (c == ' ')
          c = '_';
    return n;
  }

  template <int dim>
  std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation>
  ParticleLayout<dim>::interpretations() const
  {
    using namespace dealii::DataComponentInterpretation;
    std::vector<DataComponentInterpretation> i(n_properties(),
                                               component_is_scalar);
    if (dim > 1)
      for (unsigned int d = 0; d < dim; ++d)
        {
          i[velocity + d] = component_is_part_of_vector;
          i[X + d]        = component_is_part_of_vector;
        }
    return i;
  }

  template <int dim>
  std::vector<std::string>
  ParticleLayout<dim>::csv_headers(
    const std::vector<std::string> &history_names) const
  {
    auto n = names(history_names);
    for (unsigned int d = 0; d < dim; ++d)
      {
        n[velocity + d] = std::string("v_") + axis[d];
        n[X + d]        = std::string("X_") + axis[d];
      }
    return n;
  }

  template struct ParticleLayout<1>;
  template struct ParticleLayout<2>;
  template struct ParticleLayout<3>;
} // namespace mpm
