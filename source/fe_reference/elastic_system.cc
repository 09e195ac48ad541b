#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <mpm/fe_reference/displacement_function.h>
#include <mpm/fe_reference/elastic_system.h>
#include <mpm/utilities/expression.h>
#include <mpm/utilities/input_error.h>

#include <fstream>
#include <limits>
#include <set>

namespace mpm
{
  namespace fe_reference
  {
    using namespace dealii;

    namespace
    {
      std::string
      coordinate_names(const int dim)
      {
        return dim == 2 ? "x,y" : "x,y,z";
      }

      /// Rigid-body motion k: translations along x, y(, z), then rotations
      /// about z (2D), or about x, y, z (3D); zero pressure.
      template <int dim>
      class RigidMotion : public Function<dim>
      {
      public:
        RigidMotion(const unsigned int k, const unsigned int n_components)
          : Function<dim>(n_components)
          , k(k)
        {}

        double
        value(const Point<dim> &x, const unsigned int c) const override
        {
          if (c >= dim)
            return 0;
          if (k < dim)
            return c == k ? 1. : 0.;
          // rotation about axis a: e_a x x
          const unsigned int a = dim == 2 ? 2 : k - dim;
          Tensor<1, 3>       x3, axis;
          for (unsigned int d = 0; d < dim; ++d)
            x3[d] = x[d];
          axis[a] = 1;
          return cross_product_3d(axis, x3)[c];
        }

      private:
        const unsigned int k;
      };

      template <int dim>
      std::unique_ptr<FESystem<dim>>
      make_element(const unsigned int degree, const bool mixed)
      {
        if (mixed)
          return std::make_unique<FESystem<dim>>(FE_Q<dim>(degree),
                                                 dim,
                                                 FE_Q<dim>(degree - 1),
                                                 1);
        return std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim);
      }
    } // namespace

    template <int dim>
    ElasticSystem<dim>::ElasticSystem(const AllParameters<dim> &parameters,
                                      const Triangulation<dim> &tria)
      : parameters(parameters)
      , is_mixed(parameters.discretisation.formulation ==
                 Discretisation::Formulation::mixed)
      , moduli(parameters.material.youngs_modulus,
               parameters.material.poissons_ratio,
               parameters.kinematics)
      , fe(make_element<dim>(parameters.discretisation.degree, is_mixed))
      // the mapping follows curved manifolds a mesh may carry; on the
      // straight-sided meshes of the Geometry subsection it is exact anyway
      , mapping(parameters.discretisation.degree)
      , dofs(tria)
    {
      if (is_mixed && !std::isfinite(moduli.inverse_lambda))
        throw InputError("Formulation = mixed needs Poisson's ratio > 0 "
                         "(the pressure equation divides by lambda)");
    }

    template <int dim>
    bool
    ElasticSystem<dim>::has_dirichlet_boundary() const
    {
      return !parameters.boundary.clamped.empty() ||
             !parameters.boundary.prescribed.empty();
    }

    template <int dim>
    void
    ElasticSystem<dim>::setup()
    {
      dofs.distribute_dofs(*fe);

      const FEValuesExtractors::Vector u(0);
      const ComponentMask              u_mask = fe->component_mask(u);
      const auto                      &bc     = parameters.boundary;

      // which ids the mesh has, so that a misspelled id is reported
      std::set<types::boundary_id> mesh_ids;
      for (const auto &face : dofs.get_triangulation().active_face_iterators())
        if (face->at_boundary())
          mesh_ids.insert(face->boundary_id());
      for (const auto *list :
           {&bc.clamped, &bc.slip, &bc.prescribed, &bc.traction_ids})
        for (const auto id : *list)
          if (mesh_ids.count(id) == 0)
            {
              std::string present;
              for (const auto m : mesh_ids)
                present += (present.empty() ? "" : ", ") + std::to_string(m);
              throw InputError("Boundary conditions: boundary id " +
                               std::to_string(id) +
                               " does not occur on the mesh (its boundary "
                               "ids: " +
                               present + "; see Geometry/Type)");
            }

      affine_constraints.clear();
      DoFTools::make_hanging_node_constraints(dofs, affine_constraints);
      // Dirichlet conditions first: the no-normal-flux constraints leave
      // dofs that are already constrained alone (clamped corners win).
      const Functions::ZeroFunction<dim> zero(fe->n_components());
      for (const auto id : bc.clamped)
        VectorTools::interpolate_boundary_values(
          mapping, dofs, id, zero, affine_constraints, u_mask);
      const Expression<dim>           prescribed(bc.prescribed_displacement,
                                       dim,
                                       coordinate_names(dim),
                                       parameters.constants,
                                       false,
                                       "Prescribed displacement");
      const DisplacementFunction<dim> g(prescribed, fe->n_components());
      for (const auto id : bc.prescribed)
        VectorTools::interpolate_boundary_values(
          mapping, dofs, id, g, affine_constraints, u_mask);
      if (!bc.slip.empty())
        VectorTools::compute_no_normal_flux_constraints(
          dofs,
          0,
          std::set<types::boundary_id>(bc.slip.begin(), bc.slip.end()),
          affine_constraints,
          mapping);
      affine_constraints.close();

      DynamicSparsityPattern dsp(dofs.n_dofs());
      DoFTools::make_sparsity_pattern(dofs, dsp, affine_constraints, false);
      sparsity.copy_from(dsp);
      stiffness.reinit(sparsity);
      mass.reinit(sparsity);
      load.reinit(dofs.n_dofs());
      displacement.reinit(dofs.n_dofs());
    }

    template <int dim>
    void
    ElasticSystem<dim>::assemble(const bool with_mass)
    {
      stiffness = 0;
      mass      = 0;
      load      = 0;

      const auto                        &bc = parameters.boundary;
      const Expression<dim>              body_force(bc.body_force,
                                       dim,
                                       coordinate_names(dim),
                                       parameters.constants,
                                       false,
                                       "Body force");
      const Expression<dim>              traction(bc.traction,
                                     dim,
                                     coordinate_names(dim),
                                     parameters.constants,
                                     false,
                                     "Traction");
      const std::set<types::boundary_id> traction_ids(bc.traction_ids.begin(),
                                                      bc.traction_ids.end());

      const unsigned int    p = parameters.discretisation.degree;
      const QGauss<dim>     quadrature(p + 1);
      const QGauss<dim - 1> face_quadrature(p + 1);
      FEValues<dim>         fe_values(mapping,
                              *fe,
                              quadrature,
                              update_values | update_gradients |
                                update_quadrature_points | update_JxW_values);
      FEFaceValues<dim>     fe_face_values(mapping,
                                       *fe,
                                       face_quadrature,
                                       update_values |
                                         update_quadrature_points |
                                         update_JxW_values);

      const FEValuesExtractors::Vector     u(0);
      const FEValuesExtractors::Scalar     pressure(dim);
      const unsigned int                   n = fe->n_dofs_per_cell();
      FullMatrix<double>                   cell_k(n, n), cell_m(n, n);
      Vector<double>                       cell_f(n);
      std::vector<types::global_dof_index> indices(n);
      std::vector<SymmetricTensor<2, dim>> eps(n);
      std::vector<double>                  div(n), q(n);
      std::vector<Tensor<1, dim>>          phi(n);
      const double                         rho = parameters.material.density;
      const double                         mu  = moduli.mu;
      // the displacement formulation's lambda; finite (nu < 0.5 there)
      const double lambda = is_mixed ? 0. : moduli.lambda;
      double       b[dim], t[dim];

      for (const auto &cell : dofs.active_cell_iterators())
        {
          fe_values.reinit(cell);
          cell_k = 0;
          cell_m = 0;
          cell_f = 0;
          for (unsigned int qp = 0; qp < quadrature.size(); ++qp)
            {
              const double JxW = fe_values.JxW(qp);
              for (unsigned int i = 0; i < n; ++i)
                {
                  eps[i] = fe_values[u].symmetric_gradient(i, qp);
                  div[i] = fe_values[u].divergence(i, qp);
                  phi[i] = fe_values[u].value(i, qp);
                  q[i]   = is_mixed ? fe_values[pressure].value(i, qp) : 0.;
                }
              body_force.value(fe_values.quadrature_point(qp), 0, b);
              for (unsigned int i = 0; i < n; ++i)
                {
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      // displacement: 2 mu eps:eps + lambda div div;
                      // mixed: 2 mu eps:eps - p div v - q div u - q p/lambda
                      double k =
                        2 * mu * (eps[i] * eps[j]) + lambda * div[i] * div[j];
                      if (is_mixed)
                        k -= q[i] * div[j] + div[i] * q[j] +
                             moduli.inverse_lambda * q[i] * q[j];
                      cell_k(i, j) += k * JxW;
                      if (with_mass)
                        cell_m(i, j) += rho * (phi[i] * phi[j]) * JxW;
                    }
                  for (unsigned int d = 0; d < dim; ++d)
                    cell_f(i) += rho * b[d] * phi[i][d] * JxW;
                }
            }
          for (const auto f : cell->face_indices())
            if (cell->at_boundary(f) &&
                traction_ids.count(cell->face(f)->boundary_id()) > 0)
              {
                fe_face_values.reinit(cell, f);
                for (unsigned int qp = 0; qp < face_quadrature.size(); ++qp)
                  {
                    traction.value(fe_face_values.quadrature_point(qp), 0, t);
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        const auto v = fe_face_values[u].value(i, qp);
                        for (unsigned int d = 0; d < dim; ++d)
                          cell_f(i) += t[d] * v[d] * fe_face_values.JxW(qp);
                      }
                  }
              }
          cell->get_dof_indices(indices);
          affine_constraints.distribute_local_to_global(
            cell_k, cell_f, indices, stiffness, load);
          if (with_mass)
            affine_constraints.distribute_local_to_global(cell_m,
                                                          indices,
                                                          mass);
        }
    }

    template <int dim>
    bool
    ElasticSystem<dim>::leaves_rigid_body_motion() const
    {
      if (has_dirichlet_boundary())
        return false;
      // The constraints (slip, hanging nodes) are homogeneous here: a rigid
      // motion r is admissible if distribute() does not change it. The
      // admissible combinations are the null space of the violations
      // V = [r_k - distribute(r_k)]; test the Gram matrix V^T V.
      const unsigned int          n_rigid = dim * (dim + 1) / 2;
      std::vector<Vector<double>> violation;
      for (unsigned int k = 0; k < n_rigid; ++k)
        {
          Vector<double> r(dofs.n_dofs());
          VectorTools::interpolate(mapping,
                                   dofs,
                                   RigidMotion<dim>(k, fe->n_components()),
                                   r);
          r /= r.l2_norm();
          Vector<double> v(r);
          affine_constraints.distribute(v);
          v -= r;
          violation.push_back(v);
        }
      LAPACKFullMatrix<double> gram(n_rigid, n_rigid);
      for (unsigned int k = 0; k < n_rigid; ++k)
        for (unsigned int l = 0; l < n_rigid; ++l)
          gram(k, l) = violation[k] * violation[l];
      gram.compute_eigenvalues();
      double smallest = std::numeric_limits<double>::max();
      for (unsigned int k = 0; k < n_rigid; ++k)
        smallest = std::min(smallest, std::abs(gram.eigenvalue(k)));
      return smallest < 1e-12;
    }

    template <int dim>
    void
    ElasticSystem<dim>::solve_static()
    {
      if (leaves_rigid_body_motion())
        throw InputError(
          "Boundary conditions: the clamped, slip and prescribed boundaries "
          "leave a rigid-body motion free, so the static problem has no "
          "unique solution (clamp a boundary, or add slip boundaries that "
          "hold every translation and rotation)");
      assemble(false);
      SparseDirectUMFPACK direct;
      try
        {
          direct.initialize(stiffness);
        }
      catch (const std::exception &e)
        {
          throw InputError(
            "the stiffness matrix is singular: the boundary conditions do "
            "not remove every rigid-body motion (add clamped or slip "
            "boundaries). UMFPACK: " +
            clean_dealii_message(e.what()));
        }
      direct.vmult(displacement, load);
      affine_constraints.distribute(displacement);
    }

    template <int dim>
    void
    ElasticSystem<dim>::assemble_stiffness_and_mass()
    {
      assemble(true);
      for (types::global_dof_index i = 0; i < dofs.n_dofs(); ++i)
        if (affine_constraints.is_constrained(i))
          mass.set(i, i, 0.);
    }

    template <int dim>
    Vector<double>
    ElasticSystem<dim>::point_value(const Point<dim> &p) const
    {
      Vector<double> value(fe->n_components());
      try
        {
          VectorTools::point_value(mapping, dofs, displacement, p, value);
        }
      catch (...)
        {
          std::ostringstream s;
          s << "Analysis/Points of interest: the point " << p
            << " is not inside the body";
          throw InputError(s.str());
        }
      return value;
    }

    template <int dim>
    std::vector<SymmetricTensor<2, dim>>
    ElasticSystem<dim>::quadrature_point_stresses() const
    {
      const QGauss<dim> quadrature(parameters.discretisation.degree + 1);
      FEValues<dim>     fe_values(mapping,
                              *fe,
                              quadrature,
                              update_values | update_gradients);
      const FEValuesExtractors::Vector     u(0);
      const FEValuesExtractors::Scalar     pressure(dim);
      std::vector<SymmetricTensor<2, dim>> eps(quadrature.size());
      std::vector<double>                  p(quadrature.size());
      std::vector<SymmetricTensor<2, dim>> out;
      for (const auto &cell : dofs.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_symmetric_gradients(displacement, eps);
          if (is_mixed)
            fe_values[pressure].get_function_values(displacement, p);
          for (unsigned int qp = 0; qp < quadrature.size(); ++qp)
            {
              const double hydrostatic =
                is_mixed ? -p[qp] : moduli.lambda * trace(eps[qp]);
              out.push_back(2 * moduli.mu * eps[qp] +
                            hydrostatic * unit_symmetric_tensor<dim>());
            }
        }
      return out;
    }

    template <int dim>
    void
    ElasticSystem<dim>::write_vtu(
      const std::string                         &file_name,
      const std::vector<const Vector<double> *> &fields,
      const std::vector<std::string>            &names) const
    {
      DataOut<dim> data_out;
      data_out.attach_dof_handler(dofs);
      for (unsigned int f = 0; f < fields.size(); ++f)
        {
          std::vector<std::string> component_names(dim, names[f]);
          std::vector<DataComponentInterpretation::DataComponentInterpretation>
            interpretation(
              dim, DataComponentInterpretation::component_is_part_of_vector);
          if (is_mixed)
            {
              component_names.push_back(names[f] + "_pressure");
              interpretation.push_back(
                DataComponentInterpretation::component_is_scalar);
            }
          data_out.add_data_vector(*fields[f],
                                   component_names,
                                   DataOut<dim>::type_dof_data,
                                   interpretation);
        }
      data_out.build_patches(mapping, parameters.discretisation.degree);
      std::ofstream out(file_name);
      if (!out)
        throw InputError("cannot write '" + file_name + "'");
      data_out.write_vtu(out);
    }

    template class ElasticSystem<2>;
    template class ElasticSystem<3>;
  } // namespace fe_reference
} // namespace mpm
