#include <mpm/remedies/assumed_stress.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace mpm
{
  namespace remedies
  {
    using namespace dealii;

    namespace
    {
      /// Voigt order: 2D xx yy xy; 3D xx yy zz yz xz xy. Arrays per
      /// dimension (not pointers into one table), so that the per-particle
      /// loop of add() indexes compile-time constants.
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
      const SymmetricTensor<4, dim> A_of = metric == Metric::mass ?
                                             identity_tensor<dim>() :
                                             compliance;
      for (unsigned int a = 0; a < n_voigt; ++a)
        for (unsigned int b = 0; b < n_voigt; ++b)
          {
            const double ma = voigt_i<dim>[a] == voigt_j<dim>[a] ? 1. : 2.;
            const double mb = voigt_i<dim>[b] == voigt_j<dim>[b] ? 1. : 2.;
            W[a][b] = ma * mb *
                      A_of[voigt_i<dim>[a]][voigt_j<dim>[a]][voigt_i<dim>[b]]
                          [voigt_j<dim>[b]];
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

      // the connected groups of stress components (H_kl = TWT[row k][row
      // l] * moment): a column belongs to its component's group
      using C = internal::BasisColumns<dim>;
      unsigned int group_of_row[n_voigt];
      for (unsigned int a = 0; a < n_voigt; ++a)
        group_of_row[a] = a;
      for (bool merged = true; merged;)
        {
          merged = false;
          for (unsigned int a = 0; a < n_voigt; ++a)
            for (unsigned int b = 0; b < n_voigt; ++b)
              if ((TWT[a][b] != 0. || TWT[b][a] != 0.) &&
                  group_of_row[b] > group_of_row[a])
                group_of_row[b] = group_of_row[a], merged = true;
        }
      unsigned int group[n_beta];
      for (unsigned int k = 0; k < n_active; ++k)
        group[k] = group_of_row[C::row[k]];
      for (unsigned int j = 0; j < n_active; ++j)
        {
          coupled[j] = 0;
          for (unsigned int k = 0; k < n_active; ++k)
            if (k != j && group[k] == group[j])
              coupled[j] |= std::uint32_t(1) << k;
        }
    }

    template <int dim>
    SymmetricTensor<2, dim>
    AssumedStressProjection<dim>::field(const Point<dim> &xi,
                                        const double     *beta) const
    {
      return cartesian_field(beta).value(xi);
    }

    template <int dim>
    void
    AssumedStressProjection<dim>::add(Moments                       &sums,
                                      const Point<dim>              &xi,
                                      const double                   weight,
                                      const SymmetricTensor<2, dim> &stress) const
    {
      using C = internal::BasisColumns<dim>;
      if (!(weight > 0))
        return;
      sums.total += weight;
      double r[dim], m[n_monomials];
      for (unsigned int d = 0; d < dim; ++d)
        r[d] = 2 * xi[d] - 1;
      C::monomials(r, m);
      for (unsigned int i = 0; i < n_monomials; ++i)
        {
          const double wm = weight * m[i];
          for (unsigned int j = i; j < n_monomials; ++j)
            sums.moment[i][j] += wm * m[j];
        }
      // T^T W sigma: the stress seen from the natural components
      for (unsigned int a = 0; a < n_voigt; ++a)
        {
          double v = 0;
          for (unsigned int b = 0; b < n_voigt; ++b)
            v += TW[a][b] * stress[voigt_i<dim>[b]][voigt_j<dim>[b]];
          v *= weight;
          for (unsigned int i = 0; i < n_monomials; ++i)
            sums.rhs[a][i] += v * m[i];
        }
    }

    template <int dim>
    typename AssumedStressProjection<dim>::Result
    AssumedStressProjection<dim>::project(
      std::vector<StressSample<dim>> &samples,
      double                         *beta_out) const
    {
      Moments sums{};
      for (const auto &p : samples)
        add(sums, p.xi, p.weight, p.stress);
      double       beta[n_beta];
      const Result result = solve(sums, beta);
      if (result == Result::unchanged)
        return result;
      const CartesianField sigma = cartesian_field(beta);
      for (auto &p : samples)
        p.stress = sigma.value(p.xi);
      if (beta_out)
        std::copy(beta, beta + n_beta, beta_out);
      return result;
    }

    template <int dim>
    typename AssumedStressProjection<dim>::CartesianField
    AssumedStressProjection<dim>::cartesian_field(const double *beta) const
    {
      using C = internal::BasisColumns<dim>;
      double natural[n_voigt][n_monomials] = {};
      for (unsigned int k = 0; k < n_active; ++k)
        natural[C::row[k]][C::mono[k]] += beta[k];
      CartesianField sigma;
      for (unsigned int a = 0; a < n_voigt; ++a)
        for (unsigned int i = 0; i < n_monomials; ++i)
          {
            double s = 0;
            for (unsigned int b = 0; b < n_voigt; ++b)
              s += transform[a][b] * natural[b][i];
            sigma.c[a][i] = s;
          }
      return sigma;
    }

    template <int dim>
    typename AssumedStressProjection<dim>::Result
    AssumedStressProjection<dim>::solve(const Moments &sums,
                                        double        *beta) const
    {
      std::fill(beta, beta + n_beta, 0.);
      if (!(sums.total > 0))
        return Result::unchanged;
      // The field's size as a compile-time constant: the loops below
      // unroll (this solve runs once per cell and body every step).
      if constexpr (dim == 2)
        return n_active == 5 ? solve_sized<5>(sums, beta) :
                               solve_sized<7>(sums, beta);
      else
        return n_active == 18 ? solve_sized<18>(sums, beta) :
                                solve_sized<21>(sums, beta);
    }

    template <int dim>
    template <unsigned int n>
    typename AssumedStressProjection<dim>::Result
    AssumedStressProjection<dim>::solve_sized(const Moments &sums,
                                              double        *beta) const
    {
      using C          = internal::BasisColumns<dim>;
      const auto entry = [&](const unsigned int k, const unsigned int l) {
        const unsigned int i = std::min(C::mono[k], C::mono[l]);
        const unsigned int j = std::max(C::mono[k], C::mono[l]);
        return TWT[C::row[k]][C::row[l]] * sums.moment[i][j];
      };
      // The 3D fields visit only the entries within a group of coupled
      // columns, in ascending order (the others are zero and stay zero);
      // the small 2D ones all of them, in loops the compiler unrolls.
      constexpr bool sparse    = n > 7;
      const auto     for_below = [&](const unsigned int j, const auto &f) {
        if constexpr (sparse)
          for (auto m = coupled[j] & ((std::uint32_t(1) << j) - 1); m != 0;
               m &= m - 1)
            f(static_cast<unsigned int>(__builtin_ctz(m)));
        else
          for (unsigned int k = 0; k < j; ++k)
            f(k);
      };
      const auto for_above = [&](const unsigned int j, const auto &f) {
        if constexpr (sparse)
          for (auto m = coupled[j] & ~((std::uint32_t(2) << j) - 1); m != 0;
               m &= m - 1)
            f(static_cast<unsigned int>(__builtin_ctz(m)));
        else
          for (unsigned int i = j + 1; i < n; ++i)
            f(i);
      };
      double H[n][n], R[n];
      for (unsigned int k = 0; k < n; ++k)
        {
          R[k]    = sums.rhs[C::row[k]][C::mono[k]];
          H[k][k] = entry(k, k);
          for_above(k, [&](const unsigned int i) { H[i][k] = entry(i, k); });
        }
      // the fallback's whole matrix
      const auto constant_fallback = [&]() {
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int l = 0; l < n; ++l)
            H[k][l] = entry(k, l);
        return solve_constant(H, R, beta);
      };

      // H is symmetric positive semi-definite. Its LDL^T factorisation
      // (unpivoted: the matrix is tiny and SPD when the layout is good)
      // says whether the layout determines every beta: a pivot below
      // 1e-6 of its diagonal entry means that column (nearly) depends on
      // the previous ones (one particle, particles on a line or a plane).
      // Solving anyway would amplify the round-off of the particle sums
      // by up to the inverse ratio: with 1e-10 serial and parallel runs
      // of a 3D collision drifted apart by 1e-4.
      double L[n][n], D[n];
      for (unsigned int j = 0; j < n; ++j)
        {
          double d = H[j][j];
          for_below(j, [&](const unsigned int k) {
            d -= L[j][k] * L[j][k] * D[k];
          });
          if (!(d > 1e-6 * H[j][j]))
            return constant_fallback();
          D[j] = d;
          for_above(j, [&](const unsigned int i) {
            double l = H[i][j];
            for_below(j, [&](const unsigned int k) {
              l -= L[i][k] * L[j][k] * D[k];
            });
            L[i][j] = l / d;
          });
        }
      // L y = R, D z = y, L^T beta = z
      for (unsigned int i = 0; i < n; ++i)
        {
          double y = R[i];
          for_below(i, [&](const unsigned int k) { y -= L[i][k] * beta[k]; });
          beta[i] = y;
        }
      for (unsigned int i = 0; i < n; ++i)
        beta[i] /= D[i];
      for (unsigned int i = n; i-- > 0;)
        for_above(i, [&](const unsigned int k) {
          beta[i] -= L[k][i] * beta[k];
        });
      return Result::full;
    }

    template <int dim>
    template <unsigned int n>
    typename AssumedStressProjection<dim>::Result
    AssumedStressProjection<dim>::solve_constant(const double (&H)[n][n],
                                                 const double (&R)[n],
                                                 double *beta) const
    {
      const auto      c   = constant_columns<dim>();
      const unsigned  n_c = c.size();
      Eigen::MatrixXd Hc(n_c, n_c);
      Eigen::VectorXd Rc(n_c);
      for (unsigned int i = 0; i < n_c; ++i)
        {
          Rc(i) = R[c[i]];
          for (unsigned int j = 0; j < n_c; ++j)
            Hc(i, j) = H[c[i]][c[j]];
        }
      std::fill(beta, beta + n_beta, 0.);
      const Eigen::LDLT<Eigen::MatrixXd> ldlt_c(Hc);
      if (!(ldlt_c.info() == Eigen::Success && ldlt_c.isPositive() &&
            ldlt_c.rcond() > 1e-12))
        return Result::unchanged;
      const Eigen::VectorXd b = ldlt_c.solve(Rc);
      for (unsigned int i = 0; i < n_c; ++i)
        beta[c[i]] = b(i);
      return Result::constant;
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
  } // namespace remedies
} // namespace mpm
