#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <bilayer/geometry/interface_curve.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// Angle @p phi relative to @p phi0 along the direction @p sign,
    /// in [0, 2 pi).
    double
    angle_from(const double phi, const double phi0, const double sign)
    {
      double d = sign * (phi - phi0);
      d        = std::fmod(d, 2 * numbers::PI);
      if (d < 0)
        d += 2 * numbers::PI;
      return d;
    }

    double
    arc_sign(const InterfaceCurve::Piece &piece)
    {
      return piece.sweep >= 0 ? 1. : -1.;
    }

    /// Parameter of the point of @p piece closest to @p p, and the distance.
    std::pair<double, double>
    project(const InterfaceCurve::Piece &piece, const Point<2> &p)
    {
      if (piece.kind == InterfaceCurve::Piece::Kind::segment)
        {
          const double   s = std::clamp(p * piece.tau + piece.offset,
                                      piece.s0,
                                      piece.s0 + piece.length);
          const Point<2> q = piece.a + (s - piece.s0) * piece.tau;
          return {s, p.distance(q)};
        }
      const double sign = arc_sign(piece);
      const double phi =
        std::atan2(p[1] - piece.centre[1], p[0] - piece.centre[0]);
      const double d     = angle_from(phi, piece.phi0, sign);
      const double range = std::abs(piece.sweep);
      if (d <= range)
        return {piece.s0 + piece.radius * d,
                std::abs(p.distance(piece.centre) - piece.radius)};
      // Outside the arc's angles: the nearer end.
      const double to_a = p.distance(piece.a), to_b = p.distance(piece.b);
      return to_a <= to_b ? std::make_pair(piece.s0, to_a) :
                            std::make_pair(piece.s0 + piece.length, to_b);
    }
  } // namespace


  std::optional<std::pair<Point<2>, double>>
  fit_circle(const std::vector<Point<2>> &p)
  {
    if (p.size() < 3)
      return std::nullopt;
    // Three well separated points: the first, the farthest from it, the
    // farthest from the line through both.
    const Point<2> a = p[0];
    Point<2>       b = a;
    for (const auto &q : p)
      if (q.distance(a) > b.distance(a))
        b = q;
    const double ab  = a.distance(b);
    Point<2>     c   = a;
    double       off = 0;
    for (const auto &q : p)
      {
        const Tensor<1, 2> d = q - a, e = (b - a) / ab;
        const double       h = std::abs(d[0] * e[1] - d[1] * e[0]);
        if (h > off)
          {
            off = h;
            c   = q;
          }
      }
    if (off <= 1e-8 * ab)
      return std::nullopt;
    // Circumcentre of a, b, c.
    const double d =
      2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
    const double a2 = a.norm_square(), b2 = b.norm_square(),
                 c2 = c.norm_square();
    const Point<2> centre(
      (a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d,
      (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d);
    const double radius = centre.distance(a);
    for (const auto &q : p)
      if (std::abs(centre.distance(q) - radius) > 1e-8 * radius)
        return std::nullopt;
    return std::make_pair(centre, radius);
  }


  InterfaceCurve::InterfaceCurve(std::vector<Piece> pieces, const double start)
    : pieces_(std::move(pieces))
  {
    double s = start;
    for (auto &piece : pieces_)
      {
        piece.s0 = s;
        if (piece.kind == Piece::Kind::segment)
          {
            piece.length = piece.a.distance(piece.b);
            AssertThrow(piece.length > 0,
                        ExcMessage("Sigma has a piece of zero length at (" +
                                   std::to_string(piece.a[0]) + ", " +
                                   std::to_string(piece.a[1]) + ")"));
            piece.tau    = unit_vector(piece.b - piece.a);
            piece.offset = piece.s0 - piece.a * piece.tau;
          }
        else
          {
            piece.phi0   = std::atan2(piece.a[1] - piece.centre[1],
                                    piece.a[0] - piece.centre[0]);
            piece.length = piece.radius * std::abs(piece.sweep);
          }
        s += piece.length;
      }
    for (unsigned int i = 1; i < pieces_.size(); ++i)
      AssertThrow(pieces_[i - 1].b.distance(pieces_[i].a) <= 1e-8 * (s - start),
                  ExcMessage("the pieces of Sigma do not form a chain"));
  }


  InterfaceCurve
  InterfaceCurve::segment(const Point<2> &a, const Point<2> &b)
  {
    Piece piece;
    piece.a             = a;
    piece.b             = b;
    const double length = a.distance(b);
    AssertThrow(length > 0, ExcMessage("Sigma has zero length"));
    const Tensor<1, 2> tau = unit_vector(b - a);
    return InterfaceCurve({piece}, a * tau);
  }


  unsigned int
  InterfaceCurve::piece_at(const double s) const
  {
    unsigned int i = 0;
    while (i + 1 < pieces_.size() && s >= pieces_[i + 1].s0)
      ++i;
    return i;
  }


  double
  InterfaceCurve::parameter(const Point<2> &p) const
  {
    double best = std::numeric_limits<double>::max(), s = 0;
    for (const auto &piece : pieces_)
      {
        const auto [t, d] = project(piece, p);
        if (d < best)
          {
            best = d;
            s    = t;
          }
      }
    return s;
  }


  double
  InterfaceCurve::distance(const Point<2> &p) const
  {
    double best = std::numeric_limits<double>::max();
    for (const auto &piece : pieces_)
      best = std::min(best, project(piece, p).second);
    return best;
  }


  double
  InterfaceCurve::distance(const Piece &piece, const Point<2> &p)
  {
    return project(piece, p).second;
  }


  Point<2>
  InterfaceCurve::point(const double s) const
  {
    const Piece &piece = pieces_[piece_at(s)];
    const double t     = std::clamp(s - piece.s0, 0., piece.length);
    if (piece.kind == Piece::Kind::segment)
      return piece.a + t * piece.tau;
    const double phi = piece.phi0 + arc_sign(piece) * t / piece.radius;
    return piece.centre +
           piece.radius * Tensor<1, 2>({std::cos(phi), std::sin(phi)});
  }


  Tensor<1, 2>
  InterfaceCurve::piece_normal(const Piece &piece, const double s)
  {
    if (piece.kind == Piece::Kind::segment)
      return Tensor<1, 2>({-piece.tau[1], piece.tau[0]});
    const double t   = std::clamp(s - piece.s0, 0., piece.length);
    const double phi = piece.phi0 + arc_sign(piece) * t / piece.radius;
    // Tangent of the arc in the direction of growing s, turned by +90.
    const double sign = arc_sign(piece);
    return Tensor<1, 2>({-sign * std::cos(phi), -sign * std::sin(phi)});
  }


  Tensor<1, 2>
  InterfaceCurve::normal(const double s) const
  {
    const unsigned int i = piece_at(s);
    Tensor<1, 2>       n = piece_normal(pieces_[i], s);
    // At a junction of two pieces: the bisector.
    const double tol = tolerance();
    if (i > 0 && std::abs(s - pieces_[i].s0) <= tol)
      n += piece_normal(pieces_[i - 1], s);
    else if (i + 1 < pieces_.size() && std::abs(s - pieces_[i + 1].s0) <= tol)
      n += piece_normal(pieces_[i + 1], s);
    else
      return n;
    return unit_vector(n);
  }


  bool
  InterfaceCurve::corner(const double  s,
                         Tensor<1, 2> &before,
                         Tensor<1, 2> &after) const
  {
    const unsigned int i   = piece_at(s);
    const double       tol = tolerance();
    // The junction at the start of piece j (j >= 1) if s is there.
    unsigned int j = 0;
    if (i > 0 && std::abs(s - pieces_[i].s0) <= tol)
      j = i;
    else if (i + 1 < pieces_.size() && std::abs(s - pieces_[i + 1].s0) <= tol)
      j = i + 1;
    if (j == 0 || pieces_[j].continues)
      return false;
    const double s0 = pieces_[j].s0;
    before          = piece_normal(pieces_[j - 1], s0);
    after           = piece_normal(pieces_[j], s0);
    // Different tangents: the angle between the normals above 1e-8.
    return std::abs(before[0] * after[1] - before[1] * after[0]) > 1e-8 ||
           before * after < 0;
  }


  void
  InterfaceCurve::reverse()
  {
    const double       start = s_begin();
    std::vector<Piece> reversed;
    for (auto it = pieces_.rbegin(); it != pieces_.rend(); ++it)
      {
        Piece piece = *it;
        std::swap(piece.a, piece.b);
        piece.sweep = -piece.sweep;
        // The junction at the new start is the one at the old end.
        piece.continues = it != pieces_.rbegin() && std::prev(it)->continues;
        reversed.push_back(piece);
      }
    const double length = this->length();
    // The crack pieces in the new parameter.
    std::vector<CrackSet::Piece> cracks;
    for (const auto &c : crack_.pieces())
      cracks.push_back(
        {start + (start + length - c.end), start + (start + length - c.start)});
    std::reverse(cracks.begin(), cracks.end());
    // The clamped and inner ends, kept across the assignment below (which
    // resets them) and swapped: the end at s_begin is the old end at s_end.
    auto clamped = clamped_ends;
    for (auto &ends : clamped)
      std::swap(ends[0], ends[1]);
    const std::array<bool, 2> inner = {{inner_ends[1], inner_ends[0]}};
    *this                           = InterfaceCurve(reversed, start);
    set_crack(CrackSet(cracks, tolerance()));
    clamped_ends = clamped;
    inner_ends   = inner;
  }


  bool
  InterfaceCurve::on_gamma_d(const double s) const
  {
    return on_gamma_d(s, 0) && on_gamma_d(s, 1);
  }


  bool
  InterfaceCurve::on_gamma_d(const double s, const unsigned int d) const
  {
    AssertIndexRange(d, 2);
    const double tol = tolerance();
    return (clamped_ends[d][0] && std::abs(s - s_begin()) < tol) ||
           (clamped_ends[d][1] && std::abs(s - s_end()) < tol);
  }


  std::string
  InterfaceCurve::crack_refusal(const CrackSet &crack,
                                const bool      whole_allowed) const
  {
    const double tol          = tolerance();
    const auto  &pieces       = crack.pieces();
    double       previous_end = s_begin() - 2 * tol;
    for (const auto &piece : pieces)
      {
        std::ostringstream m;
        m << std::setprecision(10) << "the crack piece (" << piece.start << ", "
          << piece.end << ") of Sigma";
        if (!(piece.start + tol < piece.end))
          return m.str() + " is empty or reversed";
        if (!(piece.start > previous_end + tol && piece.end <= s_end() + tol))
          {
            m << " overlaps the piece before it or lies outside Sigma (s in ["
              << s_begin() << ", " << s_end() << "])";
            return m.str();
          }
        previous_end        = piece.end;
        const bool at_begin = std::abs(piece.start - s_begin()) <= tol,
                   at_end   = std::abs(piece.end - s_end()) <= tol;
        if (at_begin && at_end && !whole_allowed)
          {
            m << " covers all of Sigma (s in [" << s_begin() << ", " << s_end()
              << "]): some of Sigma must stay glued";
            return m.str();
          }
        for (const unsigned int k : {0u, 1u})
          if ((k == 0 ? at_begin : at_end) && inner_ends[k])
            {
              m << " reaches the end s = " << (k == 0 ? s_begin() : s_end())
                << ", a cross-point inside the specimen where other "
                   "interfaces meet it: a crack must end before a point "
                   "where three regions meet";
              return m.str();
            }
        for (const unsigned int k : {0u, 1u})
          if ((k == 0 ? at_begin : at_end) && end_on_gamma_d(k))
            {
              m << " reaches the end s = " << (k == 0 ? s_begin() : s_end())
                << " of Sigma, which lies on Gamma_D (clamped): a crack must "
                   "not reach Gamma_D (an edge crack needs a free or loaded "
                   "boundary at its mouth)";
              return m.str();
            }
      }
    return "";
  }


  std::string
  InterfaceCurve::description() const
  {
    std::ostringstream out;
    unsigned int       arcs = 0;
    for (const auto &piece : pieces_)
      arcs += piece.kind == Piece::Kind::arc;
    out << pieces_.size() << (pieces_.size() == 1 ? " piece" : " pieces");
    if (arcs > 0)
      out << " (" << arcs << (arcs == 1 ? " arc" : " arcs") << ")";
    out << ", length " << length();
    return out.str();
  }
} // namespace bilayer
