#pragma once

#include <deal.II/base/tensor.h>

#include <vector>

namespace mpm
{
  /**
   * The shape-function weights of one cell's particles in the implicit
   * step, with the nodes numbered in the cell's node list: the union of
   * the nodes its particles reach, in the order first reached. In standard
   * MPM that is the cell's vertices in their order; a domain family's
   * particles also reach the nodes of neighbouring cells. A particle's
   * entries are merged by node (GIMP lists a node once per cell of its
   * box). After the cell's last particle, make_dense() gives every
   * particle a gradient for each node of the list (zero where it does not
   * reach), which the cell sums of the volumetric smoothing and the
   * tangent's columns need.
   */
  template <int dim>
  class CellStencils
  {
  public:
    /// For a grid of @p n_local_nodes nodes (owned and ghost).
    explicit CellStencils(const unsigned int n_local_nodes = 0)
      : slot(n_local_nodes, -1)
    {}

    /// Start a cell (the list of the last one is forgotten).
    void
    begin_cell()
    {
      for (const unsigned int i : node_list)
        slot[i] = -1;
      node_list.clear();
      first.assign(1, 0);
      local.clear();
      values.clear();
      gradients.clear();
      faces.clear();
    }

    /**
     * Add the particle whose weights @p w have just been evaluated;
     * @p face (may be null): the weights of its loaded face, one per
     * entry of @p w.
     */
    template <typename Weights>
    void
    add(const Weights &w, const double *face)
    {
      const unsigned int start = local.size();
      for (unsigned int k = 0; k < w.size(); ++k)
        {
          const unsigned int l = local_index(w.node(k));
          unsigned int       e = start;
          while (e < local.size() && local[e] != l)
            ++e;
          if (e == local.size())
            {
              local.push_back(l);
              values.push_back(0.);
              gradients.emplace_back();
              faces.push_back(0.);
            }
          values[e] += w.value(k);
          gradients[e] += w.gradient(k);
          if (face)
            faces[e] += face[k];
        }
      first.push_back(local.size());
    }

    unsigned int
    n_particles() const
    {
      return first.size() - 1;
    }
    /// The cell's node list: node-local indices of the grid.
    unsigned int
    n_nodes() const
    {
      return node_list.size();
    }
    const unsigned int *
    nodes() const
    {
      return node_list.data();
    }

    /// Particle p's entries are begin(p), ..., end(p) - 1.
    unsigned int
    begin(const unsigned int p) const
    {
      return first[p];
    }
    unsigned int
    end(const unsigned int p) const
    {
      return first[p + 1];
    }
    /// Entry e: its node's place in the list, S, grad S, face weight.
    unsigned int
    node(const unsigned int e) const
    {
      return local[e];
    }
    double
    value(const unsigned int e) const
    {
      return values[e];
    }
    const dealii::Tensor<1, dim> &
    gradient(const unsigned int e) const
    {
      return gradients[e];
    }
    double
    face(const unsigned int e) const
    {
      return faces[e];
    }

    /// After the cell's last particle: the dense gradients.
    void
    make_dense()
    {
      const unsigned int n = n_nodes();
      dense.assign(n_particles() * n, dealii::Tensor<1, dim>());
      reached.assign(n_particles() * n, 0);
      for (unsigned int p = 0; p < n_particles(); ++p)
        for (unsigned int e = begin(p); e < end(p); ++e)
          {
            dense[p * n + local[e]]   = gradients[e];
            reached[p * n + local[e]] = 1;
          }
    }
    /// Particle p's gradient for every node of the list (make_dense()).
    const dealii::Tensor<1, dim> *
    dense_gradients(const unsigned int p) const
    {
      return dense.data() + p * n_nodes();
    }
    /// Whether particle p reaches node l of the list (make_dense()).
    bool
    reaches(const unsigned int p, const unsigned int l) const
    {
      return reached[p * n_nodes() + l];
    }

  private:
    unsigned int
    local_index(const unsigned int i)
    {
      if (slot[i] < 0)
        {
          slot[i] = node_list.size();
          node_list.push_back(i);
        }
      return slot[i];
    }

    std::vector<int>          slot; ///< per grid node: place in the list
    std::vector<unsigned int> node_list;
    std::vector<unsigned int> first = {0}; ///< per particle: first entry
    std::vector<unsigned int> local;
    std::vector<double>       values;
    std::vector<dealii::Tensor<1, dim>> gradients;
    std::vector<double>                 faces;
    std::vector<dealii::Tensor<1, dim>> dense;
    std::vector<char>                   reached;
  };
} // namespace mpm
