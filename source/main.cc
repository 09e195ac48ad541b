// The mpm application: read `set Dimension` from the parameter file, then
// build and run Simulator<dim>. Every error the user can fix ends with one
// message and a non-zero exit status.

#include <deal.II/base/mpi.h>

#include <mpm/parameters/listing_style.h>
#include <mpm/parameters/parameters.h>
#include <mpm/solver/resource_estimate.h>
#include <mpm/solver/simulator.h>
#include <mpm/utilities/input_error.h>

#include <filesystem>
#include <iostream>
#include <string>

namespace
{
  const char *usage =
    "Usage: mpm [options] FILE.prm\n"
    "       mpirun -np N mpm FILE.prm\n"
    "\n"
    "Explicit material point method on a deal.II Q1 grid.\n"
    "\n"
    "Options:\n"
    "  -h, --help                 this text\n"
    "  --validate FILE.prm        read and set up the case (grid, bodies,\n"
    "                             particles, stability check), then stop\n"
    "                             without writing anything\n"
    "  --resume FILE.prm          continue from the latest checkpoint in\n"
    "                             the output directory (sets Checkpointing/\n"
    "                             Resume computation = true)\n"
    "  --print-parameters [DIM] [FORMAT]\n"
    "                             print every parameter with its default\n"
    "                             and documentation (DIM = 1, 2 or 3;\n"
    "                             default 2), in parameter-file syntax\n"
    "                             (FORMAT = prm, the default) or as JSON\n"
    "                             (FORMAT = json)\n"
    "\n"
    "Documentation: the manual (scripts/build_manual.sh builds it from doc/;\n"
    "start at doc/index.md); doc/parameter_file.md for the file format.\n";

  template <int dim>
  void
  run(const std::string &file,
      const unsigned int n_bodies,
      const bool         validate,
      const bool         resume)
  {
    dealii::ParameterHandler prm;
    mpm::Parameters::AllParameters<dim>::declare_parameters(prm, n_bodies);
    mpm::Parameters::parse_file(prm, file);
    if (resume)
      {
        prm.enter_subsection("Checkpointing");
        prm.set("Resume computation", "true");
        prm.leave_subsection();
      }
    mpm::Parameters::AllParameters<dim> parameters;
    parameters.file_name = file;
    mpm::parse_with_range_check([&]() { parameters.parse_parameters(prm); });
    // Count before allocating: a case that cannot fit is refused now,
    // not after minutes of allocation.
    const auto estimate = mpm::estimate_resources(
      parameters,
      std::filesystem::path(file).parent_path().string(),
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
    const bool   limit_given = parameters.memory_limit > 0;
    const double limit       = limit_given ? parameters.memory_limit * 1e9 :
                                             mpm::available_memory(MPI_COMM_WORLD);
    mpm::check_resources(estimate, limit, limit_given);
    // Errors leave the simulator's scope normally (its timer would complain
    // about being destroyed during stack unwinding) and are re-thrown.
    std::exception_ptr error;
    {
      mpm::Simulator<dim> simulator(parameters, prm, MPI_COMM_WORLD);
      try
        {
          simulator.setup();
          if (validate)
            {
              if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
                std::cout << "mpm: " << file << " is valid ("
                          << simulator.particles().n_global_particles()
                          << " particles)\n  memory estimate: "
                          << estimate.summary() << "; "
                          << (limit > 0 ? mpm::gigabytes(limit) :
                                          std::string("unknown"))
                          << (limit_given ? " allowed" : " available")
                          << std::endl;
            }
          else
            simulator.run();
        }
      catch (...)
        {
          error = std::current_exception();
        }
    }
    if (error)
      std::rethrow_exception(error);
  }

  template <int dim>
  void
  print_parameters(const dealii::ParameterHandler::OutputStyle style)
  {
    dealii::ParameterHandler prm;
    mpm::Parameters::AllParameters<dim>::declare_parameters(prm, 1);
    prm.set("Dimension", std::to_string(dim));
    prm.print_parameters(std::cout, style);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  std::string file;
  bool        validate = false;
  bool        resume   = false;
  for (int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      if (a == "-h" || a == "--help")
        {
          if (root)
            std::cout << usage;
          return 0;
        }
      else if (a == "--print-parameters")
        {
          const std::string d     = (i + 1 < argc) ? argv[i + 1] : "2";
          const std::string f     = (i + 2 < argc) ? argv[i + 2] : "prm";
          const auto        style = mpm::Parameters::listing_style(f);
          if (!style)
            {
              if (root)
                std::cerr << "mpm: --print-parameters: unknown format '" << f
                          << "' (prm or json)\n";
              return 1;
            }
          if (root)
            {
              if (d == "1")
                print_parameters<1>(*style);
              else if (d == "3")
                print_parameters<3>(*style);
              else
                print_parameters<2>(*style);
            }
          return 0;
        }
      else if (a == "--validate")
        validate = true;
      else if (a == "--resume")
        resume = true;
      else if (!a.empty() && a[0] == '-')
        {
          if (root)
            std::cerr << "mpm: unknown option '" << a << "'\n\n" << usage;
          return 1;
        }
      else if (file.empty())
        file = a;
      else
        {
          if (root)
            std::cerr << "mpm: more than one parameter file given\n";
          return 1;
        }
    }
  if (file.empty())
    {
      if (root)
        std::cerr << usage;
      return 1;
    }

  try
    {
      const auto pre = mpm::Parameters::read_preamble(file);
      pre.require_every_body_described(file);
      switch (pre.dimension)
        {
          case 1:
            run<1>(file, pre.n_bodies, validate, resume);
            break;
          case 2:
            run<2>(file, pre.n_bodies, validate, resume);
            break;
          default:
            run<3>(file, pre.n_bodies, validate, resume);
        }
    }
  catch (const mpm::InputError &e)
    {
      if (root)
        std::cerr << "mpm: error: " << e.what() << "\nNothing was written."
                  << std::endl;
      return 1;
    }
  catch (const mpm::RuntimeError &e)
    {
      if (root)
        std::cerr << "mpm: the simulation stopped " << e.what()
                  << "\nOutput written before this point is kept." << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      // Possibly on this rank only: report here and stop every rank.
      std::cerr << "mpm: internal error on rank "
                << dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)
                << ": " << e.what() << std::endl;
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        MPI_Abort(MPI_COMM_WORLD, 3);
      return 3;
    }
  return 0;
}
