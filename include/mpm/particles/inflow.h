#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <mpm/particles/body.h>
#include <mpm/particles/inflow_parameters.h>

#include <array>
#include <string>
#include <vector>

namespace mpm
{
  /**
   * Where and when an inlet creates particles. The inlet's cross-section
   * carries a fixed lattice of n points; the fluid is cut into layers of
   * thickness s (Particle spacing) along the direction, one particle per
   * lattice point and layer, each of volume A s / n, so that every layer
   * carries exactly rho A s. Layer k is the fluid that crosses the inlet
   * between t0 + k s/v and t0 + (k+1) s/v; it exists from the time
   * tau_k = t0 + (k + 1/2) s/v at which its centre crosses, and at time
   * t >= tau_k lies v (t - tau_k) downstream. The state at time t thus
   * holds every layer with tau_k <= t: the injected mass is a function of
   * time alone, and a run resumed at t continues with the same layers.
   * Particle ids are first_id + k stride + j (j: lattice point; the
   * inlets of a run interleave by layer, so that the ids do not depend on
   * how many layers the run will create).
   */
  template <int dim>
  class Inflow
  {
  public:
    /// @p run_end_time: Time stepping/End time (bounds the layers when
    /// neither End time nor Volume does); @p where: "Bodies/Body 0/Inflow".
    Inflow(const InflowParameters<dim> &prm,
           const unsigned int           body,
           const double                 run_end_time,
           const std::string           &where);

    /// Number the particles: layer k, point j gets first + k stride + j.
    void
    set_ids(const unsigned long long first, const unsigned long long stride)
    {
      first_id  = first;
      id_stride = stride;
    }

    unsigned int
    body() const
    {
      return body_index;
    }
    const std::string &
    where() const
    {
      return location;
    }
    /// Particles per layer (lattice points of the cross-section).
    unsigned int
    n_per_layer() const
    {
      return offsets.size();
    }
    /// Layers the inlet creates over the whole run.
    unsigned long long
    n_layers() const
    {
      return n_total_layers;
    }
    unsigned long long
    n_particles() const
    {
      return n_total_layers * offsets.size();
    }
    /// Reference volume of each particle, A s / n.
    double
    particle_volume() const
    {
      return volume;
    }
    /// The velocity v n of the entering fluid.
    dealii::Tensor<1, dim>
    velocity() const
    {
      return prm.speed * prm.direction;
    }
    /// Layers whose centre has crossed the inlet by time @p t.
    unsigned long long
    layers_at(const double t) const;

    /// The seeds (position at time @p t, volume, domain, corners) and ids
    /// of layer @p k, appended.
    void
    layer(const unsigned long long         k,
          const double                     t,
          std::vector<ParticleSeed<dim>>  &seeds,
          std::vector<unsigned long long> &ids) const;

    /// The lattice points at distance @p d downstream of the inlet.
    std::vector<dealii::Point<dim>>
    points_at(const double d) const;

    /// The planned layers and particles of @p prm up to @p run_end_time,
    /// without building the lattice's points (the resource estimate).
    static unsigned long long
    planned_particles(const InflowParameters<dim> &prm,
                      const double                 run_end_time);

  private:
    InflowParameters<dim> prm;
    unsigned int          body_index;
    std::string           location;
    /// the inlet's frame: tangents[0..dim-2] orthonormal to the direction
    std::array<dealii::Tensor<1, dim>, (dim > 1 ? dim - 1 : 1)> tangents;
    /// lattice points relative to the centre, in the inlet's plane
    std::vector<dealii::Tensor<1, dim>> offsets;
    double                              volume = 0;
    /// half the tangential width of a particle's domain
    double             half_width     = 0;
    unsigned long long n_total_layers = 0;
    unsigned long long first_id = 0, id_stride = 0;
  };
} // namespace mpm
