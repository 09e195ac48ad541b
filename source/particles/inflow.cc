#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <mpm/parameters/parsing.h>
#include <mpm/particles/inflow.h>
#include <mpm/utilities/input_error.h>
#include <mpm/utilities/numbers.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mpm
{
  using namespace dealii;

  template <int dim>
  void
  InflowParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    const std::string shape = dim == 3 ? "disk" :
                              dim == 2 ? "segment" :
                                         "point";
    prm.declare_entry(
      "Enabled",
      "false",
      Patterns::Bool(),
      "Create particles of this body through an inlet: a " + shape +
        " at Center, normal to Direction, through which the body's material "
        "enters at Speed from Start time until End time or until Volume has "
        "entered. The mass flux is rho0 v A (rho0 the material's reference "
        "density, A the inlet's area): the fluid is cut into layers of "
        "thickness Particle spacing, each carrying rho0 A s, and a layer "
        "appears when its centre crosses the inlet. New particles take the "
        "body's Initial stress at their position (e.g. the inlet pressure, "
        "0 for a free jet) and no strain. The statistics file's column "
        "injected_mass counts the mass that has entered. A body with "
        "Geometry = none starts without particles.");
    prm.declare_entry("Center",
                      Parameters::default_point(dim, 0.5),
                      Patterns::List(Patterns::Double(), dim, dim),
                      "The inlet's centre [m]; the inlet must lie inside the "
                      "grid, clear of its boundary.");
    prm.declare_entry("Direction",
                      dim == 1 ? "1" :
                      dim == 2 ? "0, -1" :
                                 "0, 0, -1",
                      Patterns::List(Patterns::Double(), dim, dim),
                      "The direction of the entering flow (normalised; not "
                      "zero).");
    prm.declare_entry("Radius",
                      "0.05",
                      NumberOrConstant(),
                      dim == 3 ? "The disk's radius [m], positive." :
                      dim == 2 ? "Half the segment's length [m], positive." :
                                 "Not used in 1D (the inlet is the point).");
    prm.declare_entry("Speed",
                      "1",
                      NumberOrConstant(),
                      "The speed v of the entering flow [m/s], positive.");
    prm.declare_entry("Start time",
                      "0",
                      NumberOrConstant(),
                      "When the flow starts [s], at least 0.");
    prm.declare_entry("End time",
                      "",
                      Patterns::Anything(),
                      "When the flow stops [s], after Start time; empty: "
                      "with the run, or when Volume has entered.");
    prm.declare_entry(
      "Volume",
      "0",
      NumberOrConstant(),
      "The volume to let in [m^3; m^2 per unit thickness in 2D; m per unit "
      "cross-section in 1D], rounded to whole layers (A s each); 0: not "
      "limited. With End time too, the flow stops at whichever comes "
      "first.");
    prm.declare_entry(
      "Particle spacing",
      "0.01",
      NumberOrConstant(),
      "The thickness s of a layer [m], and the spacing of the particles "
      "across the inlet (in 2D adjusted so that a whole number of "
      "particles spans the segment); positive and at most the inlet's "
      "width. A grid cell h wide takes about (h/s)^dim particles.");
  }

  template <int dim>
  double
  InflowParameters<dim>::area() const
  {
    return dim == 3 ? numbers::PI * radius * radius : dim == 2 ? 2 * radius : 1;
  }

  namespace
  {
    /// Round @p x to the nearest integer at or above 0.
    unsigned long long
    to_count(const double x)
    {
      return x > 0.5 ? static_cast<unsigned long long>(std::floor(x + 0.5)) :
                       0ull;
    }

    /// The lattice across the inlet (offsets in the tangent coordinates):
    /// 2D m points of spacing 2R/m; 3D the square lattice of spacing s
    /// through the centre, inside the disk.
    template <int dim>
    std::vector<std::array<double, 2>>
    lattice(const InflowParameters<dim> &prm, double &width)
    {
      std::vector<std::array<double, 2>> points;
      width = prm.spacing;
      if constexpr (dim == 1)
        points.push_back({{0., 0.}});
      else if constexpr (dim == 2)
        {
          const unsigned long long m =
            std::max(1ull, to_count(2 * prm.radius / prm.spacing));
          width = 2 * prm.radius / m;
          for (unsigned long long i = 0; i < m; ++i)
            points.push_back({{(i + 0.5) * width - prm.radius, 0.}});
        }
      else
        {
          const long long half =
            static_cast<long long>(std::ceil(prm.radius / prm.spacing));
          // in lattice units, points on the circle (to round-off) left out
          const double r = prm.radius / prm.spacing;
          for (long long i = -half; i <= half; ++i)
            for (long long j = -half; j <= half; ++j)
              if (double(i * i + j * j) < r * r * (1 - 1e-12))
                points.push_back({{i * prm.spacing, j * prm.spacing}});
        }
      return points;
    }

    /// Layers with centre crossing at or before @p t.
    template <int dim>
    unsigned long long
    layers_until(const InflowParameters<dim> &prm, const double t)
    {
      if (!(t >= prm.start_time))
        return 0;
      return static_cast<unsigned long long>(
        std::floor((t - prm.start_time) * prm.speed / prm.spacing + 0.5));
    }

    template <int dim>
    unsigned long long
    total_layers(const InflowParameters<dim> &prm, const double run_end_time)
    {
      unsigned long long n =
        layers_until(prm, std::min(prm.end_time, run_end_time));
      if (prm.volume > 0)
        n = std::min(n, to_count(prm.volume / (prm.area() * prm.spacing)));
      return n;
    }
  } // namespace

  template <int dim>
  void
  InflowParameters<dim>::parse_parameters(ParameterHandler &prm)
  {
    enabled = prm.get_bool("Enabled");
    center  = Parameters::parse_point<dim>(prm.get("Center"), "Inflow/Center");
    const auto dir =
      Parameters::parse_point<dim>(prm.get("Direction"), "Inflow/Direction");
    const auto entry = [&](const std::string &name) {
      return "Inflow/" + name + " = " + prm.get(name);
    };
    if (!(dir.norm() > 0) || !std::isfinite(dir.norm()))
      throw InputError(entry("Direction") + " must be a non-zero direction");
    direction         = dir / dir.norm();
    const auto number = [&](const std::string &name) {
      try
        {
          return get_number(prm, name);
        }
      catch (const InputError &e)
        {
          throw InputError("Inflow/" + std::string(e.what()));
        }
    };
    radius     = dim == 1 ? 0.5 : number("Radius");
    speed      = number("Speed");
    start_time = number("Start time");
    volume     = number("Volume");
    spacing    = number("Particle spacing");
    end_time   = std::numeric_limits<double>::infinity();
    if (!prm.get("End time").empty())
      end_time = number("End time");
    if (!enabled)
      return;
    if (dim > 1 && !(radius > 0 && std::isfinite(radius)))
      throw InputError(entry("Radius") + " must be positive");
    if (!(speed > 0 && std::isfinite(speed)))
      throw InputError(entry("Speed") +
                       " must be positive: the inflow's mass flux rho v A "
                       "would be zero or negative");
    if (!(start_time >= 0 && std::isfinite(start_time)))
      throw InputError(entry("Start time") + " must be at least 0");
    if (!(end_time > start_time))
      throw InputError(entry("End time") + " must come after Start time = " +
                       prm.get("Start time"));
    if (!(volume >= 0 && std::isfinite(volume)))
      throw InputError(entry("Volume") + " must be at least 0 (0: no limit)");
    if (!(spacing > 0 && std::isfinite(spacing)))
      throw InputError(entry("Particle spacing") + " must be positive");
    if (dim > 1 && spacing > 2 * radius)
      throw InputError(entry("Particle spacing") +
                       " is wider than the inlet (2 Radius = " +
                       std::to_string(2 * radius) + ")");
    if (volume > 0 && to_count(volume / (area() * spacing)) == 0)
      throw InputError(entry("Volume") +
                       " is less than half a layer of the inlet (area times "
                       "Particle spacing = " +
                       std::to_string(area() * spacing) + ")");
  }

  template <int dim>
  Inflow<dim>::Inflow(const InflowParameters<dim> &parameters,
                      const unsigned int           body,
                      const double                 run_end_time,
                      const std::string           &where)
    : prm(parameters)
    , body_index(body)
    , location(where)
  {
    const Tensor<1, dim> &n = prm.direction;
    if constexpr (dim == 2)
      tangents[0] = Tensor<1, 2>({-n[1], n[0]});
    if constexpr (dim == 3)
      {
        // the axis least aligned with n gives a well-conditioned tangent
        unsigned int axis = 0;
        for (unsigned int d = 1; d < 3; ++d)
          if (std::abs(n[d]) < std::abs(n[axis]))
            axis = d;
        Tensor<1, 3> e;
        e[axis]     = 1;
        tangents[0] = cross_product_3d(n, e);
        tangents[0] /= tangents[0].norm();
        tangents[1] = cross_product_3d(n, tangents[0]);
      }
    double     width  = 0;
    const auto points = lattice(prm, width);
    for (const auto &p : points)
      {
        Tensor<1, dim> o;
        for (unsigned int k = 0; k + 1 < dim; ++k)
          o += p[k] * tangents[k];
        offsets.push_back(o);
      }
    volume = prm.area() * prm.spacing / offsets.size();
    // the tangential half-width that gives the domain the volume V
    half_width     = dim == 3 ? std::sqrt(volume / prm.spacing) / 2 :
                     dim == 2 ? width / 2 :
                                0;
    n_total_layers = total_layers(prm, run_end_time);
  }

  template <int dim>
  unsigned long long
  Inflow<dim>::layers_at(const double t) const
  {
    return std::min(layers_until(prm, t), n_total_layers);
  }

  template <int dim>
  std::vector<Point<dim>>
  Inflow<dim>::points_at(const double d) const
  {
    std::vector<Point<dim>> points;
    for (const auto &o : offsets)
      points.push_back(prm.center + d * prm.direction + o);
    return points;
  }

  template <int dim>
  void
  Inflow<dim>::layer(const unsigned long long         k,
                     const double                     t,
                     std::vector<ParticleSeed<dim>>  &seeds,
                     std::vector<unsigned long long> &ids) const
  {
    // distance travelled since the layer's centre crossed the inlet
    const double d =
      std::max(0., (t - prm.start_time) * prm.speed - (k + 0.5) * prm.spacing);
    ParticleSeed<dim> s;
    s.volume = volume;
    for (unsigned int d0 = 0; d0 < dim; ++d0)
      s.domain[d0][0] = prm.spacing / 2 * prm.direction[d0];
    for (unsigned int c = 1; c < dim; ++c)
      for (unsigned int d0 = 0; d0 < dim; ++d0)
        s.domain[d0][c] = half_width * tangents[c - 1][d0];
    for (unsigned int j = 0; j < offsets.size(); ++j)
      {
        s.position = prm.center + d * prm.direction + offsets[j];
        // deal.II vertex order: bit i of c picks the side along r_i
        for (unsigned int c = 0; c < (1u << dim); ++c)
          {
            s.corners[c] = s.position;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int d0 = 0; d0 < dim; ++d0)
                s.corners[c][d0] += ((c >> i) & 1 ? 1. : -1.) * s.domain[d0][i];
          }
        seeds.push_back(s);
        ids.push_back(first_id + k * id_stride + j);
      }
  }

  template <int dim>
  unsigned long long
  Inflow<dim>::planned_particles(const InflowParameters<dim> &prm,
                                 const double                 run_end_time)
  {
    if (!prm.enabled)
      return 0;
    double width = 0;
    return total_layers(prm, run_end_time) * lattice(prm, width).size();
  }

  template struct InflowParameters<1>;
  template struct InflowParameters<2>;
  template struct InflowParameters<3>;
  template class Inflow<1>;
  template class Inflow<2>;
  template class Inflow<3>;
} // namespace mpm
