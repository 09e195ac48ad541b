#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

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

    /**
     * Build @p out from @p in, with the vertices of every cell in the
     * order of the coordinate axes (vertex i at the corner whose bit d
     * says min or max in direction d) if every cell is an axis-parallel
     * box. A mesh generator numbers a structured block's vertices in its
     * own order, which leaves the boxes' axes permuted; in axis order the
     * grid is Cartesian (grid/background_grid.h) and takes the fast path.
     * Boundary and material ids are kept.
     */
    template <int dim>
    void
    create_in_axis_order(const dealii::Triangulation<dim> &in,
                         dealii::Triangulation<dim>       &out)
    {
      using namespace dealii;
      if constexpr (dim == 1)
        {
          // 1D cells are ordered; their boundary ids live on vertices
          out.copy_triangulation(in);
          return;
        }
      else
        {
          constexpr unsigned int n_vertices =
            GeometryInfo<dim>::vertices_per_cell;
          std::vector<Point<dim>>    vertices = in.get_vertices();
          std::vector<CellData<dim>> cells, as_read;
          SubCellData                boundary;
          bool                       all_boxes = dim > 1;
          for (const auto &cell : in.active_cell_iterators())
            {
              CellData<dim> c(n_vertices);
              for (unsigned int v = 0; v < n_vertices; ++v)
                c.vertices[v] = cell->vertex_index(v);
              c.material_id = cell->material_id();
              c.manifold_id = cell->manifold_id();
              as_read.push_back(c);
              Point<dim> lo = cell->vertex(0), hi = lo;
              for (unsigned int v = 1; v < n_vertices; ++v)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    lo[d] = std::min(lo[d], cell->vertex(v)[d]);
                    hi[d] = std::max(hi[d], cell->vertex(v)[d]);
                  }
              const double              tol     = 1e-10 * cell->diameter();
              unsigned int              corners = 0; // bit c: corner c taken
              std::vector<unsigned int> ordered(n_vertices);
              for (unsigned int v = 0; v < n_vertices && all_boxes; ++v)
                {
                  unsigned int corner = 0;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      const double x = cell->vertex(v)[d];
                      if (std::abs(x - hi[d]) <= tol && hi[d] - lo[d] > tol)
                        corner |= 1u << d;
                      else if (!(std::abs(x - lo[d]) <= tol))
                        all_boxes = false;
                    }
                  if (corners & (1u << corner))
                    all_boxes = false;
                  corners |= 1u << corner;
                  ordered[corner] = cell->vertex_index(v);
                }
              if (all_boxes)
                c.vertices = ordered;
              cells.push_back(c);
              for (const unsigned int f : cell->face_indices())
                if (cell->at_boundary(f))
                  {
                    const auto        face = cell->face(f);
                    CellData<dim - 1> b(
                      GeometryInfo<dim - 1>::vertices_per_cell);
                    for (unsigned int i = 0; i < b.vertices.size(); ++i)
                      b.vertices[i] = face->vertex_index(i);
                    b.boundary_id = face->boundary_id();
                    if constexpr (dim == 2)
                      boundary.boundary_lines.push_back(b);
                    if constexpr (dim == 3)
                      boundary.boundary_quads.push_back(b);
                  }
            }
          if (!all_boxes) // as read: deal.II has oriented them consistently
            cells.swap(as_read);
          GridTools::delete_unused_vertices(vertices, cells, boundary);
          out.create_triangulation(vertices, cells, boundary);
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

    const std::string          ext = path.extension().string();
    dealii::Triangulation<dim> serial;
    dealii::GridIn<dim>        in(serial);
    std::ifstream              stream(path);
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
    if (serial.n_active_cells() == 0)
      throw InputError(entry + " = '" + file_name + "': the mesh has no cells");
    check_cells(serial, entry + " = '" + file_name + "'");
    create_in_axis_order(serial, tria);
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
