// mpm-fe, the finite-element reference solver: read `set Dimension`, then
// run the refinement study of the parameter file (statics or modal
// analysis). Errors the user can fix end with one message naming the file
// and parameter, and exit status 1; nothing is written.

#include <deal.II/base/mpi.h>

#include <mpm/fe_reference/parameters.h>
#include <mpm/fe_reference/refinement_study.h>
#include <mpm/parameters/listing_style.h>
#include <mpm/parameters/parameters.h>
#include <mpm/utilities/input_error.h>

#include <iostream>
#include <string>

namespace
{
  const char *usage =
    "Usage: mpm-fe [options] FILE.prm\n"
    "\n"
    "Finite-element reference solver: linear elasticity with Q_p or\n"
    "Taylor-Hood Q_p/Q_(p-1) elements, statics or modal analysis, run on a\n"
    "list of global refinements (a refinement study). Direct solver on one\n"
    "process, or (Linear solver/Method = AMG, statics) distributed over\n"
    "the processes of mpirun with Trilinos and algebraic multigrid.\n"
    "\n"
    "Options:\n"
    "  -h, --help                 this text\n"
    "  --print-parameters [DIM] [FORMAT]\n"
    "                             every parameter with its default and\n"
    "                             documentation (DIM = 2 or 3; default 2),\n"
    "                             in parameter-file syntax (FORMAT = prm,\n"
    "                             the default) or as JSON (FORMAT = json)\n"
    "\n"
    "Documentation: doc/fe_reference.md.\n";

  template <int dim>
  void
  run(const std::string &file)
  {
    dealii::ParameterHandler prm;
    mpm::fe_reference::AllParameters<dim>::declare_parameters(prm);
    mpm::Parameters::parse_file(prm, file);
    mpm::fe_reference::AllParameters<dim> parameters;
    parameters.file_name = file;
    try
      {
        mpm::parse_with_range_check(
          [&]() { parameters.parse_parameters(prm); });
      }
    catch (const mpm::InputError &e)
      {
        throw mpm::InputError("Error in the parameter file '" + file +
                              "':\n    " + e.what());
      }
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (n_ranks > 1 && parameters.solver.method ==
                         mpm::fe_reference::LinearSolver::Method::direct)
      throw mpm::InputError(
        "Error in the parameter file '" + file +
        "':\n    Linear solver/Method = direct runs on one process, not on " +
        std::to_string(n_ranks) +
        " (set Method = AMG to distribute the mesh, or run without mpirun)");
    // one process prints
    std::ostream  null_stream(nullptr);
    std::ostream &log =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ?
        std::cout :
        null_stream;
    try
      {
        mpm::fe_reference::run_refinement_study(parameters, log);
      }
    catch (const mpm::InputError &e)
      {
        // found while solving (a point outside the body, a free body)
        throw mpm::InputError("Error in the parameter file '" + file +
                              "':\n    " + e.what());
      }
  }

  template <int dim>
  void
  print_parameters(const dealii::ParameterHandler::OutputStyle style)
  {
    dealii::ParameterHandler prm;
    mpm::fe_reference::AllParameters<dim>::declare_parameters(prm);
    prm.set("Dimension", std::to_string(dim));
    prm.print_parameters(std::cout, style);
  }
} // namespace

int
main(int argc, char **argv)
{
  // the direct solver is serial; Linear solver/Method = AMG distributes
  // the mesh over the processes
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  std::string file;
  for (int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      if (a == "-h" || a == "--help")
        {
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
              std::cerr << "mpm-fe: --print-parameters: unknown format '" << f
                        << "' (prm or json)\n";
              return 1;
            }
          if (d == "3")
            print_parameters<3>(*style);
          else
            print_parameters<2>(*style);
          return 0;
        }
      else if (!a.empty() && a[0] == '-')
        {
          std::cerr << "mpm-fe: unknown option '" << a << "'\n\n" << usage;
          return 1;
        }
      else if (file.empty())
        file = a;
      else
        {
          std::cerr << "mpm-fe: more than one parameter file given\n";
          return 1;
        }
    }
  if (file.empty())
    {
      std::cerr << usage;
      return 1;
    }

  try
    {
      const auto pre = mpm::Parameters::read_preamble(file);
      if (pre.dimension == 2)
        run<2>(file);
      else if (pre.dimension == 3)
        run<3>(file);
      else
        throw mpm::InputError("Error in the parameter file '" + file +
                              "':\n    Dimension = 1: mpm-fe solves 2D and "
                              "3D problems");
    }
  catch (const mpm::InputError &e)
    {
      // every process meets the same error; one reports it
      if (root)
        std::cerr << "mpm-fe: error: " << e.what() << "\nNothing was written."
                  << std::endl;
      return 1;
    }
  catch (const mpm::RuntimeError &e)
    {
      if (root)
        std::cerr << "mpm-fe: the computation stopped " << e.what()
                  << "\nNothing was written." << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "mpm-fe: internal error: " << e.what() << std::endl;
      return 3;
    }
  return 0;
}
