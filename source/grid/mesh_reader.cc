#include <deal.II/grid/grid_in.h>

#include <mpm/grid/mesh_reader.h>
#include <mpm/shape_functions/q1_cell.h>
#include <mpm/utilities/input_error.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace mpm
{
  namespace
  {
    template <int dim>
    std::string
    point_text(const dealii::Point<dim> &p)
    {
      std::string s = "(";
      for (unsigned int d = 0; d < dim; ++d)
        s += (d ? ", " : "") + std::to_string(p[d]);
      return s + ")";
    }

    /**
     * Every coarse cell must map the reference cell one to one: the
     * Jacobian determinant of the (bi/tri)linear map must be positive at
     * every vertex. That rejects inverted, flattened and bow-tie cells,
     * which the particle location and the stable step cannot handle.
     * (In 3D a positive determinant at the vertices is necessary, not
     * sufficient; it catches the usual mistakes.)
     */
    template <int dim>
    void
    check_cells(const dealii::Triangulation<dim> &tria, const std::string &what)
    {
      using Cell = shape_functions::Q1Cell<dim>;
      for (auto cell = tria.begin(0); cell != tria.end(0); ++cell)
        {
          std::array<dealii::Point<dim>, Cell::n_vertices> v;
          for (unsigned int i = 0; i < Cell::n_vertices; ++i)
            v[i] = cell->vertex(i);
          Cell geo;
          geo.reinit(v, 0.);
          const double size = cell->diameter();
          for (unsigned int i = 0; i < Cell::n_vertices; ++i)
            {
              dealii::Point<dim> xi;
              for (unsigned int d = 0; d < dim; ++d)
                xi[d] = (i >> d) & 1;
              if (!(determinant(geo.jacobian(xi)) >
                    1e-12 * std::pow(size, dim)))
                throw InputError(
                  what + ": the cell with centre " +
                  point_text(cell->center()) +
                  " is inverted or degenerate (zero or negative volume "
                  "near its vertex " +
                  point_text(v[i]) +
                  "); every cell must be convex, with its vertices in "
                  "the order the format prescribes");
            }
        }
    }
  } // namespace

  template <int dim>
  void
  read_mesh(dealii::Triangulation<dim> &tria,
            const std::string          &file_name,
            const std::string          &input_folder,
            const std::string          &entry)
  {
    namespace fs = std::filesystem;
    fs::path path(file_name);
    if (path.is_relative() && !input_folder.empty() &&
        fs::exists(fs::path(input_folder) / path))
      path = fs::path(input_folder) / path;
    if (!fs::exists(path))
      throw InputError(entry + " = '" + file_name +
                       "': file not found (looked next to the parameter "
                       "file and in the working directory)");

    const std::string   ext = path.extension().string();
    dealii::GridIn<dim> in(tria);
    std::ifstream       stream(path);
    try
      {
        if (ext == ".msh")
          in.read_msh(stream);
        else if (ext == ".inp" || ext == ".ucd")
          in.read_ucd(stream);
        else
          throw InputError(entry + " = '" + file_name +
                           "': unknown mesh format '" + ext +
                           "' (use .msh or .ucd/.inp)");
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        // deal.II's ExcIO carries a page of generic advice and no detail.
        std::string why = clean_dealii_message(e.what());
        if (why.find("An input/output error has occurred") != std::string::npos)
          why = std::string("it is not a valid ") +
                (ext == ".msh" ? "Gmsh" : "UCD") +
                " mesh (a truncated file, or another format)";
        throw InputError(entry + " = '" + file_name +
                         "': cannot read the mesh: " + why);
      }
    if (tria.n_global_active_cells() == 0)
      throw InputError(entry + " = '" + file_name + "': the mesh has no cells");
    check_cells(tria, entry + " = '" + file_name + "'");
  }

  template void
  read_mesh<1>(dealii::Triangulation<1> &,
               const std::string &,
               const std::string &,
               const std::string &);
  template void
  read_mesh<2>(dealii::Triangulation<2> &,
               const std::string &,
               const std::string &,
               const std::string &);
  template void
  read_mesh<3>(dealii::Triangulation<3> &,
               const std::string &,
               const std::string &,
               const std::string &);
} // namespace mpm
