#include <deal.II/grid/grid_in.h>

#include <mpm/grid/mesh_reader.h>
#include <mpm/utilities/input_error.h>

#include <filesystem>
#include <fstream>

namespace mpm
{
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
        throw InputError(
          entry + " = '" + file_name +
          "': cannot read the mesh: " + clean_dealii_message(e.what()));
      }
    if (tria.n_global_active_cells() == 0)
      throw InputError(entry + " = '" + file_name + "': the mesh has no cells");
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
