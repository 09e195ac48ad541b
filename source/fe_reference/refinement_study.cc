#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/tria.h>

#include <mpm/fe_reference/distributed_elastic_system.h>
#include <mpm/fe_reference/elastic_system.h>
#include <mpm/fe_reference/modal_analysis.h>
#include <mpm/fe_reference/reference_mesh.h>
#include <mpm/fe_reference/refinement_study.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      bool
      is_modal(const AllParameters<dim> &parameters)
      {
        return parameters.analysis.type == Analysis<dim>::Type::modal;
      }

      /// "48,60" for the column names
      template <int dim>
      std::string
      point_name(const Point<dim> &p)
      {
        std::ostringstream s;
        s << p;
        std::string name = s.str();
        for (auto &c : name)
          if (c == ' ')
            c = ',';
        return name;
      }

      /// Column names of the values of a row.
      template <int dim>
      std::vector<std::string>
      value_names(const AllParameters<dim> &parameters)
      {
        std::vector<std::string> names;
        if (is_modal(parameters))
          for (unsigned int k = 1; k <= parameters.analysis.n_modes; ++k)
            names.push_back("omega_" + std::to_string(k));
        else
          for (const auto &p : parameters.analysis.points)
            for (unsigned int d = 0; d < dim; ++d)
              names.push_back(std::string("u_") + "xyz"[d] + "(" +
                              point_name(p) + ")");
        return names;
      }

      template <int dim>
      std::string
      quantity_name(const AllParameters<dim> &parameters)
      {
        if (is_modal(parameters))
          return "T_1";
        return std::string("u_") + "xyz"[parameters.analysis.component] + "(" +
               point_name(parameters.analysis.points[0]) + ")";
      }

      template <int dim>
      void
      print_row(std::ostream &out, const StudyRow &row, const bool first)
      {
        out << std::setw(6) << row.refinements << std::setw(9) << row.cells
            << std::setw(10) << row.dofs;
        out << std::scientific << std::setprecision(8);
        for (const double v : row.values)
          out << std::setw(17) << v;
        out << std::setw(17) << row.quantity;
        if (first)
          out << std::setw(12) << "-";
        else
          out << std::setw(12) << std::setprecision(3) << row.change;
        out << std::defaultfloat << std::endl;
      }

      /// The displacement at the points of interest, and the quantity.
      template <int dim, typename System>
      void
      record_point_values(const System             &system,
                          const AllParameters<dim> &parameters,
                          StudyRow                 &row)
      {
        for (const auto &p : parameters.analysis.points)
          {
            const auto u = system.point_value(p);
            for (unsigned int d = 0; d < dim; ++d)
              row.values.push_back(u[d]);
          }
        row.quantity = row.values[parameters.analysis.component];
      }

    } // namespace

    template <int dim>
    std::vector<StudyRow>
    run_refinement_study(const AllParameters<dim> &parameters,
                         std::ostream             &log)
    {
      const bool        modal = is_modal(parameters);
      const std::string input_folder =
        std::filesystem::path(parameters.file_name).parent_path().string();

      log << "mpm-fe: " << (modal ? "modal analysis" : "static analysis")
          << ", "
          << (parameters.discretisation.formulation ==
                  Discretisation::Formulation::mixed ?
                "mixed Q" + std::to_string(parameters.discretisation.degree) +
                  "/Q" + std::to_string(parameters.discretisation.degree - 1) :
                "Q" + std::to_string(parameters.discretisation.degree))
          << ", " << to_string(parameters.kinematics) << "\n";
      log << std::setw(6) << "refs" << std::setw(9) << "cells" << std::setw(10)
          << "dofs";
      for (const auto &name : value_names(parameters))
        log << std::setw(17) << name;
      log << std::setw(17) << quantity_name(parameters) << std::setw(12)
          << "rel.change" << std::endl;

      std::vector<StudyRow> rows;
      const bool            distributed =
        parameters.solver.method == LinearSolver::Method::amg;
      const MPI_Comm     comm = MPI_COMM_WORLD;
      const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
      Triangulation<dim> tria;
      parallel::distributed::Triangulation<dim> distributed_tria(comm);
      // the finest system is kept for the vtu output
      std::unique_ptr<ElasticSystem<dim>>            system;
      std::unique_ptr<DistributedElasticSystem<dim>> distributed_system;
      Modes                                          modes;
      for (const unsigned int r : parameters.discretisation.refinements)
        {
          StudyRow row;
          row.refinements = r;
          if (distributed)
            {
              distributed_system.reset();
              create_coarse_mesh(distributed_tria,
                                 parameters.geometry,
                                 input_folder);
              distributed_tria.refine_global(r);
              distributed_system =
                std::make_unique<DistributedElasticSystem<dim>>(
                  parameters, distributed_tria);
              distributed_system->setup();
              row.cells             = distributed_tria.n_global_active_cells();
              row.dofs              = distributed_system->n_dofs();
              const auto statistics = distributed_system->solve_static();
              row.linear_iterations = statistics.iterations;
              row.assembly_seconds  = statistics.assembly_seconds;
              row.amg_setup_seconds = statistics.amg_setup_seconds;
              row.solve_seconds     = statistics.solve_seconds;
              record_point_values(*distributed_system, parameters, row);
            }
          else
            {
              system.reset();
              create_coarse_mesh(tria, parameters.geometry, input_folder);
              tria.refine_global(r);
              system = std::make_unique<ElasticSystem<dim>>(parameters, tria);
              system->setup();
              row.cells = tria.n_active_cells();
              row.dofs  = system->dof_handler().n_dofs();
              if (modal)
                {
                  system->assemble_stiffness_and_mass();
                  modes = compute_modes(*system, parameters.analysis.n_modes);
                  for (const double w2 : modes.omega_squared)
                    row.values.push_back(std::sqrt(w2));
                  row.quantity         = 2 * M_PI / row.values[0];
                  row.rigid_body_modes = modes.n_rigid_body_modes;
                }
              else
                {
                  system->solve_static();
                  record_point_values(*system, parameters, row);
                }
            }
          if (!rows.empty())
            row.change = std::abs(row.quantity - rows.back().quantity) /
                         std::max(std::abs(row.quantity), 1e-300);
          print_row<dim>(log, row, rows.empty());
          if (distributed)
            log << "        " << row.linear_iterations << " "
                << (distributed_system->mixed() ? "MINRES" : "CG")
                << " iterations with AMG on "
                << Utilities::MPI::n_mpi_processes(comm)
                << " processes; wall time: assembly " << std::fixed
                << std::setprecision(2) << row.assembly_seconds
                << " s, AMG set-up " << row.amg_setup_seconds << " s, solve "
                << row.solve_seconds << " s" << std::defaultfloat << std::endl;
          rows.push_back(row);
        }

      const StudyRow &last = rows.back();
      const double    ref  = parameters.analysis.reference_value;
      log << std::setprecision(8)
          << "reference value: " << quantity_name(parameters) << " = "
          << last.quantity;
      if (rows.size() > 1)
        log << " (relative change over the last two refinements "
            << std::setprecision(3) << last.change << ")";
      log << "\n";
      if (rows.size() > 2)
        {
          // Richardson: with the observed ratio r of successive changes the
          // remaining error of the last run is about its change / (r - 1)
          const double q0 = rows[rows.size() - 3].quantity;
          const double q1 = rows[rows.size() - 2].quantity;
          const double q2 = last.quantity;
          const double r  = (q1 - q0) / (q2 - q1);
          if (std::isfinite(r) && r > 1)
            log << "Richardson estimate from the last three runs "
                << "(ratio of changes " << std::setprecision(3) << r
                << "): " << std::setprecision(8) << q2 + (q2 - q1) / (r - 1)
                << "\n";
        }
      if (modal)
        log << "first eigenfrequency f_1 = " << std::setprecision(8)
            << last.values[0] / (2 * M_PI) << " Hz"
            << (last.rigid_body_modes > 0 ?
                  "; skipped " + std::to_string(last.rigid_body_modes) +
                    " rigid-body (near-zero) modes" :
                  std::string())
            << "\n";
      if (ref != 0)
        log << "ratio to the Reference value " << std::setprecision(8) << ref
            << ": " << last.quantity / ref << "\n";
      if (parameters.analysis.required_change > 0 &&
          !(rows.size() > 1 &&
            last.change < parameters.analysis.required_change))
        log << "WARNING: the relative change " << last.change
            << " is not below the Required relative change "
            << parameters.analysis.required_change << ": add refinements\n";
      log << std::flush;

      // everything succeeded: now write
      namespace fs = std::filesystem;
      const fs::path dir(parameters.output.directory);
      if (root)
        {
          fs::create_directories(parameters.output.directory);
          std::ofstream csv(dir / "refinement_study.csv");
          csv << "refinements,cells,dofs";
          // a point's coordinates are separated by spaces here, not by
          // the field separator: u_x(48 60)
          for (auto name : value_names(parameters))
            {
              std::replace(name.begin(), name.end(), ',', ' ');
              csv << "," << name;
            }
          csv << "," << (modal ? "T_1" : "quantity") << ",relative_change";
          if (ref != 0)
            csv << ",ratio_to_reference";
          if (distributed)
            csv << ",linear_iterations,assembly_seconds,amg_setup_seconds,"
                   "solve_seconds";
          csv << "\n" << std::setprecision(12);
          for (const auto &row : rows)
            {
              csv << row.refinements << "," << row.cells << "," << row.dofs;
              for (const double v : row.values)
                csv << "," << v;
              csv << "," << row.quantity << "," << row.change;
              if (ref != 0)
                csv << "," << row.quantity / ref;
              if (distributed)
                csv << "," << row.linear_iterations << ","
                    << row.assembly_seconds << "," << row.amg_setup_seconds
                    << "," << row.solve_seconds;
              csv << "\n";
            }
        }
      // the directory exists before any process writes into it
      MPI_Barrier(comm);
      if (parameters.output.write_vtu && distributed)
        distributed_system->write_vtu((dir / "solution.vtu").string());
      else if (parameters.output.write_vtu)
        {
          if (modal)
            {
              std::vector<const Vector<double> *> fields;
              std::vector<std::string>            names;
              for (unsigned int k = 0; k < modes.shapes.size(); ++k)
                {
                  fields.push_back(&modes.shapes[k]);
                  names.push_back("mode_" + std::to_string(k + 1));
                }
              system->write_vtu((dir / "modes.vtu").string(), fields, names);
            }
          else
            system->write_vtu((dir / "solution.vtu").string(),
                              {&system->solution()},
                              {"displacement"});
        }
      if (!parameters.output.test_summary.empty() && root)
        {
          std::ofstream out(parameters.output.test_summary);
          out << std::scientific << std::setprecision(5);
          for (const auto &row : rows)
            {
              out << "refinements " << row.refinements << " dofs " << row.dofs;
              for (unsigned int k = 0; k < row.values.size(); ++k)
                out << " " << value_names(parameters)[k] << " "
                    << row.values[k];
              out << " quantity " << row.quantity << "\n";
            }
        }
      return rows;
    }

    template std::vector<StudyRow>
    run_refinement_study(const AllParameters<2> &, std::ostream &);
    template std::vector<StudyRow>
    run_refinement_study(const AllParameters<3> &, std::ostream &);
  } // namespace fe_reference
} // namespace mpm
