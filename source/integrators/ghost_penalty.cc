#include <deal.II/base/mpi.h>

#include <mpm/integrators/ghost_penalty.h>
#include <mpm/utilities/input_error.h>

#include <algorithm>
#include <cmath>

namespace mpm
{
  using namespace dealii;

  namespace
  {
    // The two-point Gauss rule on [0, 1].
    const double gauss_low  = 0.5 - 0.5 / std::sqrt(3.);
    const double gauss_high = 0.5 + 0.5 / std::sqrt(3.);

    /// |cell| by the 2^d-point Gauss rule (exact for a Q1 cell).
    template <int dim>
    double
    measure(const shape_functions::Q1Cell<dim> &cell)
    {
      double V = 0;
      for (unsigned int q = 0; q < (1u << dim); ++q)
        {
          Point<dim> xi;
          for (unsigned int e = 0; e < dim; ++e)
            xi[e] = ((q >> e) & 1) ? gauss_high : gauss_low;
          V += std::abs(determinant(cell.jacobian(xi))) / (1u << dim);
        }
      return V;
    }
  } // namespace

  template <int dim>
  double
  GhostPenalty<dim>::youngs_modulus(const std::vector<Body<dim>> &bodies)
  {
    double E_max = 0;
    for (const auto &body : bodies)
      {
        double E = 0, nu = 0;
        if (!body.is_rigid() && body.material->elastic_moduli(E, nu))
          E_max = std::max(E_max, E);
      }
    if (!(E_max > 0))
      throw InputError(
        "Implicit solver/Ghost penalty scales with the bodies' largest "
        "Young's modulus, but no deformable body's material has one; set "
        "Ghost penalty = 0");
    return E_max;
  }

  template <int dim>
  void
  GhostPenalty<dim>::reinit(const BackgroundGrid<dim> &grid)
  {
    candidates.clear();
    faces.clear();
    for (const auto &cell : grid.owned_cells())
      for (const unsigned int f : cell->face_indices())
        {
          const unsigned int c  = cell->active_cell_index();
          const unsigned int nb = grid.face_neighbor(c, f);
          if (nb == BackgroundGrid<dim>::outside_grid ||
              nb == BackgroundGrid<dim>::unknown_cell)
            continue;
          const auto neighbor = cell->neighbor(f);
          const bool mine     = neighbor->is_locally_owned() ?
                                  c < nb :
                                  cell->subdomain_id() < neighbor->subdomain_id();
          if (mine)
            candidates.push_back({c, f, nb});
        }
  }

  template <int dim>
  typename NodalLinearSystem<dim>::NodeGroups
  GhostPenalty<dim>::couplings(const BackgroundGrid<dim> &grid) const
  {
    typename NodalLinearSystem<dim>::NodeGroups groups;
    if (!enabled())
      return groups;
    constexpr unsigned int nv = BackgroundGrid<dim>::n_vertices;
    for (const Face &face : candidates)
      {
        groups.nodes.insert(groups.nodes.end(),
                            grid.nodes(face.cell),
                            grid.nodes(face.cell) + nv);
        groups.nodes.insert(groups.nodes.end(),
                            grid.nodes(face.neighbor),
                            grid.nodes(face.neighbor) + nv);
        groups.close_group();
      }
    return groups;
  }

  template <int dim>
  void
  GhostPenalty<dim>::select_faces(const BackgroundGrid<dim> &grid,
                                  const std::vector<char>   &active,
                                  const NodalVector         &support,
                                  const NodalVector         &full_support)
  {
    faces.clear();
    if (!enabled())
      return;
    constexpr unsigned int nv = BackgroundGrid<dim>::n_vertices;
    // A cell takes part if all its nodes are unknowns; it is weak if one
    // of them is covered by less than a quarter of its support.
    const auto all_active = [&](const unsigned int c) {
      const unsigned int *n = grid.nodes(c);
      return std::all_of(n, n + nv, [&](const unsigned int i) {
        return active[i] != 0;
      });
    };
    const auto weak = [&](const unsigned int c) {
      const unsigned int *n = grid.nodes(c);
      return std::any_of(n, n + nv, [&](const unsigned int i) {
        return support.local_element(i) < 0.25 * full_support.local_element(i);
      });
    };
    for (const Face &face : candidates)
      if (all_active(face.cell) && all_active(face.neighbor) &&
          (weak(face.cell) || weak(face.neighbor)))
        faces.push_back(face_matrix(grid, face));
  }

  template <int dim>
  void
  GhostPenalty<dim>::select_all_faces(const BackgroundGrid<dim> &grid)
  {
    faces.clear();
    for (const Face &face : candidates)
      faces.push_back(face_matrix(grid, face));
  }

  template <int dim>
  typename GhostPenalty<dim>::FaceMatrix
  GhostPenalty<dim>::face_matrix(const BackgroundGrid<dim> &grid,
                                 const Face                &face) const
  {
    FaceMatrix                 result;
    std::vector<unsigned int> &nodes = result.nodes;
    FullMatrix<double>        &M     = result.M;
    constexpr unsigned int     nv    = BackgroundGrid<dim>::n_vertices;
    const auto                &own   = grid.geometry(face.cell);
    const auto                &other = grid.geometry(face.neighbor);
    const unsigned int        *a     = grid.nodes(face.cell);
    const unsigned int        *b     = grid.nodes(face.neighbor);
    // The face's nodes: the cell's, then the neighbour's not on the face.
    nodes.assign(a, a + nv);
    unsigned int in_list[nv];
    for (unsigned int v = 0; v < nv; ++v)
      {
        const auto k = std::find(a, a + nv, b[v]) - a;
        if (k < int(nv))
          in_list[v] = k;
        else
          {
            in_list[v] = nodes.size();
            nodes.push_back(b[v]);
          }
      }
    const unsigned int n = nodes.size();
    M.reinit(n, n);

    // h: the mean of the two cells' sizes |cell|^(1/d)
    const double h = std::pow(0.5 * (measure(own) + measure(other)), 1. / dim);
    // Gauss points of the face: xi_d = side in the normal direction d.
    const unsigned int d    = face.face / 2;
    const double       side = face.face % 2;
    Tensor<1, dim>     normal_ref;
    normal_ref[d] = side > 0 ? 1. : -1.;
    Tensor<1, dim>      grad_own[nv], grad_other[nv];
    std::vector<double> jump(n);
    Point<dim>          centre; // the start of the inverse map
    for (unsigned int e = 0; e < dim; ++e)
      centre[e] = 0.5;
    for (unsigned int q = 0; q < (1u << (dim - 1)); ++q)
      {
        Point<dim> xi;
        double     weight = 1;
        for (unsigned int e = 0, k = 0; e < dim; ++e)
          if (e == d)
            xi[e] = side;
          else
            {
              xi[e] = ((q >> k++) & 1) ? gauss_high : gauss_low;
              weight *= 0.5;
            }
        // Nanson: n ds = det(J) J^-T N_ref ds_ref
        const Tensor<2, dim> J = own.jacobian(xi);
        const Tensor<1, dim> area =
          determinant(J) * (transpose(invert(J)) * normal_ref);
        const double         ds       = area.norm() * weight;
        const Tensor<1, dim> normal   = area / area.norm();
        const Point<dim>     xi_other = other.inverse_map(own.map(xi), centre);
        own.gradients(xi, grad_own);
        other.gradients(xi_other, grad_other);
        // [[dN_a/dn]] = dN_a/dn from the cell minus that from the neighbour
        std::fill(jump.begin(), jump.end(), 0.);
        for (unsigned int v = 0; v < nv; ++v)
          {
            jump[v] += grad_own[v] * normal;
            jump[in_list[v]] -= grad_other[v] * normal;
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            M(i, j) += scale * h * ds * jump[i] * jump[j];
      }
    return result;
  }

  template <int dim>
  void
  GhostPenalty<dim>::add_to_system(const NodalVector      &u,
                                   const bool              with_matrix,
                                   NodalLinearSystem<dim> &system,
                                   NodalVector            &internal_force) const
  {
    FullMatrix<double>                   K;
    Vector<double>                       rhs;
    std::vector<types::global_dof_index> indices;
    for (const auto &[nodes, M] : faces)
      {
        const unsigned int n = nodes.size();
        rhs.reinit(n * dim);
        if (with_matrix)
          K.reinit(n * dim, n * dim);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int c = 0; c < dim; ++c)
            {
              double f = 0;
              for (unsigned int j = 0; j < n; ++j)
                {
                  f += M(i, j) * u.local_element(nodes[j] * dim + c);
                  if (with_matrix)
                    K(i * dim + c, j * dim + c) = M(i, j);
                }
              rhs(i * dim + c) = -f;
              internal_force.local_element(nodes[i] * dim + c) += f;
            }
        system.node_indices(nodes.data(), n, indices);
        if (with_matrix)
          system.add_cell(K, rhs, indices);
        else
          system.add_cell_rhs(rhs, indices);
      }
  }

  template <int dim>
  double
  GhostPenalty<dim>::form(const NodalVector &u,
                          const NodalVector &w,
                          const MPI_Comm     comm) const
  {
    double g = 0;
    for (const auto &[nodes, M] : faces)
      {
        for (unsigned int i = 0; i < nodes.size(); ++i)
          for (unsigned int j = 0; j < nodes.size(); ++j)
            for (unsigned int c = 0; c < dim; ++c)
              g += w.local_element(nodes[i] * dim + c) * M(i, j) *
                   u.local_element(nodes[j] * dim + c);
      }
    return Utilities::MPI::sum(g, comm);
  }

  template class GhostPenalty<1>;
  template class GhostPenalty<2>;
  template class GhostPenalty<3>;
} // namespace mpm
