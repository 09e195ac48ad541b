#include <mpm/remedies/linearized_cell_smoothing.h>
#include <mpm/remedies/volumetric_smoothing.h>

namespace mpm
{
  namespace remedies
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      std::vector<char>
      cell_averages(const std::vector<Body<dim>> &bodies)
      {
        const VolumetricSmoothing<dim> smoothing(bodies);
        std::vector<char>              cell(bodies.size());
        for (unsigned int b = 0; b < bodies.size(); ++b)
          cell[b] = smoothing.average(b) == VolumeAverage::cell;
        return cell;
      }
    } // namespace

    template <int dim>
    LinearizedCellSmoothing<dim>::LinearizedCellSmoothing(
      const std::vector<Body<dim>> &bodies)
      : LinearizedCellSmoothing(cell_averages(bodies))
    {}

    template <int dim>
    LinearizedCellSmoothing<dim>::LinearizedCellSmoothing(
      const std::vector<char> &cell)
      : cell_average(cell)
      , sums(cell.size())
    {
      for (const char c : cell_average)
        any_body = any_body || c;
    }

    template <int dim>
    void
    LinearizedCellSmoothing<dim>::reset(const unsigned int n)
    {
      n_nodes = n;
      for (Sums &s : sums)
        {
          s.V0 = s.V = s.V_n = s.V_n_tr_h = 0;
          s.V_n_G.assign(n, Tensor<1, dim>());
          s.V_g.assign(n, Tensor<1, dim>());
          s.V_G.assign(n, Tensor<1, dim>());
        }
    }

    template <int dim>
    void
    LinearizedCellSmoothing<dim>::add(const Point &p)
    {
      Sums        &s = sums[p.body];
      const double V = determinant(p.F) * p.V0;
      s.V0 += p.V0;
      s.V += V;
      s.V_n += p.V_n;
      s.V_n_tr_h += p.V_n * trace(p.h);
      const Tensor<2, dim> f_inv_T = transpose(p.f_inv);
      for (unsigned int b = 0; b < n_nodes; ++b)
        {
          s.V_n_G[b] += p.V_n * p.G[b];
          s.V_g[b] += V * (f_inv_T * p.G[b]);
          s.V_G[b] += V * p.G[b];
        }
    }

    template <int dim>
    void
    LinearizedCellSmoothing<dim>::material_increment(
      Point          &p,
      const bool      total,
      Tensor<2, dim> &h_rate,
      Tensor<2, dim> &F_bar,
      Tensor<2, dim> &h_eff) const
    {
      const Sums &s = sums[p.body];
      smoothed_increment(
        p, total, s.V / s.V0, s.V_n_tr_h / s.V_n, h_rate, F_bar, h_eff);
    }

    template <int dim>
    void
    LinearizedCellSmoothing<dim>::smoothed_increment(Point          &p,
                                                     const bool      total,
                                                     const double    J_bar,
                                                     const double    theta_bar,
                                                     Tensor<2, dim> &h_rate,
                                                     Tensor<2, dim> &F_bar,
                                                     Tensor<2, dim> &h_eff)
    {
      // The explicit update's smoothing, with h = dt L for the rate.
      const double J = determinant(p.F);
      h_rate         = p.h;
      F_bar          = p.F;
      smooth_volume_change<dim>(h_rate, F_bar, J, J_bar, theta_bar);
      p.alpha = std::pow(J_bar / J, 1. / dim);
      if (!total)
        {
          h_eff = h_rate;
          return;
        }
      h_eff = p.alpha * p.f;
      for (unsigned int d = 0; d < dim; ++d)
        h_eff[d][d] -= 1.;
    }

    template <int dim>
    Tensor<2, dim>
    LinearizedCellSmoothing<dim>::derivative(const Point       &p,
                                             const bool         total,
                                             const unsigned int b,
                                             const unsigned int k) const
    {
      const Sums &s = sums[p.body];
      return increment_derivative(
        p, total, b, k, total ? s.V_g[b][k] / s.V : s.V_n_G[b][k] / s.V_n);
    }

    template <int dim>
    Tensor<2, dim>
    LinearizedCellSmoothing<dim>::increment_derivative(
      const Point       &p,
      const bool         total,
      const unsigned int b,
      const unsigned int k,
      const double       average_change)
    {
      Tensor<2, dim> d;
      if (!total)
        {
          // d h_bar = e_k (x) G_b + (d theta_bar - G_bk)/d I
          d[k]           = p.G[b];
          const double v = (average_change - p.G[b][k]) / dim;
          for (unsigned int i = 0; i < dim; ++i)
            d[i][i] += v;
          return d;
        }
      // d(alpha f) = alpha e_k (x) G_b + f d alpha, with
      // d alpha / alpha = (d J_bar / J_bar - d J / J) / d,
      // d J / J = (f^-T G_b)_k (the cell's d J_bar / J_bar = sum V f^-T
      // G_b / sum V).
      const double dJ_J    = (transpose(p.f_inv) * p.G[b])[k];
      const double d_alpha = p.alpha * (average_change - dJ_J) / dim;
      d                    = d_alpha * p.f;
      d[k] += p.alpha * p.G[b];
      return d;
    }

    template <int dim>
    bool
    LinearizedCellSmoothing<dim>::volume_gradient(const unsigned int   b,
                                                  const bool           total,
                                                  const bool           fixed,
                                                  std::vector<double> &g,
                                                  std::vector<double> &b_change,
                                                  double              &V) const
    {
      const Sums &s = sums[b];
      V             = total ? s.V : s.V_n;
      if (!cell_average[b] || !(V > 0))
        return false;
      const auto &change    = total ? s.V_g : s.V_n_G;
      const auto &direction = fixed ? s.V_G : s.V_g;
      g.resize(n_nodes * dim);
      b_change.resize(n_nodes * dim);
      for (unsigned int a = 0; a < n_nodes; ++a)
        for (unsigned int k = 0; k < dim; ++k)
          {
            g[a * dim + k]        = direction[a][k];
            b_change[a * dim + k] = change[a][k];
          }
      return true;
    }

    template class LinearizedCellSmoothing<1>;
    template class LinearizedCellSmoothing<2>;
    template class LinearizedCellSmoothing<3>;
  } // namespace remedies
} // namespace mpm
