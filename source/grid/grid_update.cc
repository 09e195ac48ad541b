#include <deal.II/base/utilities.h>

#include <mpm/grid/grid_update.h>

#include <cmath>
#include <sstream>

namespace mpm
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    std::string
    describe_node(const BackgroundGrid<dim> &grid,
                  const unsigned int         i,
                  const char                *what)
    {
      std::ostringstream s;
      s << "non-finite nodal " << what << " at the grid node at ("
        << grid.node_position(i) << ")";
      return s.str();
    }

    /// @p node_pass on the active nodes of @p active (the other nodes of
    /// @p kinematics, with @p nc components each, zeroed), or on every
    /// owned node.
    template <int dim, typename NodePass>
    void
    for_each_node(const BackgroundGrid<dim> &grid,
                  ActiveNodes               *active,
                  NodalVector               &kinematics,
                  const unsigned int         nc,
                  const NodePass            &node_pass)
    {
      if (!active)
        {
          for (unsigned int i = 0; i < grid.n_owned_nodes(); ++i)
            node_pass(i);
          return;
        }
      active->zero_inactive(kinematics, nc);
      for (const unsigned int i : active->nodes())
        node_pass(i);
      active->record(kinematics);
    }
  } // namespace

  template <int dim>
  std::string
  update_grid(const BackgroundGrid<dim> &grid,
              const NodalVector         &p2g,
              const double               dt,
              const double               damping,
              const double               min_mass,
              NodalVector               &kinematics,
              ActiveNodes               *active)
  {
    using P           = P2GLayout<dim>;
    using K           = KinematicsLayout<dim>;
    const double *in  = p2g.begin();
    double       *out = kinematics.begin();
    std::string   error;
    for_each_node(
      grid, active, kinematics, K::n_components, [&](const unsigned int i) {
        const double *node = in + i * P::n_components;
        double       *k    = out + i * K::n_components;
        const double  m    = node[P::mass];
        if (!(m > min_mass))
          {
            if (!std::isfinite(m) && error.empty())
              error = describe_node(grid, i, "mass");
            for (unsigned int c = 0; c < K::n_components; ++c)
              k[c] = 0;
            return;
          }
        double p[dim], f[dim];
        for (unsigned int d = 0; d < dim; ++d)
          {
            p[d] = node[P::momentum + d];
            f[d] = node[P::force + d] - damping * p[d];
          }
        grid.constrain(i, p);
        grid.constrain(i, f);
        for (unsigned int d = 0; d < dim; ++d)
          {
            k[K::increment + d] = dt * f[d] / m;
            k[K::velocity + d]  = (p[d] + dt * f[d]) / m;
            if (!std::isfinite(k[K::velocity + d]) && error.empty())
              error = describe_node(grid, i, "velocity");
          }
      });
    kinematics.update_ghost_values();
    return error;
  }

  template <int dim>
  std::string
  nodal_velocity(const BackgroundGrid<dim> &grid,
                 const NodalVector         &p2g,
                 const NodalVector         &momentum,
                 const unsigned int         momentum_components,
                 const unsigned int         momentum_offset,
                 const double               min_mass,
                 NodalVector               &kinematics,
                 ActiveNodes               *active)
  {
    using P = P2GLayout<dim>;
    using K = KinematicsLayout<dim>;
    std::string error;
    for_each_node(
      grid, active, kinematics, K::n_components, [&](const unsigned int i) {
        const double m = p2g.local_element(i * P::n_components + P::mass);
        double       v[dim];
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = m > min_mass ? momentum.local_element(i * momentum_components +
                                                       momentum_offset + d) /
                                  m :
                                0.;
        grid.constrain(i, v);
        for (unsigned int d = 0; d < dim; ++d)
          {
            kinematics.local_element(i * K::n_components + K::velocity + d) =
              v[d];
            if (!std::isfinite(v[d]) && error.empty())
              error = describe_node(grid, i, "velocity");
          }
      });
    kinematics.update_ghost_values();
    return error;
  }

  template std::string
  update_grid<1>(const BackgroundGrid<1> &,
                 const NodalVector &,
                 double,
                 double,
                 double,
                 NodalVector &,
                 ActiveNodes *);
  template std::string
  update_grid<2>(const BackgroundGrid<2> &,
                 const NodalVector &,
                 double,
                 double,
                 double,
                 NodalVector &,
                 ActiveNodes *);
  template std::string
  update_grid<3>(const BackgroundGrid<3> &,
                 const NodalVector &,
                 double,
                 double,
                 double,
                 NodalVector &,
                 ActiveNodes *);
  template std::string
  nodal_velocity<1>(const BackgroundGrid<1> &,
                    const NodalVector &,
                    const NodalVector &,
                    unsigned int,
                    unsigned int,
                    double,
                    NodalVector &,
                    ActiveNodes *);
  template std::string
  nodal_velocity<2>(const BackgroundGrid<2> &,
                    const NodalVector &,
                    const NodalVector &,
                    unsigned int,
                    unsigned int,
                    double,
                    NodalVector &,
                    ActiveNodes *);
  template std::string
  nodal_velocity<3>(const BackgroundGrid<3> &,
                    const NodalVector &,
                    const NodalVector &,
                    unsigned int,
                    unsigned int,
                    double,
                    NodalVector &,
                    ActiveNodes *);
} // namespace mpm
