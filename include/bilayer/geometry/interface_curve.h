#ifndef bilayer_interface_curve_h
#define bilayer_interface_curve_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <bilayer/core/layout.h>

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace bilayer
{
  /**
   * @p v divided by its length, component by component (deal.II's Tensor
   * division multiplies by the inverse, which is not exact: (v, 0) would
   * not become (1, 0) for every v, and the frames of a straight Sigma would
   * not be exactly its axes).
   */
  inline dealii::Tensor<1, 2>
  unit_vector(const dealii::Tensor<1, 2> &v)
  {
    const double length = v.norm();
    return dealii::Tensor<1, 2>({v[0] / length, v[1] / length});
  }

  /// The unit tangent of the frame with unit normal @p normal (the
  /// direction of growing s): the normal turned by -90 degrees.
  inline dealii::Tensor<1, 2>
  tangent_of(const dealii::Tensor<1, 2> &normal)
  {
    return dealii::Tensor<1, 2>({normal[1], -normal[0]});
  }

  /**
   * The circle through the points @p p, if they are not collinear and all
   * lie on one circle (relative tolerance 1e-8): (centre, radius). The
   * curves of a Gmsh scene whose nodes it fits are arcs of Sigma.
   */
  std::optional<std::pair<dealii::Point<2>, double>>
  fit_circle(const std::vector<dealii::Point<2>> &p);

  /**
   * The interface Sigma as a geometric curve: a chain of straight segments
   * and circular arcs from one end on the outer boundary to the other, with
   * its parametrisation s (arc length plus a constant), the point and the
   * unit normal at s, the crack gamma_c as a set of s-intervals (CrackSet)
   * and which of its two ends lie on Gamma_D.
   *
   * Every quantity "along Sigma" in the program (the break points of the
   * traces, the multiplier nodes, the Gauss points of the coupling, the
   * crack pieces, the interface CSV) is a value of s; every vector on Sigma
   * that is split into normal and tangential parts uses normal(s). The
   * straight horizontal Sigma of the built-in rectangle is the special case
   * of one segment with s = x and nu = (0, 1).
   *
   * Orientation: s grows so that Omega+ lies on the left; the normal
   * nu = (-tau_y, tau_x) is the tangent tau turned by +90 degrees, so it
   * points from Omega- into Omega+ (the outer normal of Omega-) and the
   * jump [u].nu = (u+ - u-).nu >= 0 is the non-penetration condition.
   *
   * At a point where two pieces meet (a corner of a polygonal Sigma, the
   * junction of a segment and an arc) the normal is the normalised sum of
   * the two pieces' normals there: nodal normals of mortar contact, so that
   * the multiplier at a corner node acts along the bisector.
   */
  class InterfaceCurve
  {
  public:
    /// One piece of the chain: a segment from a to b, or an arc of the
    /// circle (centre, radius) from a to b turning by the signed angle
    /// sweep (radians, negative for a clockwise arc); phi0 is the angle
    /// of a (set by the constructor).
    struct Piece
    {
      enum class Kind
      {
        segment,
        arc
      };
      Kind             kind = Kind::segment;
      dealii::Point<2> a, b;
      dealii::Point<2> centre;
      double           radius = 0, sweep = 0, phi0 = 0;
      /// Parameter s at the start of the piece and its length.
      double s0 = 0, length = 0;
      /// Segment: s = dot(p, tau) + offset (exact s = x for the horizontal
      /// segment of the rectangle).
      dealii::Tensor<1, 2> tau;
      double               offset = 0;
      /// Whether the piece continues the previous one as the next chord of
      /// one curve given only by its polygon (a curved Gmsh curve that is
      /// neither straight nor a circle): their junction is no corner of
      /// Sigma (the turn there is O(h)).
      bool continues = false;
    };

    InterfaceCurve() = default;

    /**
     * The chain through @p pieces (each given by kind and end points, arcs
     * also by centre and radius), starting at s = @p s_begin. Checks that
     * consecutive pieces meet.
     */
    InterfaceCurve(std::vector<Piece> pieces, const double s_begin);

    /// The straight segment from @p a to @p b with s = the coordinate along
    /// it measured from the origin's projection (s = x for a horizontal
    /// segment pointing in +x).
    static InterfaceCurve
    segment(const dealii::Point<2> &a, const dealii::Point<2> &b);

    /**
     * Whether s is a corner of Sigma: a junction of two pieces whose
     * tangents differ there (not a chord of a curve given by its polygon,
     * Piece::continues). Then @p before and @p after are the unit normals
     * (into Omega+) of the piece ending and of the piece starting at s.
     */
    bool
    corner(const double          s,
           dealii::Tensor<1, 2> &before,
           dealii::Tensor<1, 2> &after) const;

    /// Parameter of the point of Sigma closest to @p p.
    double
    parameter(const dealii::Point<2> &p) const;

    /// Distance of @p p from the curve.
    double
    distance(const dealii::Point<2> &p) const;

    /// Distance of @p p from one @p piece of the curve.
    static double
    distance(const Piece &piece, const dealii::Point<2> &p);

    dealii::Point<2>
    point(const double s) const;

    /// Unit normal from Omega- into Omega+ at s (the bisector where two
    /// pieces meet).
    dealii::Tensor<1, 2>
    normal(const double s) const;

    double
    s_begin() const
    {
      return pieces_.empty() ? 0. : pieces_.front().s0;
    }
    double
    s_end() const
    {
      return pieces_.empty() ? 0. : pieces_.back().s0 + pieces_.back().length;
    }
    /// The sum of the pieces' lengths.
    double
    length() const
    {
      double sum = 0;
      for (const auto &piece : pieces_)
        sum += piece.length;
      return sum;
    }

    /// A tolerance for comparing values of s: 1e-10 times the length.
    double
    tolerance() const
    {
      return 1e-10 * length();
    }

    const std::vector<Piece> &
    pieces() const
    {
      return pieces_;
    }

    /// Reverse the direction of s (and so of the normal), keeping s_begin.
    void
    reverse();

    /// The crack pieces, told the ends of Sigma (a piece that reaches one
    /// is an edge crack: CrackSet::mouth()).
    void
    set_crack(const CrackSet &crack)
    {
      crack_ = crack;
      crack_.set_sigma_ends(s_begin(), s_end());
    }

    /**
     * Why @p crack cannot be the crack on this curve, empty if it can: its
     * pieces must be non-empty, ordered, disjoint and inside Sigma; a piece
     * may reach an end of Sigma (an edge crack, its mouth on the outer
     * boundary) only where that end is not on Gamma_D of either side
     * (gamma_c and Gamma_D are disjoint: end_on_gamma_d()), and some of
     * Sigma must stay glued (no piece covers all of it), unless
     * @p whole_allowed (a cohesive zone: its springs hold the regions).
     */
    std::string
    crack_refusal(const CrackSet &crack,
                  const bool      whole_allowed = false) const;
    const CrackSet &
    crack() const
    {
      return crack_;
    }

    /**
     * Which ends of Sigma are clamped on which side: @p clamped[d][k] is
     * true if the end node k (0 at s_begin, 1 at s_end) of subdomain d
     * (index of Subdomain: 0 for Omega-, 1 for Omega+) lies on a clamped
     * boundary edge of that subdomain (both layers prescribed there).
     */
    void
    set_clamped_ends(const std::array<std::array<bool, 2>, 2> &clamped)
    {
      clamped_ends = clamped;
    }

    /**
     * Which ends of the curve (0 at s_begin, 1 at s_end) lie inside the
     * specimen: cross-points, where it meets other interfaces (three
     * regions or more meet there). A crack must not reach them
     * (crack_refusal()).
     */
    void
    set_inner_ends(const std::array<bool, 2> &inner)
    {
      inner_ends = inner;
    }

    /**
     * Whether the point s of Sigma is an end of Sigma on Gamma_D for the
     * gluing across Sigma: the end node is clamped on both sides, so that
     * the jump there is fixed by the Dirichlet data alone.
     */
    bool
    on_gamma_d(const double s) const;

    /**
     * Whether the point s of Sigma is an end of Sigma whose node of
     * subdomain @p d (0 for Omega-, 1 for Omega+) is clamped: the gluing
     * of the two layers on that subdomain is fixed there by the Dirichlet
     * data.
     */
    bool
    on_gamma_d(const double s, const unsigned int d) const;

    /**
     * Whether end @p k of Sigma (0 at s_begin, 1 at s_end) lies on Gamma_D
     * of either side (its end node of Omega- or of Omega+ is clamped): a
     * crack must not reach it.
     */
    bool
    end_on_gamma_d(const unsigned int k) const
    {
      return clamped_ends[0][k] || clamped_ends[1][k];
    }

    /// "segment", "arc" or "polyline of N pieces" for the run header.
    std::string
    description() const;

  private:
    /// Index of the piece that holds s.
    unsigned int
    piece_at(const double s) const;

    static dealii::Tensor<1, 2>
    piece_normal(const Piece &piece, const double s);

    std::vector<Piece>                 pieces_;
    CrackSet                           crack_;
    std::array<std::array<bool, 2>, 2> clamped_ends = {
      {{{false, false}}, {{false, false}}}};
    std::array<bool, 2> inner_ends = {{false, false}};
  };
} // namespace bilayer

#endif
