#include <mpm/grid/active_nodes.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace mpm
{
  void
  ActiveNodes::reset(const dealii::Utilities::MPI::Partitioner &nodes)
  {
    n_owned = nodes.locally_owned_size();
    mark.assign(n_owned + nodes.n_ghost_indices(), 0);
    imports.clear();
    for (const auto &[begin, end] : nodes.import_indices())
      for (unsigned int i = begin; i < end; ++i)
        imports.push_back(i);
    // a node may be imported from several ranks
    std::sort(imports.begin(), imports.end());
    imports.erase(std::unique(imports.begin(), imports.end()), imports.end());
    active.clear();
    nonzero.clear();
    clear_marks();
  }

  void
  ActiveNodes::clear_marks()
  {
    std::fill(mark.begin(), mark.end(), 0);
    for (const unsigned int i : imports)
      mark[i] = 1;
  }

  void
  ActiveNodes::collect()
  {
    active.clear();
    // eight marks at a time: most of a large grid is empty
    unsigned int i = 0;
    for (; i + 8 <= n_owned; i += 8)
      {
        std::uint64_t word;
        std::memcpy(&word, mark.data() + i, 8);
        if (word != 0)
          for (unsigned int j = i; j < i + 8; ++j)
            if (mark[j])
              active.push_back(j);
      }
    for (; i < n_owned; ++i)
      if (mark[i])
        active.push_back(i);
  }

  void
  ActiveNodes::zero(NodalVector &v, const unsigned int nc)
  {
    const auto known = nonzero.find(&v);
    if (known == nonzero.end())
      {
        v = 0.;
        return;
      }
    double *const data = v.begin();
    for (const unsigned int i : known->second)
      std::fill(data + i * nc, data + (i + 1) * nc, 0.);
  }

  void
  ActiveNodes::zero_inactive(NodalVector &v, const unsigned int nc)
  {
    const auto known = nonzero.find(&v);
    if (known == nonzero.end())
      {
        // the ghosts are the owners' values, brought by
        // update_ghost_values()
        std::fill(v.begin(), v.begin() + n_owned * nc, 0.);
        return;
      }
    double *const data = v.begin();
    for (const unsigned int i : known->second)
      if (!mark[i])
        std::fill(data + i * nc, data + (i + 1) * nc, 0.);
  }

  void
  ActiveNodes::record(const NodalVector &v)
  {
    nonzero[&v] = active;
  }
} // namespace mpm
