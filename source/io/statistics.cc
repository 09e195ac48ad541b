#include <deal.II/base/mpi.h>

#include <mpm/io/atomic_files.h>
#include <mpm/io/statistics.h>
#include <mpm/particles/particle_layout.h>

#include <algorithm>
#include <array>
#include <iomanip>
#include <limits>

namespace mpm
{
  using namespace dealii;

  template <int dim>
  void
  GlobalStatistics<dim>::compute(Particles::ParticleHandler<dim> &particles,
                                 const std::vector<Body<dim>>    &bodies,
                                 const MPI_Comm                   comm)
  {
    using L = ParticleLayout<dim>;
    // Local sums in one array, reduced with one collective call.
    constexpr unsigned int n        = 4 + dim + 3 + 1;
    double                 local[n] = {};
    // the loads per body where they are constant; NaN otherwise
    std::vector<std::array<double, 2 * dim>> load(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        load[b].fill(std::numeric_limits<double>::quiet_NaN());
        if (bodies[b].body_force.is_constant())
          bodies[b].body_force.value({}, 0., load[b].data());
        if (!bodies[b].has_traction())
          std::fill(load[b].begin() + dim, load[b].end(), 0.);
        else if (bodies[b].traction.is_constant())
          bodies[b].traction.value({}, 0., load[b].data() + dim);
      }
    for (const auto &p : particles)
      {
        const double *prop = p.get_properties().data();
        const double  m    = prop[L::mass];
        const auto   &mat =
          *bodies[static_cast<unsigned int>(prop[L::body])].material;
        double v2 = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            v2 += prop[L::velocity + d] * prop[L::velocity + d];
            local[4 + d] += m * prop[L::velocity + d];
          }
        local[0] += 1;
        local[1] += m;
        local[2] += 0.5 * m * v2;
        // A collective sum: a material that throws here (inverted
        // particle) must not leave this rank alone, so it counts as NaN.
        double energy;
        try
          {
            energy = mat.strain_energy_density(
              load_stress(prop + L::stress),
              embed<dim>(load_matrix<dim>(prop + L::F), 1.),
              ArrayView<const double>(prop + L::history, mat.n_history()));
          }
        catch (const std::exception &)
          {
            energy = std::numeric_limits<double>::quiet_NaN();
          }
        local[3] += prop[L::volume0] * energy;
        Tensor<1, 3> x, v;
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d] = p.get_location()[d];
            v[d] = prop[L::velocity + d];
          }
        const Tensor<1, 3> h = m * cross_product_3d(x, v);
        for (unsigned int d = 0; d < 3; ++d)
          local[4 + dim + d] += h[d];
        const auto  &f    = load[static_cast<unsigned int>(prop[L::body])];
        const double area = prop[L::traction_area];
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double u = x[d] - prop[L::X + d];
            local[n - 1] +=
              (m * f[d] + (area > 0 ? area * f[dim + d] : 0.)) * u;
          }
      }
    double global[n];
    Utilities::MPI::sum(ArrayView<const double>(local, n),
                        comm,
                        ArrayView<double>(global, n));
    n_particles    = static_cast<unsigned long long>(global[0] + 0.5);
    mass           = global[1];
    kinetic_energy = global[2];
    strain_energy  = global[3];
    for (unsigned int d = 0; d < dim; ++d)
      momentum[d] = global[4 + d];
    for (unsigned int d = 0; d < 3; ++d)
      angular_momentum[d] = global[4 + dim + d];
    load_work = global[n - 1];
  }

  template <int dim>
  std::vector<std::string>
  StatisticsFile<dim>::column_names(const std::vector<std::string> &extra)
  {
    const char              *axis[3] = {"x", "y", "z"};
    std::vector<std::string> c       = {"time",
                                        "step",
                                        "dt",
                                        "n_particles",
                                        "mass",
                                        "removed_mass",
                                        "kinetic_energy",
                                        "strain_energy",
                                        "total_energy"};
    for (unsigned int d = 0; d < dim; ++d)
      c.push_back(std::string("momentum_") + axis[d]);
    if (dim == 2)
      c.push_back("angular_momentum_z");
    if (dim == 3)
      for (unsigned int d = 0; d < 3; ++d)
        c.push_back(std::string("angular_momentum_") + axis[d]);
    c.insert(c.end(), extra.begin(), extra.end());
    return c;
  }

  template <int dim>
  void
  StatisticsFile<dim>::open(const std::string              &file_name,
                            const std::vector<std::string> &extra)
  {
    // A plain header line: pandas (sep=r"\s+") and gnuplot (using
    // 'time':'kinetic_energy') both read the columns by name.
    out.open(file_name);
    bool first = true;
    for (const auto &c : column_names(extra))
      {
        out << (first ? "" : " ") << c;
        first = false;
      }
    out << '\n' << std::flush;
    if (!out)
      throw std::runtime_error("cannot write the statistics file '" +
                               file_name + "'");
  }

  template <int dim>
  void
  StatisticsFile<dim>::resume(const std::string &file_name,
                              const std::string &content)
  {
    write_file_atomically(file_name, content);
    out.open(file_name, std::ios::app);
    if (!out)
      throw std::runtime_error("cannot write the statistics file '" +
                               file_name + "'");
  }

  template <int dim>
  void
  StatisticsFile<dim>::write_row(const double                 time,
                                 const unsigned int           step,
                                 const double                 dt,
                                 const GlobalStatistics<dim> &s,
                                 const std::vector<double>   &extra)
  {
    if (!out.is_open())
      return;
    out << std::setprecision(12) << time << ' ' << step << ' ' << dt << ' '
        << s.n_particles << ' ' << s.mass << ' ' << s.removed_mass << ' '
        << s.kinetic_energy << ' ' << s.strain_energy << ' '
        << s.kinetic_energy + s.strain_energy;
    for (unsigned int d = 0; d < dim; ++d)
      out << ' ' << s.momentum[d];
    if (dim == 2)
      out << ' ' << s.angular_momentum[2];
    if (dim == 3)
      for (unsigned int d = 0; d < 3; ++d)
        out << ' ' << s.angular_momentum[d];
    for (const double e : extra)
      out << ' ' << e;
    out << '\n' << std::flush;
    if (!out)
      throw std::runtime_error("cannot write the statistics file");
  }

  template struct GlobalStatistics<1>;
  template struct GlobalStatistics<2>;
  template struct GlobalStatistics<3>;
  template class StatisticsFile<1>;
  template class StatisticsFile<2>;
  template class StatisticsFile<3>;
} // namespace mpm
