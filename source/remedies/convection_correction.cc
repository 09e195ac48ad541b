#include <mpm/particles/cell_loop.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/remedies/convection_correction.h>
#include <mpm/remedies/convection_correction_remedy.h>
#include <mpm/transfer/particle_to_grid.h>

#include <cmath>
#include <limits>

namespace mpm
{
  namespace remedies
  {
    using namespace dealii;

    CellLine
    CellLine::fit(const std::vector<AxialSample> &samples,
                  const AxialSample              *extra)
    {
      CellLine line;
      double   W = 0, Wr = 0, Wv = 0;
      for (const auto &s : samples)
        {
          W += s.volume;
          Wr += s.volume * s.r;
          Wv += s.volume * s.value;
        }
      if (!(W > 0))
        return line;
      line.r_mean = Wr / W;
      line.mean   = Wv / W;
      double Wrr = 0, Wrv = 0;
      for (const auto &s : samples)
        {
          Wrr += s.volume * (s.r - line.r_mean) * (s.r - line.r_mean);
          Wrv += s.volume * (s.r - line.r_mean) * (s.value - line.mean);
        }
      // The least-squares line passes through the weighted mean; r lies in
      // [-1, 1], so the spread test needs no scale.
      if (Wrr > 1e-12 * W)
        line.slope = Wrv / Wrr;
      else if (extra != nullptr && std::abs(extra->r - line.r_mean) > 1e-6)
        line.slope = (extra->value - line.mean) / (extra->r - line.r_mean);
      return line;
    }

    double
    CellLine::moment(const double a, const double b, const unsigned int k) const
    {
      const double c = mean - slope * r_mean; // the line is c + slope r
      if (k == 0)
        return (b - a) * (c + slope * 0.5 * (a + b));
      return c * (b * b - a * a) / 2 + slope * (b * b * b - a * a * a) / 3;
    }

    double
    convection_shift(const std::vector<AxialSample> &samples,
                     const AxialSample              *extra,
                     const double                    a,
                     const double                    b,
                     const double                    h)
    {
      double W = 0, Wv = 0;
      for (const auto &s : samples)
        {
          W += s.volume;
          Wv += s.volume * s.value;
        }
      if (!(W > 0))
        return 0.;
      const double integral =
        0.5 * h * CellLine::fit(samples, extra).moment(a, b, 0);
      return (integral - Wv) / W;
    }

    template <int dim>
    ConvectionCorrection<dim>::ConvectionCorrection(
      const std::vector<Body<dim>> &bodies)
      : ForcePassHook<dim>("convection correction")
      , corrected(bodies.size(), 0)
      , loads(bodies.size(), 0)
    {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (const auto *choice =
              bodies[b]
                .prm.locking_remedies
                .template find<ConvectionCorrectionSettings>())
          {
            corrected[b] = 1;
            loads[b]     = choice->body_force && bodies[b].has_body_force();
            any          = true;
          }
    }

    template <int dim>
    void
    ConvectionCorrection<dim>::before_force_pass(
      const BackgroundGrid<dim>       &grid,
      Particles::ParticleHandler<dim> &particles,
      const std::vector<Body<dim>>    &bodies,
      const double                     time)
    {
      saved.clear();
      nodal_forces.clear();
      if constexpr (dim != 1)
        {
          (void)grid, (void)particles, (void)bodies, (void)time;
        }
      else
        {
          using L = ParticleLayout<1>;
          if (!any)
            return;

          // The particles of the active neighbour across face f (0: left).
          const auto for_each_in_neighbour =
            [&](const auto &cell, const unsigned int f, const auto &visit) {
              if (cell->at_boundary(f))
                return;
              auto n = cell->neighbor(f);
              while (n->has_children())
                n = n->child(1 - f);
              const typename Triangulation<1>::active_cell_iterator active(n);
              for (const auto &q : particles.particles_in_cell(active))
                visit(q);
            };
          // The particle's body force m_p b_p, as P2G adds it.
          const auto body_force = [&](const auto &p, const double *prop) {
            double g = 0;
            bodies[static_cast<unsigned int>(prop[L::body])].body_force_at(
              p.get_location(), prop + L::X, time, &g);
            return prop[L::mass] * g;
          };

          // Shifts are collected first and applied at the end: a cell may
          // borrow the stress of a neighbour's particle, which must be the
          // material's.
          std::vector<std::pair<double *, double>> shifts;
          std::vector<double>                      net_force(bodies.size()),
            body_mass(bodies.size());
          std::vector<AxialSample> stress, load;
          std::vector<double *>    targets;
          const double inf = std::numeric_limits<double>::infinity();
          for_each_cell_with_particles(
            grid, particles, [&](const auto &cell, const auto &pic) {
              const double x0   = cell->vertex(0)[0];
              const double h    = cell->vertex(1)[0] - x0;
              const auto   r_of = [&](const double x) {
                return 2 * (x - x0) / h - 1;
              };
              for (unsigned int b = 0; b < bodies.size(); ++b)
                {
                  if (!corrected[b])
                    continue;
                  stress.clear();
                  load.clear();
                  targets.clear();
                  double lo = inf, hi = -inf, W = 0, Wr = 0;
                  double particle_force[2] = {}; // sum_p N_ip m_p b_p
                  double particle_mass[2]  = {}; // sum_p N_ip m_p
                  for (auto &p : pic)
                    {
                      double *prop = p.get_properties().data();
                      if (static_cast<unsigned int>(prop[L::body]) != b)
                        continue;
                      const double x  = p.get_location()[0];
                      const double V  = prop[L::volume];
                      const double xi = p.get_reference_location()[0];
                      stress.push_back({2 * xi - 1, V, prop[L::stress]});
                      targets.push_back(prop + L::stress);
                      if (loads[b])
                        {
                          const double f = body_force(p, prop);
                          load.push_back({2 * xi - 1, V, f / V});
                          particle_force[0] += (1 - xi) * f;
                          particle_force[1] += xi * f;
                          particle_mass[0] += (1 - xi) * prop[L::mass];
                          particle_mass[1] += xi * prop[L::mass];
                        }
                      lo = std::min(lo, r_of(x - 0.5 * V));
                      hi = std::max(hi, r_of(x + 0.5 * V));
                      W += V;
                      Wr += V * (2 * xi - 1);
                    }
                  if (stress.empty())
                    continue;
                  // Where the body goes on into a neighbour, it fills the
                  // cell up to that face; at a free end, up to the edge of
                  // its particles' domains (length V_p).
                  bool         continues[2] = {false, false};
                  AxialSample  near_stress{0, 0, 0}, near_load{0, 0, 0};
                  double       distance = inf;
                  const double r_mean   = W > 0 ? Wr / W : 0.;
                  for (unsigned int f = 0; f < 2; ++f)
                    for_each_in_neighbour(cell, f, [&](const auto &q) {
                      const double *prop = q.get_properties().data();
                      if (static_cast<unsigned int>(prop[L::body]) != b)
                        return;
                      continues[f]   = true;
                      const double r = r_of(q.get_location()[0]);
                      if (std::abs(r - r_mean) < distance)
                        {
                          distance    = std::abs(r - r_mean);
                          near_stress = {r, prop[L::volume], prop[L::stress]};
                          if (loads[b])
                            near_load = {r,
                                         prop[L::volume],
                                         body_force(q, prop) / prop[L::volume]};
                        }
                    });
                  const bool   borrow = distance < inf;
                  const double a      = continues[0] ? -1. : lo;
                  const double c      = continues[1] ? 1. : hi;
                  const double delta  = convection_shift(
                    stress, borrow ? &near_stress : nullptr, a, c, h);
                  for (double *s : targets)
                    shifts.emplace_back(s, delta);
                  if (loads[b])
                    {
                      // (h/2) int_a^c N_v line dr with N_0,1 = (1 -+ r)/2
                      const auto line =
                        CellLine::fit(load, borrow ? &near_load : nullptr);
                      const double        m0    = line.moment(a, c, 0);
                      const double        m1    = line.moment(a, c, 1);
                      const unsigned int *nodes = grid.nodes(cell);
                      for (unsigned int v = 0; v < 2; ++v)
                        {
                          const double df = 0.25 * h * (v ? m0 + m1 : m0 - m1) -
                                            particle_force[v];
                          nodal_forces.push_back(
                            {nodes[v], b, df, particle_mass[v]});
                          net_force[b] += df;
                          body_mass[b] += particle_mass[v];
                        }
                    }
                }
            });
          // The body's total load stays sum_p m_p b_p, as without the
          // correction: the net of the corrections goes back as a uniform
          // acceleration, which strains nothing.
          for (auto &n : nodal_forces)
            if (body_mass[n.body] > 0)
              n.force -= net_force[n.body] * n.mass / body_mass[n.body];
          saved.reserve(shifts.size());
          for (const auto &[s, delta] : shifts)
            {
              saved.emplace_back(s, *s);
              *s += delta;
            }
        }
    }

    template <int dim>
    void
    ConvectionCorrection<dim>::after_force_pass(NodalVector &p2g)
    {
      for (const auto &[s, value] : saved)
        *s = value;
      saved.clear();
      using P = transfer::P2GLayout<dim>;
      // 1D: one rank owns every node.
      double *const out = p2g.begin();
      for (const auto &n : nodal_forces)
        out[n.node * P::n_components + P::force] += n.force;
      nodal_forces.clear();
    }

    template class ConvectionCorrection<1>;
    template class ConvectionCorrection<2>;
    template class ConvectionCorrection<3>;
  } // namespace remedies
} // namespace mpm
