// Helpers for the mpm-fe tests: parameters from parameter-file text, and
// the check lines of ../tests.h.
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <mpm/fe_reference/elastic_system.h>
#include <mpm/fe_reference/parameters.h>
#include <mpm/fe_reference/reference_mesh.h>

#include <memory>
#include <string>

#include "../tests.h"

namespace fe_test
{
  /// mpm-fe parameters from text (all entries declared, `Dimension` added).
  template <int dim>
  mpm::fe_reference::AllParameters<dim>
  parameters(const std::string &text)
  {
    dealii::ParameterHandler prm;
    mpm::fe_reference::AllParameters<dim>::declare_parameters(prm);
    prm.parse_input_from_string("set Dimension = " + std::to_string(dim) +
                                "\n" + text);
    mpm::fe_reference::AllParameters<dim> p;
    p.file_name = "test.prm";
    p.parse_parameters(prm);
    return p;
  }

  /// The coarse mesh of @p p (Geometry) and an ElasticSystem set up on it.
  template <int dim>
  struct MeshedSystem
  {
    explicit MeshedSystem(const mpm::fe_reference::AllParameters<dim> &p)
    {
      mpm::fe_reference::create_coarse_mesh(tria, p.geometry, "");
      system = std::make_unique<mpm::fe_reference::ElasticSystem<dim>>(p, tria);
      system->setup();
    }

    dealii::Triangulation<dim>                             tria;
    std::unique_ptr<mpm::fe_reference::ElasticSystem<dim>> system;
  };
} // namespace fe_test
