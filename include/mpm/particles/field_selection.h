#pragma once

#include <mpm/particles/particle_layout.h>

#include <vector>

namespace mpm
{
  /**
   * The particles a pass works on: every particle, or those whose body
   * belongs to one velocity field (contact, contact/multi_field_contact.h).
   * A pass over one field skips the other fields' particles, so each
   * field gets its own nodal sums from the same kernels.
   */
  struct FieldSelection
  {
    /// per body, its field; null: every particle is selected
    const std::vector<unsigned char> *field_of_body = nullptr;
    unsigned int                      field         = 0;

    /// Whether the particle with properties @p prop is not in the pass.
    template <int dim>
    bool
    skips(const double *prop) const
    {
      return field_of_body && (*field_of_body)[static_cast<unsigned int>(
                                prop[ParticleLayout<dim>::body])] != field;
    }
  };
} // namespace mpm
