#pragma once

#include <deal.II/base/tensor.h>

#include <mpm/particles/body.h>
#include <mpm/shape_functions/q1_cell.h>

#include <cmath>
#include <vector>

namespace mpm
{
  namespace remedies
  {
    /**
     * `Volumetric smoothing = cell` in the implicit step: the smoothed
     * kinematics of a trial increment, exactly those of the explicit
     * stress update (VolumetricSmoothing::update_cell), and their
     * derivatives with respect to the nodal increment (doc/theory/implicit.md,
     * section 1). The particles of one body in one cell couple:
     * - rate form (the seed's theta-bar; models that integrate a rate):
     *   h_bar = h + (theta - tr h)/d I, theta = sum V_n tr h / sum V_n, a
     *   B-bar of the step's displacement gradient h;
     * - total form (F-bar; models whose stress is a function of F):
     *   F_bar = (J_bar/J)^(1/d) F, J_bar = sum J V0 / sum V0, with the
     *   material's increment h_eff = F_bar F_n^-1 - I = alpha f - I.
     * Usage per cell: reset(), add() each particle, then
     * material_increment() and derivative() per particle.
     */
    template <int dim>
    class LinearizedCellSmoothing
    {
    public:
      static constexpr unsigned int nv = shape_functions::n_q1<dim>;

      /// One particle's trial state: h = sum u_a (x) G_a, f = I + h,
      /// F = f F_n; V_n its volume at the start of the step, V0 initial.
      struct Point
      {
        unsigned int           body;
        dealii::Tensor<2, dim> h, f, f_inv, F;
        double                 j, V_n, V0;
        /// grad N_a(x_p^n) for each node a of the cell's list (reset())
        const dealii::Tensor<1, dim> *G;
        /// F-bar's (J_bar/J)^(1/d), set by material_increment()
        double alpha = 1;
      };

      explicit LinearizedCellSmoothing(const std::vector<Body<dim>> &bodies);

      /// @p cell_average per body: whether it averages over the cell.
      explicit LinearizedCellSmoothing(const std::vector<char> &cell_average);

      /// Whether the body with index @p b averages over the cell.
      bool
      smooths(const unsigned int b) const
      {
        return cell_average[b];
      }

      /// Whether some body averages over the cell.
      bool
      any() const
      {
        return any_body;
      }

      /// Start a cell whose particles reach @p n_nodes nodes (the cell's
      /// vertices in standard MPM; more with a domain family).
      void
      reset(const unsigned int n_nodes = nv);

      /// Add one particle of a smoothing body to its body's cell sums.
      void
      add(const Point &p);

      /**
       * The kinematics the material sees, as in the explicit update:
       * @p h_rate = dt L_bar (rate form) and @p F_bar (total form); and
       * @p h_eff, the increment whose derivative derivative() gives:
       * h_rate for a rate model, alpha f - I for a total one. Sets
       * p.alpha, which derivative() uses.
       */
      void
      material_increment(Point                  &p,
                         const bool              total,
                         dealii::Tensor<2, dim> &h_rate,
                         dealii::Tensor<2, dim> &F_bar,
                         dealii::Tensor<2, dim> &h_eff) const;

      /// d h_eff / d u_bk: the derivative of the material's increment of
      /// particle @p p by component @p k of the increment of node @p b of
      /// the cell's list.
      dealii::Tensor<2, dim>
      derivative(const Point       &p,
                 const bool         total,
                 const unsigned int b,
                 const unsigned int k) const;

      /**
       * The kinematics of material_increment() for given averages: the
       * volume ratio @p J_bar (total form) and the trace @p theta_bar of
       * h (rate form), whichever neighbourhood they average over (the
       * cell, or the nodes: LinearizedNodeSmoothing). Sets p.alpha.
       */
      static void
      smoothed_increment(Point                  &p,
                         const bool              total,
                         const double            J_bar,
                         const double            theta_bar,
                         dealii::Tensor<2, dim> &h_rate,
                         dealii::Tensor<2, dim> &F_bar,
                         dealii::Tensor<2, dim> &h_eff);

      /**
       * d h_eff / d u_bk as derivative(), for an average whose own
       * derivative by u_bk is @p average_change: d theta_bar (rate form)
       * or d J_bar / J_bar (total form); 0 holds the average fixed.
       */
      static dealii::Tensor<2, dim>
      increment_derivative(const Point       &p,
                           const bool         total,
                           const unsigned int b,
                           const unsigned int k,
                           const double       average_change);

      /**
       * The stiff part lambda g b^T / V of the smoothed tangent of body
       * @p b in the cell (entries [a dim + k] for node a of the cell's
       * list, direction k): the pressure's force takes g = sum V f^-T
       * G_a, the current volume's gradient (in a @p fixed geometry,
       * whose force takes j sigma on the undeformed grid, g = sum V G_a);
       * the averaged volume change is b . u / V, with b = sum V_n G_a and
       * V = sum V_n for a rate model, b = sum V f^-T G_a and V the
       * current volume for a total one (@p total). False if the body has
       * no particle in the cell.
       */
      bool
      volume_gradient(const unsigned int   b,
                      const bool           total,
                      const bool           fixed,
                      std::vector<double> &g,
                      std::vector<double> &b_change,
                      double              &V) const;

    private:
      struct Sums
      {
        double V0 = 0, V = 0, V_n = 0, V_n_tr_h = 0;
        /// sum V_n G_b (rate), sum V f^-T G_b (total) and sum V G_b
        /// (the fixed geometry's force) per node b
        std::vector<dealii::Tensor<1, dim>> V_n_G, V_g, V_G;
      };
      std::vector<char> cell_average; ///< per body
      bool              any_body = false;
      std::vector<Sums> sums; ///< per body, of the current cell
      unsigned int      n_nodes = nv;
    };
  } // namespace remedies
} // namespace mpm
