#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <mpm/materials/material.h>

#include <map>
#include <string>
#include <vector>

/**
 * The parameter file of mpm-fe, the finite-element reference solver. The
 * preamble (Dimension, Kinematic assumption, Constants) and the Material
 * subsection are the ones of the mpm parameter file, so a body's material
 * can be copied between the two; the rest is FE-specific.
 */
namespace mpm
{
  namespace fe_reference
  {
    /// The solid: a box, a (bi/tri)linearly mapped box, or a mesh file.
    template <int dim>
    struct Geometry
    {
      enum class Type
      {
        box,
        quadrilateral, ///< the unit box mapped onto 2^dim corners
        mesh_file
      };
      Type                            type = Type::box;
      dealii::Point<dim>              lower, upper;
      std::vector<dealii::Point<dim>> corners; ///< deal.II vertex order
      std::vector<unsigned int>       subdivisions;
      std::string                     mesh_file;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Linear isotropic elasticity, read from the mpm Material subsection.
    struct Material
    {
      double density        = 1;
      double youngs_modulus = 1;
      double poissons_ratio = 0;

      /// nu = 0.5 (1/lambda = 0) is accepted only by the mixed formulation.
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const bool                incompressible_allowed);
    };

    /// Boundary conditions per boundary id, loads as muparser expressions.
    struct BoundaryConditions
    {
      std::vector<dealii::types::boundary_id> clamped, slip, prescribed,
        traction_ids;
      std::string prescribed_displacement; ///< of x, y(, z)
      std::string traction;                ///< of x, y(, z)
      std::string body_force;              ///< per unit mass

      /// Whether a clamped or prescribed boundary removes the rigid modes.
      bool
      has_dirichlet() const
      {
        return !clamped.empty() || !prescribed.empty();
      }

      static void
      declare_parameters(dealii::ParameterHandler &prm, const int dim);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// Elements and the refinement study.
    struct Discretisation
    {
      enum class Formulation
      {
        displacement, ///< Q_p displacement
        mixed         ///< Taylor-Hood Q_p / Q_(p-1), displacement-pressure
      };
      Formulation               formulation = Formulation::displacement;
      unsigned int              degree      = 2;
      std::vector<unsigned int> refinements; ///< global refinements per run

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// How K u = f is solved.
    struct LinearSolver
    {
      enum class Method
      {
        direct, ///< UMFPACK, serial
        amg     ///< distributed Trilinos: AMG-preconditioned CG or MINRES
      };
      Method       method         = Method::direct;
      double       tolerance      = 1e-10; ///< relative to |f|
      unsigned int max_iterations = 10000;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// What is computed and which number is the reference value.
    template <int dim>
    struct Analysis
    {
      enum class Type
      {
        statics,
        modal
      };
      Type         type    = Type::statics;
      unsigned int n_modes = 3;
      /// statics: the displacement is evaluated at these points; the
      /// first one's Component of interest is the quantity of interest
      std::vector<dealii::Point<dim>> points;
      unsigned int component       = dim - 1; ///< statics: of interest
      double       reference_value = 0;       ///< 0: none
      double       required_change = 0;       ///< 0: no requirement

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    struct Output
    {
      std::string directory = "output-fe";
      bool        write_vtu = true;
      std::string test_summary;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    template <int dim>
    struct AllParameters
    {
      std::string                   file_name;
      KinematicAssumption           kinematics;
      std::map<std::string, double> constants;
      Geometry<dim>                 geometry;
      Material                      material;
      BoundaryConditions            boundary;
      Discretisation                discretisation;
      LinearSolver                  solver;
      Analysis<dim>                 analysis;
      Output                        output;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Read and cross-check; InputError names the offending entry.
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace fe_reference
} // namespace mpm
