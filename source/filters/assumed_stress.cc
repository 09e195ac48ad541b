#include <mpm/filters/assumed_stress.h>

#include <cmath>

#include <Eigen/Dense>

namespace mpm {
  namespace filters {
    using namespace dealii;

    namespace {
      /// Voigt order: 2D xx yy xy; 3D xx yy zz yz xz xy.
      template <int dim>
      constexpr unsigned int voigt_i[dim == 2 ? 3 : 6] = {};
      template <>
      constexpr unsigned int voigt_i<2>[3] = {0, 1, 0};
      template <>
      constexpr unsigned int voigt_i<3>[6] = {0, 1, 2, 1, 0, 0};
      template <int dim>
      constexpr unsigned int voigt_j[dim == 2 ? 3 : 6] = {};
      template <>
      constexpr unsigned int voigt_j<2>[3] = {0, 1, 1};
      template <>
      constexpr unsigned int voigt_j<3>[6] = {0, 1, 2, 2, 2, 1};

      /// Constant-stress columns of the basis (the fallback subspace).
      template <int dim>
      std::vector<unsigned int>
      constant_columns()
      {
        if (dim == 2)
          return {0, 1, 2};
        return {0, 4, 8, 12, 14, 16};
      }
    } // namespace

    template <int dim>
    AssumedStressProjection<dim>::AssumedStressProjection(
      const Tensor<2, dim>          &J0,
      const Metric                   metric,
      const SymmetricTensor<4, dim> &compliance)
    {
      // The scale of J0 only rescales beta; normalising keeps H well
      // conditioned whatever the cell size.
      const Tensor<2, dim> J = J0 / J0.norm();
      for (unsigned int a = 0; a < n_voigt; ++a)
        {
          Tensor<2, dim> E; // natural unit stress a
          E[voigt_i<dim>[a]][voigt_j<dim>[a]] = 1;
          E[voigt_j<dim>[a]][voigt_i<dim>[a]] = 1;
          const Tensor<2, dim> s              = J * E * transpose(J);
          for (unsigned int b = 0; b < n_voigt; ++b)
            transform[b][a] = s[voigt_i<dim>[b]][voigt_j<dim>[b]];
        }
      // sigma : A : sigma in Voigt components (off-diagonals counted once)
      for (unsigned int a = 0; a < n_voigt; ++a)
        for (unsigned int b = 0; b < n_voigt; ++b)
          {
            const double ma = voigt_i<dim>[a] == voigt_j<dim>[a] ? 1. : 2.;
            const double mb = voigt_i<dim>[b] == voigt_j<dim>[b] ? 1. : 2.;
            const double A =
              metric == Metric::mass ?
                identity_tensor<dim>()[voigt_i<dim>[a]][voigt_j<dim>[a]]
                                      [voigt_i<dim>[b]][voigt_j<dim>[b]] :
                compliance[voigt_i<dim>[a]][voigt_j<dim>[a]][voigt_i<dim>[b]]
                          [voigt_j<dim>[b]];
            W[a][b] = ma * mb * A;
          }
    }

    template <int dim>
    void
    AssumedStressProjection<dim>::basis(const Point<dim> &xi, double *S) const
    {
      // natural coordinates in [-1, 1]
      double r[dim];
      for (unsigned int d = 0; d < dim; ++d)
        r[d] = 2 * xi[d] - 1;
      double P[n_voigt][n_beta] = {};
      if constexpr (dim == 2)
        {
          // Pian-Sumihara: ss = b1 + b4 t, tt = b2 + b5 s, st = b3
          P[0][0] = 1, P[0][3] = r[1];
          P[1][1] = 1, P[1][4] = r[0];
          P[2][2] = 1;
        }
      else
        {
          // 18-beta hexahedral field
          P[0][0] = 1, P[0][1] = r[1], P[0][2] = r[2], P[0][3] = r[1] * r[2];
          P[1][4] = 1, P[1][5] = r[0], P[1][6] = r[2], P[1][7] = r[0] * r[2];
          P[2][8] = 1, P[2][9] = r[0], P[2][10] = r[1], P[2][11] = r[0] * r[1];
          P[3][12] = 1, P[3][13] = r[0];
          P[4][14] = 1, P[4][15] = r[1];
          P[5][16] = 1, P[5][17] = r[2];
        }
      for (unsigned int a = 0; a < n_voigt; ++a)
        for (unsigned int k = 0; k < n_beta; ++k)
          {
            double s = 0;
            for (unsigned int b = 0; b < n_voigt; ++b)
              s += transform[a][b] * P[b][k];
            S[a * n_beta + k] = s;
          }
    }

    template <int dim>
    SymmetricTensor<2, dim>
    AssumedStressProjection<dim>::field(const Point<dim> &xi,
                                        const double     *beta) const
    {
      double S[n_voigt * n_beta];
      basis(xi, S);
      SymmetricTensor<2, dim> sigma;
      for (unsigned int a = 0; a < n_voigt; ++a)
        {
          double s = 0;
          for (unsigned int k = 0; k < n_beta; ++k)
            s += S[a * n_beta + k] * beta[k];
          sigma[voigt_i<dim>[a]][voigt_j<dim>[a]] = s;
        }
      return sigma;
    }

    template <int dim>
    typename AssumedStressProjection<dim>::Result
    AssumedStressProjection<dim>::project(
      std::vector<StressSample<dim>> &samples) const
    {
      using Matrix = Eigen::Matrix<double, n_beta, n_beta>;
      using Vector = Eigen::Matrix<double, n_beta, 1>;
      Matrix H     = Matrix::Zero();
      Vector R     = Vector::Zero();
      double total = 0;
      double S[n_voigt * n_beta];
      for (const auto &p : samples)
        {
          if (!(p.weight > 0))
            continue;
          total += p.weight;
          basis(p.xi, S);
          double sv[n_voigt];
          for (unsigned int a = 0; a < n_voigt; ++a)
            sv[a] = p.stress[voigt_i<dim>[a]][voigt_j<dim>[a]];
          // WS = W S (n_voigt x n_beta), W sigma
          double WS[n_voigt][n_beta] = {}, Ws[n_voigt] = {};
          for (unsigned int a = 0; a < n_voigt; ++a)
            for (unsigned int b = 0; b < n_voigt; ++b)
              {
                Ws[a] += W[a][b] * sv[b];
                for (unsigned int k = 0; k < n_beta; ++k)
                  WS[a][k] += W[a][b] * S[b * n_beta + k];
              }
          for (unsigned int k = 0; k < n_beta; ++k)
            {
              for (unsigned int a = 0; a < n_voigt; ++a)
                R(k) += p.weight * S[a * n_beta + k] * Ws[a];
              for (unsigned int l = 0; l < n_beta; ++l)
                {
                  double h = 0;
                  for (unsigned int a = 0; a < n_voigt; ++a)
                    h += S[a * n_beta + k] * WS[a][l];
                  H(k, l) += p.weight * h;
                }
            }
        }
      if (!(total > 0))
        return Result::unchanged;

      double beta[n_beta] = {};
      Result result       = Result::full;
      // Relative tolerance on the condition: below it the layout of the
      // particles cannot determine the linear terms.
      // H is symmetric positive semi-definite. A pivoted LDL^T whose
      // smallest pivot is tiny against the largest says that the particle
      // layout does not determine every beta.
      const Eigen::LDLT<Matrix> ldlt(H);
      const auto               &D = ldlt.vectorD();
      if (ldlt.info() == Eigen::Success &&
          D.minCoeff() > 1e-10 * D.cwiseAbs().maxCoeff())
        {
          const Vector b = ldlt.solve(R);
          for (unsigned int k = 0; k < n_beta; ++k)
            beta[k] = b(k);
        }
      else
        {
          result              = Result::constant;
          const auto      c   = constant_columns<dim>();
          const unsigned  n_c = c.size();
          Eigen::MatrixXd Hc(n_c, n_c);
          Eigen::VectorXd Rc(n_c);
          for (unsigned int i = 0; i < n_c; ++i)
            {
              Rc(i) = R(c[i]);
              for (unsigned int j = 0; j < n_c; ++j)
                Hc(i, j) = H(c[i], c[j]);
            }
          const Eigen::LDLT<Eigen::MatrixXd> ldlt_c(Hc);
          if (!(ldlt_c.info() == Eigen::Success && ldlt_c.isPositive() &&
                ldlt_c.rcond() > 1e-12))
            return Result::unchanged;
          const Eigen::VectorXd b = ldlt_c.solve(Rc);
          for (unsigned int i = 0; i < n_c; ++i)
            beta[c[i]] = b(i);
        }
      for (auto &p : samples)
        p.stress = field(p.xi, beta);
      return result;
    }

    template <int dim>
    SymmetricTensor<4, dim>
    isotropic_compliance(const double E,
                         const double nu,
                         const bool   plane_stress)
    {
      const double a = (1 + nu) / E;
      const double b =
        (dim == 2 && !plane_stress) ? -nu * (1 + nu) / E : -nu / E;
      return a * identity_tensor<dim>() +
             b * outer_product(unit_symmetric_tensor<dim>(),
                               unit_symmetric_tensor<dim>());
    }

    template class AssumedStressProjection<2>;
    template class AssumedStressProjection<3>;
    template SymmetricTensor<4, 2>
    isotropic_compliance<2>(double, double, bool);
    template SymmetricTensor<4, 3>
    isotropic_compliance<3>(double, double, bool);
  } // namespace filters
} // namespace mpm
