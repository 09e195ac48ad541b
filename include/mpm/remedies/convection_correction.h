#pragma once

#include <deal.II/particles/particle_handler.h>

#include <mpm/grid/background_grid.h>
#include <mpm/particles/body.h>
#include <mpm/remedies/force_pass_hook.h>

#include <utility>
#include <vector>

namespace mpm
{
  namespace remedies
  {
    /// One particle's part in a 1D cell's convection correction.
    struct AxialSample
    {
      double r;      ///< natural coordinate 2 xi - 1 in the cell
      double volume; ///< V_p (unit cross-section), the weight
      double value;  ///< sigma_xx, or the body force per length m_p b_p/V_p
    };

    /**
     * The linear field of one 1D cell, mean + slope (r - r_mean), fitted to
     * particle samples by V-weighted least squares
     * (doc/theory/convection_correction.md).
     */
    struct CellLine
    {
      double r_mean = 0, mean = 0, slope = 0;

      /// The V-weighted least-squares line of @p samples. If they sit at
      /// one position (one particle), the line through their mean and
      /// @p extra (the nearest particle of the body in a neighbouring cell,
      /// r measured in this cell), if given; otherwise their constant mean.
      static CellLine
      fit(const std::vector<AxialSample> &samples, const AxialSample *extra);

      /// int_a^b line(r) r^k dr, k = 0 or 1.
      double
      moment(const double a, const double b, const unsigned int k) const;
    };

    /**
     * The stress part of the correction for one cell and body: the common
     * shift Delta of the samples' stresses such that their quadrature,
     * sum_p V_p (sigma_p + Delta), equals the exact integral
     * (h/2) int_a^b line(r) dr of their CellLine over the part [a, b] of
     * the cell that the body occupies; h is the cell length.
     */
    double
    convection_shift(const std::vector<AxialSample> &samples,
                     const AxialSample              *extra,
                     const double                    a,
                     const double                    b,
                     const double                    h);

    /**
     * The 1D convection correction of the cell-crossing error, for the
     * bodies with `Stress filter = convection correction`. It changes the
     * forces of one P2G pass only, with the cells the particles are in:
     * before_force_pass() shifts the particles' sigma_xx cell by cell
     * (convection_shift()) and, with `Body force correction`, computes the
     * difference between the exact nodal integrals of the cell's linear
     * body-force field and the particle sums; after_force_pass() puts the
     * material's stresses back, bit for bit, and adds those differences to
     * the nodal forces (it keeps pointers into the particle properties
     * between the two). In 2D and 3D (refused by the remedy's check)
     * nothing is done.
     */
    template <int dim>
    class ConvectionCorrection : public ForcePassHook<dim>
    {
    public:
      explicit ConvectionCorrection(const std::vector<Body<dim>> &bodies);

      void
      before_force_pass(const BackgroundGrid<dim>               &grid,
                        dealii::Particles::ParticleHandler<dim> &particles,
                        const std::vector<Body<dim>>            &bodies,
                        const double                             time) override;

      void
      after_force_pass(NodalVector &p2g) override;

    private:
      /// Per body: whether it is corrected, and its body force too.
      std::vector<char> corrected, loads;
      bool              any = false;
      /// (where, original value) of every shifted stress
      std::vector<std::pair<double *, double>> saved;
      /// A body-force correction to add to a node after the pass.
      struct NodalForce
      {
        unsigned int node; ///< node-local index
        unsigned int body;
        double       force;
        double       mass; ///< sum_p N_ip m_p of the body's particles
      };
      std::vector<NodalForce> nodal_forces;
    };
  } // namespace remedies
} // namespace mpm
