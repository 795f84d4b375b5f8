#ifndef bilayer_fracture_h
#define bilayer_fracture_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/core/layout.h>
#include <bilayer/geometry/interface_curve.h>
#include <bilayer/interface/interface.h>
#include <bilayer/subproblem/subproblem.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

/**
 * @file
 * The energy release rate G = -dPi/dl at the crack tips (docs/fracture.md):
 * the derivative of the equilibrium energy with respect to the position of
 * one tip moving along Sigma, written as a domain integral over a
 * neighbourhood of the tip (the shape derivative of the energy under a
 * velocity field theta that moves the tip along Sigma),
 *
 *   G = sum over the layers and subdomains of
 *         int ( sigma : (grad u grad theta) - W div theta ) dx
 *       - s_d int_{gamma_c} psi kappa mu_c [u].tau ds,
 *
 * W = sigma : eps / 2, s_d = +-1 the direction of growth along tau, kappa
 * the curvature of Sigma (the last term exists on a curved Sigma only).
 * A layer with a VolumeLoad (body force f, eigenstrain eps*, both fixed in
 * space) adds sigma : ((grad eps*) theta) + (f . u) div theta +
 * ((grad f) theta) . u to the integrand, with sigma = C (eps - eps*) and
 * W = (eps - eps*) : sigma / 2 (docs/fracture.md §5).
 */
namespace bilayer
{
  /**
   * A crack tip: an end of a crack piece inside Omega (an end of a piece on
   * the outer boundary is none), the direction in which the crack grows
   * and the support of its velocity field theta.
   */
  struct CrackTip
  {
    /// The interface that holds the tip (Sigma: 0).
    unsigned int interface = 0;
    /// Parameter on Sigma, the point, and the unit tangent of Sigma that
    /// points away from the crack (the direction of growth).
    double               s = 0;
    dealii::Point<2>     point;
    dealii::Tensor<1, 2> direction;
    /// +1 if the crack grows in the direction of growing s, else -1.
    double sign = 1;
    /// Sigma near the tip is a circular arc (centre, radius), else straight.
    bool             arc = false;
    dealii::Point<2> centre;
    double           radius = 0;
    /**
     * Empty where Sigma within the support of theta is one straight line or
     * one circle (the fields above). Otherwise the support reaches a smooth
     * (C1) junction of pieces of different shape (a segment and a tangent
     * arc, arcs of different radii): the pieces of Sigma that theta sees,
     * T(x) is the unit tangent at the closest point of these pieces.
     */
    std::vector<InterfaceCurve::Piece> chain;
    /**
     * Outer radius R of the support of theta; 0 where G is not defined:
     * the tip sits on a corner of Sigma (G is a derivative along a smooth
     * Sigma).
     */
    double support_radius = 0;
    /// The distance from the tip to the nearest obstacle of theta (another
    /// tip, a corner or another piece of Sigma, the outer boundary, another
    /// interface, a ply boundary across the direction of growth): the
    /// support radius must stay below it.
    double free_distance = 0;

    bool
    defined() const
    {
      return support_radius > 0;
    }

    /// Whether Sigma is curved somewhere in the support of theta (then G
    /// has the contact term of a curved crack).
    bool
    curved() const
    {
      bool any = arc;
      for (const auto &piece : chain)
        any = any || piece.kind == InterfaceCurve::Piece::Kind::arc;
      return any;
    }
  };

  /// A straight piece of a curve (a face): its two ends.
  using Segment = std::array<dealii::Point<2>, 2>;

  /**
   * The tips of the crack of @p curve (interface @p interface), ordered by
   * s, with the outer boundary of @p meshes (their boundary faces off the
   * interfaces) and the other interfaces @p obstacles as obstacles: the
   * support of theta stays inside the two regions of the interface. The
   * faces @p material_boundaries between plies of different materials are
   * obstacles too, except where theta moves along them (a straight tip's
   * support may cross a ply boundary parallel to its direction of growth):
   * the domain integral of G holds where theta keeps every material
   * boundary in place.
   * @p support_radius (Fracture/Support radius): 0 chooses half the free
   * distance; a given radius must be smaller than the free distance of
   * every tip (else an exception names the entry and the allowed range).
   */
  std::vector<CrackTip>
  crack_tips(const InterfaceCurve                                  &curve,
             const std::array<const dealii::Triangulation<2> *, 2> &meshes,
             const double                       support_radius,
             const unsigned int                 interface           = 0,
             const std::vector<InterfaceCurve> &obstacles           = {},
             const std::vector<Segment>        &material_boundaries = {});

  /**
   * The velocity field theta of a tip: theta(x) = psi(|x - tip|) T(x), with
   * T the direction of growth (straight Sigma) or the rotation about the
   * arc's centre that is that direction at the tip (tangent to the arc
   * everywhere), and psi = 1 for r <= R/2, falling to 0 at r = R as a
   * quintic with two continuous derivatives. Across a smooth junction
   * (CrackTip::chain) T is the unit tangent of Sigma at the closest point,
   * oriented along the growth: constant on the region of a segment,
   * +-J (x - c) / |x - c| on that of an arc (continuous and Lipschitz: the
   * normal line at the junction separates the regions).
   */
  class ThetaField
  {
  public:
    explicit ThetaField(const CrackTip &tip);

    /// psi at distance @p r from the tip.
    double
    cutoff(const double r) const;

    /// The curvature kappa of Sigma at its point @p x (d tau / ds = kappa
    /// nu with @p nu the normal there): 0 on a segment, +-1 / radius on an
    /// arc.
    double
    curvature(const dealii::Point<2> &x, const dealii::Tensor<1, 2> &nu) const;

    dealii::Tensor<1, 2>
    value(const dealii::Point<2> &x) const;

    /// grad theta: entry (k, j) = d theta_k / d x_j.
    dealii::Tensor<2, 2>
    gradient(const dealii::Point<2> &x) const;

    /// Whether the disc of radius @p radius around @p x meets the support.
    bool
    reaches(const dealii::Point<2> &x, const double radius) const
    {
      return (x - tip.point).norm() < tip.support_radius + radius;
    }

  private:
    const CrackTip tip;
    /// Rotation of the arc field: grad T = omega J / radius.
    double omega = 0;

    /// T(x) and grad T(x) across a smooth junction (CrackTip::chain).
    void
    junction_tangent(const dealii::Point<2> &x,
                     dealii::Tensor<1, 2>   &T,
                     dealii::Tensor<2, 2>   &grad_T) const;
  };

  /// G at one tip, in total and its parts [stress x length].
  struct EnergyReleaseRate
  {
    CrackTip tip;
    /// The domain integral over both layers and subdomains plus the contact
    /// and friction terms.
    double G = 0;
    /// The contact term on a curved crack (0 on a straight one).
    double contact = 0;
    /**
     * The friction term (docs/fracture.md §6), part of G: the work of the
     * tangential force on the crack faces as the tip advances, int mu_t
     * theta_s d/ds (u- - u+).tau ds over the crack in the support of theta
     * (0 without friction; <= 0 for a constant Tresca bound).
     */
    double friction = 0;
    /**
     * The mode split of G (mode_split(), docs/fracture.md §7): G_I + G_II =
     * G, the opening (I) and sliding (II) parts; NaN where the split is not
     * defined at this tip (then mode_split_note says why).
     */
    double G_I  = std::numeric_limits<double>::quiet_NaN();
    double G_II = std::numeric_limits<double>::quiet_NaN();
    /// The phase angle psi = atan(sqrt(G_II / G_I)) [degrees], in [0, 90]
    /// (NaN where the split is not defined).
    double phase_angle = std::numeric_limits<double>::quiet_NaN();
    /// The closure length Delta of the split [length] (Fracture/Mode split
    /// length, or the automatic one); NaN where no split was computed.
    double mode_split_length = std::numeric_limits<double>::quiet_NaN();
    /// Empty where the split is defined, else why it is not; at a tip
    /// between different materials, the reference length of the split.
    std::string mode_split_note;
    /**
     * The stress intensity factors (stress_intensity_factors(),
     * docs/fracture.md §10): K L^(i eps) = K_I + i K_II at the reference
     * length L, |K|, the signed phase angle atan2(K_II, K_I) in degrees,
     * the oscillation index eps of the materials at the tip (0 where they
     * agree) and |K|^2 / (E* cosh^2(pi eps)), which equals G for the exact
     * field; NaN where K is not computed (then K_note says why).
     */
    double      K_I               = std::numeric_limits<double>::quiet_NaN();
    double      K_II              = std::numeric_limits<double>::quiet_NaN();
    double      K_magnitude       = std::numeric_limits<double>::quiet_NaN();
    double      K_phase_angle     = std::numeric_limits<double>::quiet_NaN();
    double      oscillation_index = std::numeric_limits<double>::quiet_NaN();
    double      reference_length  = std::numeric_limits<double>::quiet_NaN();
    double      G_from_K          = std::numeric_limits<double>::quiet_NaN();
    std::string K_note;
    /// Why G is not reported at this tip on this mesh (then NaN): the
    /// support of theta holds too few cells (support_cells()); empty if G
    /// is valid.
    std::string unresolved;
    /// G on the same mesh with the support radius halved (R/2), NaN where
    /// R/2 holds fewer than min_cells_per_support_radius cells at the tip
    /// (the exact G does not depend on R, the discrete one does).
    double G_half_support = std::numeric_limits<double>::quiet_NaN();
    /// The error bar dG of G [stress x length] (g_error()): NaN where no
    /// estimator is available (then error_estimate says why).
    double error = std::numeric_limits<double>::quiet_NaN();
    /// The estimator of @p error ("cycles", "support radius", "cycles and
    /// support radius", with "DWR" where the goal-oriented estimate is
    /// the larger), or "none: <why>".
    std::string error_estimate;
    /// The dual-weighted residual estimate of G - G_h (signed; NaN where
    /// not computed: Fracture/Goal-oriented estimate, docs/fracture.md
    /// §11) and the sum of the magnitudes of its cell terms.
    double G_dwr          = std::numeric_limits<double>::quiet_NaN();
    double G_dwr_absolute = std::numeric_limits<double>::quiet_NaN();
    /// (F, z) of the tip's dual solution z (GoalEstimates::dual_work).
    double dual_work = std::numeric_limits<double>::quiet_NaN();
  };

  /**
   * The error estimate of the last entry of @p G (the values of G at one
   * tip on consecutive cycles 0, 1, ..., k; NaN where not reported) from
   * the sequence of cycles: with the last changes d1 = |G_k - G_{k-1}|, d2
   * = |G_{k-1} - G_{k-2}|, d3 = |G_{k-2} - G_{k-3}| (those that exist),
   *
   *   dG = max(d1, d2, d3, d1 r / (1 - r)),
   *
   * the last term only where the last two changes have one sign and
   * contract, r = d1 / d2 < 1 (the remainder of the geometric sequence of
   * ratio r: Aitken's extrapolation); dG = 2 d1 with two values only. G of
   * adaptive cycles moves irregularly (docs/fracture.md, The error bar of
   * G): the largest of three changes, not the last one, bounds the error
   * there. NaN with fewer than two finite trailing values (cycle 0, or a
   * tip not resolved on the cycle before).
   */
  double
  g_error_from_cycles(const std::vector<double> &G);

  /**
   * The error bar of @p g on its cycle, given @p from_cycles
   * (g_error_from_cycles() of the G of this tip so far): the larger of
   * that and the single-mesh indicator |G(R) - G(R/2)|, whichever exist;
   * sets g.error and g.error_estimate (NaN and "none: ..." if neither).
   */
  void
  set_g_error(EnergyReleaseRate &g, const double from_cycles);

  /// The support radius of theta must be at least this many times the size
  /// of the cells at the tip: theta falls from 1 to 0 on R/2 < r < R, and
  /// a support inside the cells at the tip sees the discrete solution as
  /// smooth there and releases nothing (G -> 0 as R -> 0 at a fixed mesh).
  constexpr double min_cells_per_support_radius = 1;

  /// Whether a support of radius @p radius holds the cells of size
  /// @p cell_size at its tip: R >= min_cells_per_support_radius h, up to
  /// round-off (Geometry::refine refines the cells at a tip as long as this
  /// fails).
  inline bool
  support_holds(const double radius, const double cell_size)
  {
    return radius >= min_cells_per_support_radius * cell_size * (1 - 1e-9);
  }

  /// The cells at a crack tip (support_cells()).
  struct TipCells
  {
    /// The largest size of the active cells that have the tip as a vertex
    /// (the tips are mesh vertices), over both meshes: sqrt(area) for
    /// quadrilaterals, sqrt(2 area) for triangles (the side of the square of
    /// two).
    double size = 0;
    /// The mesh (0: Omega-, 1: Omega+) of the largest of them.
    unsigned int mesh = 0;
  };

  /// The cells at @p tip on @p meshes (null entries are skipped).
  TipCells
  support_cells(const CrackTip                                        &tip,
                const std::array<const dealii::Triangulation<2> *, 2> &meshes);

  /// The same from the cell extents of the two meshes (the same answer,
  /// without visiting the cells' geometry).
  TipCells
  support_cells(const CrackTip                           &tip,
                const std::array<const CellExtents *, 2> &meshes);

  /**
   * G at every tip of @p tips for the solutions @p w and the multipliers
   * @p mu (collective: each subproblem's integral is computed by its owner,
   * as a parallel task, and sent to every process). Tips that are not
   * defined() get NaN.
   */
  std::vector<EnergyReleaseRate>
  energy_release_rates(
    const PerSubproblem<const ElasticSubproblem *> &subproblems,
    const Interface                                &interface,
    const Solutions                                &w,
    const dealii::BlockVector<double>              &mu,
    const std::vector<CrackTip>                    &tips);

  /// "x = 0.5" on a straight horizontal Sigma along x, else "s = ..., (x,
  /// y) = (..., ...)": where a tip is, for the terminal and the notes.
  std::string
  tip_position(const CrackTip &tip, const bool along_x);

  /**
   * One line per tip for the heads of table.txt and table.csv (after "# "):
   * "tip k: x = ..., grows towards -x" (on a straight horizontal Sigma along
   * x) or "tip k: s = ..., (x, y) = (..., ...), grows along (..., ...)":
   * which tip the columns G tip k, dG tip k describe.
   */
  std::vector<std::string>
  tip_notes(const std::vector<EnergyReleaseRate> &release, const bool along_x);

  /**
   * One line per tip for the head of interface-NN.csv: where the tip is,
   * its direction of growth, G and its parts, the error bar dG and its
   * estimator, the support radius; with @p interface >= 0 only the tips of
   * that interface (numbered as among all).
   */
  std::vector<std::string>
  release_notes(const std::vector<EnergyReleaseRate> &release,
                const bool                            along_x,
                const int                             interface = -1);
} // namespace bilayer

#endif
