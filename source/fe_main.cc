// mpm-fe, the finite-element reference solver: read `set Dimension`, then
// run the refinement study of the parameter file (statics or modal
// analysis). Errors the user can fix end with one message naming the file
// and parameter, and exit status 1; nothing is written.

#include <deal.II/base/mpi.h>

#include <mpm/fe_reference/parameters.h>
#include <mpm/fe_reference/refinement_study.h>
#include <mpm/parameters/parameters.h>
#include <mpm/utilities/input_error.h>

#include <iostream>
#include <string>

namespace
{
  const char *usage =
    "Usage: mpm-fe [options] FILE.prm\n"
    "\n"
    "Finite-element reference solver (serial): linear elasticity with Q_p\n"
    "or Taylor-Hood Q_p/Q_(p-1) elements, statics or modal analysis, run\n"
    "on a list of global refinements (a refinement study).\n"
    "\n"
    "Options:\n"
    "  -h, --help                 this text\n"
    "  --print-parameters [DIM]   every parameter with its default and\n"
    "                             documentation (DIM = 2 or 3; default 2)\n"
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
        parameters.parse_parameters(prm);
      }
    catch (const mpm::InputError &e)
      {
        throw mpm::InputError("Error in the parameter file '" + file +
                              "':\n    " + e.what());
      }
    try
      {
        mpm::fe_reference::run_refinement_study(parameters, std::cout);
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
  print_parameters()
  {
    dealii::ParameterHandler prm;
    mpm::fe_reference::AllParameters<dim>::declare_parameters(prm);
    prm.set("Dimension", std::to_string(dim));
    prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
  }
} // namespace

int
main(int argc, char **argv)
{
  // deal.II's PETSc/Trilinos-enabled build wants MPI initialised; the
  // solver itself is serial
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    {
      std::cerr << "mpm-fe: the reference solver is serial; run it without "
                   "mpirun\n";
      return 1;
    }

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
          if (i + 1 < argc && std::string(argv[i + 1]) == "3")
            print_parameters<3>();
          else
            print_parameters<2>();
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
      std::cerr << "mpm-fe: error: " << e.what() << "\nNothing was written."
                << std::endl;
      return 1;
    }
  catch (const mpm::RuntimeError &e)
    {
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
