#include <mpm/filters/assumed_stress.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace mpm
{
  namespace filters
  {
    using namespace dealii;

    namespace
    {
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

      /// The natural field Sigma(r) = P(r) beta. Every column k of P has one
      /// nonzero: natural component row[k] (Voigt order) times the monomial
      /// mono[k] of the natural coordinates r in [-1, 1] (2D: 1, r0, r1;
      /// 3D: 1, r0, r1, r2, r1 r2, r0 r2, r0 r1). 2D Pian-Sumihara:
      /// ss = b1 + b4 t, tt = b2 + b5 s, st = b3, enriched + b6 s, b7 t;
      /// 3D: the 18-beta hexahedral field, enriched + b19 xi, b20 eta,
      /// b21 zeta on the normal stresses. So H_kl = (T^T W T)[row k][row l]
      /// sum_p w_p m_k m_l needs only the particles' monomial moments.
      template <int dim>
      struct BasisColumns;
      template <>
      struct BasisColumns<2>
      {
        static constexpr unsigned int n_mono  = 3;
        static constexpr unsigned int row[7]  = {0, 1, 2, 0, 1, 0, 1};
        static constexpr unsigned int mono[7] = {0, 0, 0, 2, 1, 1, 2};
        static void
        monomials(const double *r, double *m)
        {
          m[0] = 1, m[1] = r[0], m[2] = r[1];
        }
      };
      template <>
      struct BasisColumns<3>
      {
        static constexpr unsigned int n_mono   = 7;
        static constexpr unsigned int row[21]  = {0, 0, 0, 0, 1, 1, 1,
                                                  1, 2, 2, 2, 2, 3, 3,
                                                  4, 4, 5, 5, 0, 1, 2};
        static constexpr unsigned int mono[21] = {0, 2, 3, 4, 0, 1, 3,
                                                  5, 0, 1, 2, 6, 0, 1,
                                                  0, 2, 0, 3, 1, 2, 3};
        static void
        monomials(const double *r, double *m)
        {
          m[0] = 1, m[1] = r[0], m[2] = r[1], m[3] = r[2];
          m[4] = r[1] * r[2], m[5] = r[0] * r[2], m[6] = r[0] * r[1];
        }
      };

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
      const SymmetricTensor<4, dim> &compliance,
      const bool                     enriched)
      : n_active(enriched ? n_beta : (dim == 2 ? 5 : 18))
    {
      // The scale of J0 only rescales beta; normalising keeps H well
      // conditioned whatever the cell size.
      const Tensor<2, dim> J = J0 / J0.norm();
      double               W[n_voigt][n_voigt];
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
      for (unsigned int a = 0; a < n_voigt; ++a)
        for (unsigned int b = 0; b < n_voigt; ++b)
          {
            TW[a][b] = 0;
            for (unsigned int c = 0; c < n_voigt; ++c)
              TW[a][b] += transform[c][a] * W[c][b];
          }
      for (unsigned int a = 0; a < n_voigt; ++a)
        for (unsigned int b = 0; b < n_voigt; ++b)
          {
            TWT[a][b] = 0;
            for (unsigned int c = 0; c < n_voigt; ++c)
              TWT[a][b] += TW[a][c] * transform[c][b];
          }
    }

    template <int dim>
    __attribute__((always_inline)) inline SymmetricTensor<2, dim>
    AssumedStressProjection<dim>::field(const Point<dim> &xi,
                                        const double     *beta) const
    {
      using C = BasisColumns<dim>;
      double r[dim], m[C::n_mono];
      for (unsigned int d = 0; d < dim; ++d)
        r[d] = 2 * xi[d] - 1;
      C::monomials(r, m);
      double natural[n_voigt] = {};
      for (unsigned int k = 0; k < n_active; ++k)
        natural[C::row[k]] += beta[k] * m[C::mono[k]];
      SymmetricTensor<2, dim> sigma;
      for (unsigned int a = 0; a < n_voigt; ++a)
        {
          double s = 0;
          for (unsigned int b = 0; b < n_voigt; ++b)
            s += transform[a][b] * natural[b];
          sigma[voigt_i<dim>[a]][voigt_j<dim>[a]] = s;
        }
      return sigma;
    }

    template <int dim>
    typename AssumedStressProjection<dim>::Result
    AssumedStressProjection<dim>::project(
      std::vector<StressSample<dim>> &samples,
      double                         *beta_out) const
    {
      using Matrix                  = Eigen::Matrix<double, n_beta, n_beta>;
      using Vector                  = Eigen::Matrix<double, n_beta, 1>;
      using C                       = BasisColumns<dim>;
      constexpr unsigned int n_mono = C::n_mono;
      // Per particle only the monomial moments sum_p w m_i m_j and the
      // moments of T^T W sigma, sum_p w m_i (T^T W sigma)_a; H and R are
      // put together from them once per cell.
      double moment[n_mono][n_mono] = {};
      double rhs[n_voigt][n_mono]   = {};
      double total                  = 0;
      for (const auto &p : samples)
        {
          if (!(p.weight > 0))
            continue;
          total += p.weight;
          double r[dim], m[n_mono];
          for (unsigned int d = 0; d < dim; ++d)
            r[d] = 2 * p.xi[d] - 1;
          C::monomials(r, m);
          for (unsigned int i = 0; i < n_mono; ++i)
            {
              const double wm = p.weight * m[i];
              for (unsigned int j = i; j < n_mono; ++j)
                moment[i][j] += wm * m[j];
            }
          // T^T W sigma: the stress seen from the natural components
          for (unsigned int a = 0; a < n_voigt; ++a)
            {
              double v = 0;
              for (unsigned int b = 0; b < n_voigt; ++b)
                v += TW[a][b] * p.stress[voigt_i<dim>[b]][voigt_j<dim>[b]];
              v *= p.weight;
              for (unsigned int i = 0; i < n_mono; ++i)
                rhs[a][i] += v * m[i];
            }
        }
      if (!(total > 0))
        return Result::unchanged;
      Matrix H;
      Vector R;
      for (unsigned int k = 0; k < n_active; ++k)
        {
          R(k) = rhs[C::row[k]][C::mono[k]];
          for (unsigned int l = 0; l < n_active; ++l)
            {
              const unsigned int i = std::min(C::mono[k], C::mono[l]);
              const unsigned int j = std::max(C::mono[k], C::mono[l]);
              H(k, l)              = TWT[C::row[k]][C::row[l]] * moment[i][j];
            }
        }

      double beta[n_beta] = {};
      Result result       = Result::full;
      // H is symmetric positive semi-definite. Its LDL^T factorisation
      // (unpivoted: the matrix is tiny and SPD when the layout is good)
      // says whether the layout determines every beta: a pivot below
      // 1e-6 of its diagonal entry means that column (nearly) depends on
      // the previous ones (one particle, particles on a line or a plane).
      // Solving anyway would amplify the round-off of the particle sums
      // by up to the inverse ratio: with 1e-10 serial and parallel runs
      // of a 3D collision drifted apart by 1e-4.
      double L[n_beta][n_beta], D[n_beta];
      bool   regular = true;
      for (unsigned int j = 0; j < n_active && regular; ++j)
        {
          double d = H(j, j);
          for (unsigned int k = 0; k < j; ++k)
            d -= L[j][k] * L[j][k] * D[k];
          if (!(d > 1e-6 * H(j, j)))
            {
              regular = false;
              break;
            }
          D[j] = d;
          for (unsigned int i = j + 1; i < n_active; ++i)
            {
              double l = H(i, j);
              for (unsigned int k = 0; k < j; ++k)
                l -= L[i][k] * L[j][k] * D[k];
              L[i][j] = l / d;
            }
        }
      if (regular)
        {
          // L y = R, D z = y, L^T beta = z
          for (unsigned int i = 0; i < n_active; ++i)
            {
              double y = R(i);
              for (unsigned int k = 0; k < i; ++k)
                y -= L[i][k] * beta[k];
              beta[i] = y;
            }
          for (unsigned int i = 0; i < n_active; ++i)
            beta[i] /= D[i];
          for (unsigned int i = n_active; i-- > 0;)
            for (unsigned int k = i + 1; k < n_active; ++k)
              beta[i] -= L[k][i] * beta[k];
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
      if (beta_out)
        std::copy(beta, beta + n_beta, beta_out);
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
