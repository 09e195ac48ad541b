#include <deal.II/grid/grid_generator.h>

#include <mpm/grid/box_mesh.h>

namespace mpm
{
  template <int dim>
  void
  create_box_mesh(dealii::Triangulation<dim>      &tria,
                  const std::vector<unsigned int> &cells,
                  const dealii::Point<dim>        &lower,
                  const dealii::Point<dim>        &upper,
                  const bool                       refine)
  {
    // Largest k such that 2^k divides every direction's cell count.
    unsigned int k = 0;
    while (true)
      {
        bool divisible = true;
        for (const unsigned int n : cells)
          divisible = divisible && (n % (2u << k) == 0);
        if (!divisible)
          break;
        ++k;
      }
    std::vector<unsigned int> coarse(cells);
    for (auto &n : coarse)
      n >>= k;
    dealii::GridGenerator::subdivided_hyper_rectangle(
      tria, coarse, lower, upper, true);
    if (refine && k > 0)
      tria.refine_global(k);
  }

  template void
  create_box_mesh<1>(dealii::Triangulation<1> &,
                     const std::vector<unsigned int> &,
                     const dealii::Point<1> &,
                     const dealii::Point<1> &,
                     const bool);
  template void
  create_box_mesh<2>(dealii::Triangulation<2> &,
                     const std::vector<unsigned int> &,
                     const dealii::Point<2> &,
                     const dealii::Point<2> &,
                     const bool);
  template void
  create_box_mesh<3>(dealii::Triangulation<3> &,
                     const std::vector<unsigned int> &,
                     const dealii::Point<3> &,
                     const dealii::Point<3> &,
                     const bool);
} // namespace mpm
