#include <deal.II/base/numbers.h>
#include <deal.II/base/symmetric_tensor.h>

#include <bilayer/postprocess/arc_tangent.h>
#include <bilayer/postprocess/fracture.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    using Piece = InterfaceCurve::Piece;
    using fracture::arc_tangent;

    /// The closest point of the @p piece of Sigma to @p x: its distance,
    /// the unit tangent @p t there (direction of increasing s) and the
    /// gradient @p grad_t of that tangent as a function of x (0 on a
    /// segment and where the closest point is an end of an arc,
    /// J (I - e e^T) / |x - c| inside the angles of an arc, e = (x - c) /
    /// |x - c|).
    double
    closest_tangent(const Piece    &piece,
                    const Point<2> &x,
                    Tensor<1, 2>   &t,
                    Tensor<2, 2>   &grad_t)
    {
      grad_t = Tensor<2, 2>();
      if (piece.kind == Piece::Kind::segment)
        {
          t = piece.tau;
          const double l =
            std::clamp((x - piece.a) * piece.tau, 0., piece.length);
          return (x - (piece.a + l * piece.tau)).norm();
        }
      const double       sign = piece.sweep >= 0 ? 1. : -1.;
      const double       r    = (x - piece.centre).norm();
      const Tensor<1, 2> e    = (x - piece.centre) / r,
                         ea   = (piece.a - piece.centre) /
                              piece.a.distance(piece.centre);
      double angle = sign * std::atan2(ea[0] * e[1] - ea[1] * e[0], ea * e);
      if (angle < 0)
        angle += 2 * numbers::PI;
      if (angle <= std::abs(piece.sweep))
        {
          t = sign * Tensor<1, 2>({-e[1], e[0]});
          // J (I - e e^T) / r: d (J e) / dx.
          Tensor<2, 2> J;
          J[0][1]        = -1;
          J[1][0]        = 1;
          Tensor<2, 2> P = unit_symmetric_tensor<2>();
          P -= outer_product(e, e);
          grad_t = sign / r * (J * P);
          return std::abs(r - piece.radius);
        }
      const double to_a = x.distance(piece.a), to_b = x.distance(piece.b);
      t = arc_tangent(piece, to_a <= to_b ? piece.a : piece.b);
      return std::min(to_a, to_b);
    }
  } // namespace


  ThetaField::ThetaField(const CrackTip &tip)
    : tip(tip)
  {
    if (tip.arc)
      {
        // J (tip - centre) / radius is the counter-clockwise unit tangent.
        const Tensor<1, 2> r = tip.point - tip.centre;
        const Tensor<1, 2> t({-r[1], r[0]});
        omega = (t * tip.direction) > 0 ? 1. : -1.;
      }
  }


  double
  ThetaField::cutoff(const double r) const
  {
    const double R = tip.support_radius, r0 = 0.5 * R;
    if (r <= r0)
      return 1;
    if (r >= R)
      return 0;
    const double t = (r - r0) / (R - r0);
    return 1 - t * t * t * (10 - 15 * t + 6 * t * t);
  }


  void
  ThetaField::junction_tangent(const Point<2> &x,
                               Tensor<1, 2>   &T,
                               Tensor<2, 2>   &grad_T) const
  {
    // The piece of Sigma closest to x; the regions of two pieces meet on
    // the normal line at their junction, where both tangents agree.
    double best = std::numeric_limits<double>::max();
    for (const Piece &piece : tip.chain)
      {
        Tensor<1, 2> t;
        Tensor<2, 2> g;
        const double distance = closest_tangent(piece, x, t, g);
        if (distance < best)
          {
            best   = distance;
            T      = tip.sign * t;
            grad_T = tip.sign * g;
          }
      }
  }


  double
  ThetaField::curvature(const Point<2> &x, const Tensor<1, 2> &nu) const
  {
    if (tip.chain.empty())
      return ((tip.centre - x) * nu) / (tip.radius * tip.radius);
    double       best  = std::numeric_limits<double>::max();
    const Piece *where = nullptr;
    for (const Piece &piece : tip.chain)
      {
        const double distance = InterfaceCurve::distance(piece, x);
        if (distance < best)
          best = distance, where = &piece;
      }
    if (where == nullptr || where->kind == Piece::Kind::segment)
      return 0;
    return ((where->centre - x) * nu) / (where->radius * where->radius);
  }


  Tensor<1, 2>
  ThetaField::value(const Point<2> &x) const
  {
    const double psi = cutoff((x - tip.point).norm());
    if (psi == 0)
      return Tensor<1, 2>();
    if (!tip.chain.empty())
      {
        Tensor<1, 2> T;
        Tensor<2, 2> grad_T;
        junction_tangent(x, T, grad_T);
        return psi * T;
      }
    if (!tip.arc)
      return psi * tip.direction;
    const Tensor<1, 2> r = x - tip.centre;
    return psi * omega / tip.radius * Tensor<1, 2>({-r[1], r[0]});
  }


  Tensor<2, 2>
  ThetaField::gradient(const Point<2> &x) const
  {
    const Tensor<1, 2> d = x - tip.point;
    const double       r = d.norm();
    const double       R = tip.support_radius, r0 = 0.5 * R;
    Tensor<2, 2>       g;
    if (r >= R)
      return g;
    Tensor<1, 2> T = tip.direction;
    if (!tip.chain.empty())
      {
        Tensor<2, 2> grad_T;
        junction_tangent(x, T, grad_T);
        g = cutoff(r) * grad_T;
      }
    else if (tip.arc)
      {
        const Tensor<1, 2> c = x - tip.centre;
        T                    = omega / tip.radius * Tensor<1, 2>({-c[1], c[0]});
        const double psi     = cutoff(r);
        g[0][1]              = -psi * omega / tip.radius;
        g[1][0]              = psi * omega / tip.radius;
      }
    if (r > r0)
      {
        const double t    = (r - r0) / (R - r0);
        const double dpsi = -30 * t * t * (1 - t) * (1 - t) / (R - r0);
        const auto   e_r  = d / r;
        g += outer_product(T, dpsi * e_r);
      }
    return g;
  }

} // namespace bilayer
