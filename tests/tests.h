// Helpers for the .cc tests: run a case given as parameter-file text and
// print rounded, rank-independent results to the file "output" that the
// deal.II test scripts compare.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <mpm/parameters/parameters.h>
#include <mpm/particles/particle_layout.h>
#include <mpm/solver/simulator.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

namespace mpm_test
{
  /// A simulator built from parameter-file text (all entries declared).
  template <int dim>
  struct Case
  {
    dealii::ParameterHandler             prm;
    mpm::Parameters::AllParameters<dim>  parameters;
    std::unique_ptr<mpm::Simulator<dim>> simulator;

    Case(const std::string &text, const unsigned int n_bodies = 1)
    {
      mpm::Parameters::AllParameters<dim>::declare_parameters(prm, n_bodies);
      prm.parse_input_from_string("set Dimension = " + std::to_string(dim) +
                                  "\n" + text);
      parameters.file_name = "test.prm";
      parameters.parse_parameters(prm);
      simulator =
        std::make_unique<mpm::Simulator<dim>>(parameters, prm, MPI_COMM_WORLD);
      simulator->setup();
    }
  };

  /// The value of the integrator's statistics column @p name
  /// (Simulator::integrator_columns()) after the last step.
  template <int dim>
  double
  integrator_value(const mpm::Simulator<dim> &sim, const std::string &name)
  {
    const auto columns = sim.integrator_columns();
    return sim
      .integrator_values()[std::find(columns.begin(), columns.end(), name) -
                           columns.begin()];
  }

  /// Run @p sim to @p t_end with steps of @p fraction of the stable one.
  template <int dim>
  void
  run_until(mpm::Simulator<dim> &sim, const double t_end, const double fraction)
  {
    while (sim.time() < t_end - 1e-12)
      sim.do_time_step(
        std::min(fraction * sim.stable_time_step(), t_end - sim.time()));
  }

  /// The mass-weighted mean displacement x - X of body @p body's
  /// particles, over every rank.
  template <int dim>
  dealii::Tensor<1, dim>
  mean_displacement(mpm::Simulator<dim> &sim, const unsigned int body)
  {
    using L               = mpm::ParticleLayout<dim>;
    double local[dim + 1] = {};
    for (const auto &p : sim.particles())
      {
        const double *prop = p.get_properties().data();
        if (prop[L::body] != body)
          continue;
        local[dim] += prop[L::mass];
        for (unsigned int d = 0; d < dim; ++d)
          local[d] += prop[L::mass] * (p.get_location()[d] - prop[L::X + d]);
      }
    double sum[dim + 1];
    dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(local, dim + 1),
                                MPI_COMM_WORLD,
                                dealii::ArrayView<double>(sum, dim + 1));
    dealii::Tensor<1, dim> u;
    for (unsigned int d = 0; d < dim; ++d)
      u[d] = sum[d] / sum[dim];
    return u;
  }

  /// Output stream that writes on rank 0 only.
  inline std::ofstream &
  log()
  {
    static std::ofstream out(
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ?
        "output" :
        "/dev/null");
    return out;
  }

  /// Print a check line and fail the test (exit 1) if it does not hold.
  inline void
  check(const bool         ok,
        const std::string &what,
        const double       value,
        const double       bound)
  {
    log() << (ok ? "OK   " : "FAIL ") << what << ": " << std::scientific
          << std::setprecision(2) << value << " (bound " << bound << ")"
          << std::endl;
    if (!ok)
      {
        std::cerr << "FAIL " << what << ": " << value << " (bound " << bound
                  << ")" << std::endl;
        std::exit(1);
      }
  }

  /// A check line without its value (for output that must be the same
  /// whatever the round-off and the number of ranks); a failed check goes
  /// to stderr with its value and stops the test (exit 1).
  inline void
  report(const bool ok, const std::string &what, const double value)
  {
    log() << (ok ? "OK   " : "FAIL ") << what << std::endl;
    if (!ok)
      {
        std::cerr << "FAIL " << what << ": " << value << std::endl;
        std::exit(1);
      }
  }

  /// check(|value| <= bound)
  inline void
  check_small(const std::string &what, const double value, const double bound)
  {
    check(std::abs(value) <= bound, what, std::abs(value), bound);
  }
} // namespace mpm_test
