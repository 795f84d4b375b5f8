// Unit tests of the geometry of Sigma (InterfaceCurve), the mortar choice
// of the multiplier spaces (MultiplierSpace) and the coupling of the
// multipliers to the traces (TraceCoupling) on tiny hand-made inputs.
//
// Every printed number has a reason to be right, stated beside it and
// checked (yes/NO):
// - InterfaceCurve: a segment from (1, 1) to (4, 5) has length 5, tangent
//   (0.6, 0.8), s = p.tau (s_begin = 1.4), normal (-0.8, 0.6) (the tangent
//   turned by +90 degrees); two segments with a corner at s = 1 have the
//   two pieces' normals there and their bisector as normal(1); a circular
//   arc of radius 2 about the origin has |p - c| = R, length R |sweep|,
//   unit normals orthogonal to the tangent dp/ds (central differences),
//   pointing to the centre on a counter-clockwise arc (Omega+ on the left)
//   and away from it on a clockwise one; an arc followed by a segment along
//   its end tangent has no corner; distances are those of elementary
//   geometry; the crack set excludes its tips.
// - MultiplierSpace: choose() takes on each macro segment between shared
//   points the trace with more segments (finer) or fewer (coarser), Omega-
//   on a tie; the nodes per block are n_segments * degree + 1; D = the
//   integrals of the hat functions (h/2 at the ends, (h_l + h_r) / 2
//   inside, Simpson's weights h/6, 4h/6 for P2); a corner inside the crack
//   has the two pieces' normals as frame and two contact components in
//   [0, p]; the weighted nodal normal at the corner is (-1, 2) / sqrt(5)
//   (int phi_a nu_h over the two chords: 1/4 (0, 1) + 1/4 (-1, 1)); at
//   clamped ends of a block with a non-nodal side the end's basis function
//   joins its neighbour (row, weight h/2 + h/2).
// - TraceCoupling on Omega- = (0, 1) x (-1, 0) with 2 cells along Sigma and
//   Omega+ = (0, 1) x (0, 1) with 3 (Q1): every entry of C_- and C_+
//   against an independent integration (3-point Gauss rule on the common
//   refinement, hat functions and the dual basis psi = 2 phi_l - phi_r
//   written out here); four entries by hand (7/72, 1/4, -1/72 for the dual
//   basis, 23/108 for the Lagrange basis); row sums = int phi_a ds (the
//   traces of P1/Q1 sum to one); C w and C^T mu adjoint; the traces of
//   the linear field (x, 2x) at the nodes and Gauss points are (x, 2x).

#include <deal.II/base/function.h>
#include <deal.II/base/numbers.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <bilayer/geometry/geometry.h>
#include <bilayer/geometry/interface_curve.h>
#include <bilayer/interface/interface.h>
#include <bilayer/interface/multiplier_space.h>
#include <bilayer/interface/trace_coupling.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/subproblem/subproblem.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  constexpr double pi = numbers::PI;

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << yes(ok) << "\n";
  }

  bool
  close(const double a, const double b, const double tol = 1e-13)
  {
    return std::abs(a - b) <= tol;
  }

  bool
  close(const Tensor<1, 2> &a, const Tensor<1, 2> &b, const double tol = 1e-13)
  {
    return (a - b).norm() <= tol;
  }

  std::string
  str(const Tensor<1, 2> &v)
  {
    std::ostringstream s;
    s << std::setprecision(10) << "(" << v[0] << ", " << v[1] << ")";
    return s.str();
  }

  std::string
  str(const std::vector<double> &v)
  {
    std::ostringstream s;
    s << std::setprecision(10);
    for (unsigned int i = 0; i < v.size(); ++i)
      s << (i == 0 ? "" : " ") << v[i];
    return s.str();
  }

  InterfaceCurve::Piece
  segment_piece(const Point<2> &a, const Point<2> &b)
  {
    InterfaceCurve::Piece piece;
    piece.a = a;
    piece.b = b;
    return piece;
  }

  InterfaceCurve::Piece
  arc_piece(const Point<2> &centre,
            const double    radius,
            const double    phi_a,
            const double    sweep)
  {
    InterfaceCurve::Piece piece;
    piece.kind   = InterfaceCurve::Piece::Kind::arc;
    piece.centre = centre;
    piece.radius = radius;
    piece.sweep  = sweep;
    piece.a =
      centre + radius * Tensor<1, 2>({std::cos(phi_a), std::sin(phi_a)});
    piece.b = centre + radius * Tensor<1, 2>({std::cos(phi_a + sweep),
                                              std::sin(phi_a + sweep)});
    return piece;
  }

  const char *
  kind(const InterfaceCurve::Piece &piece)
  {
    return piece.kind == InterfaceCurve::Piece::Kind::arc ? "arc" : "segment";
  }

  void
  print_pieces(const InterfaceCurve &curve)
  {
    for (const auto &piece : curve.pieces())
      {
        std::cout << "  piece " << kind(piece) << " s0 = " << piece.s0
                  << " length = " << piece.length;
        if (piece.kind == InterfaceCurve::Piece::Kind::arc)
          std::cout << " centre = " << str(piece.centre)
                    << " radius = " << piece.radius;
        std::cout << "\n";
      }
  }

  // ------------------------------------------------------------------
  void
  straight_sigma()
  {
    std::cout << "InterfaceCurve: segment (1, 1) -> (4, 5)\n";
    const InterfaceCurve curve =
      InterfaceCurve::segment(Point<2>(1, 1), Point<2>(4, 5));
    std::cout << "  s_begin = " << curve.s_begin()
              << " s_end = " << curve.s_end()
              << " tolerance = " << curve.tolerance() << "\n";
    print_pieces(curve);
    // s = p.tau, tau = (0.6, 0.8): s_begin = 0.6 + 0.8, s_end = 1.4 + 5.
    check("s_begin = 1.4, s_end = 6.4, length 5",
          close(curve.s_begin(), 1.4) && close(curve.s_end(), 6.4) &&
            close(curve.length(), 5));
    check("tolerance = 1e-10 * length", close(curve.tolerance(), 5e-10, 1e-24));
    const Point<2> p = curve.point(1.4 + 2.5);
    std::cout << "  point(3.9) = " << str(p)
              << " normal(3.9) = " << str(curve.normal(3.9)) << "\n";
    check("point(s_begin + 2.5) = midpoint (2.5, 3)",
          close(p, Point<2>(2.5, 3)));
    check("normal = tangent turned by +90 = (-0.8, 0.6)",
          close(curve.normal(3.9), Tensor<1, 2>({-0.8, 0.6})));
    check("tangent_of(normal) = (0.6, 0.8)",
          close(tangent_of(curve.normal(3.9)), Tensor<1, 2>({0.6, 0.8})));
    // A point at distance 2 along the normal from a: projects onto a.
    const Point<2> q = Point<2>(1, 1) + 2 * Tensor<1, 2>({-0.8, 0.6});
    std::cout << "  distance(piece, a + 2 nu) = "
              << InterfaceCurve::distance(curve.pieces()[0], q)
              << " parameter = " << curve.parameter(q) << "\n";
    check("distance of a + 2 nu is 2, its parameter s_begin",
          close(InterfaceCurve::distance(curve.pieces()[0], q), 2) &&
            close(curve.parameter(q), 1.4));
    // Beyond the end b = (4, 5) along tau: the distance to b.
    const Point<2> r = Point<2>(4, 5) + 3 * Tensor<1, 2>({0.6, 0.8});
    check("distance of b + 3 tau is 3 (the nearer end)",
          close(curve.distance(r), 3));
    Tensor<1, 2> before, after;
    check("no corner on a segment", !curve.corner(3.9, before, after));

    // The horizontal segment of the rectangle: s = x, nu = (0, 1) exactly.
    const InterfaceCurve flat =
      InterfaceCurve::segment(Point<2>(-2, 0.5), Point<2>(3, 0.5));
    check("horizontal segment: s = x, normal exactly (0, 1)",
          flat.s_begin() == -2 && flat.s_end() == 3 &&
            flat.normal(0.3) == Tensor<1, 2>({0., 1.}) &&
            close(flat.point(0.3), Point<2>(0.3, 0.5)));

    // The crack set: open pieces, the tips are glued.
    CrackSet crack({{0.5, 1.5}}, 1e-10);
    check("crack (0.5, 1.5) contains 1, 0.5 + 1e-6, 1.5 - 1e-6",
          crack.contains(1.) && crack.contains(0.5 + 1e-6) &&
            crack.contains(1.5 - 1e-6));
    check("crack tips 0.5, 1.5 (also within 1e-11) and 0.4, 1.6 outside",
          !crack.contains(0.5) && !crack.contains(1.5) &&
            !crack.contains(0.5 + 1e-11) && !crack.contains(1.5 - 1e-11) &&
            !crack.contains(0.4) && !crack.contains(1.6));
  }

  // ------------------------------------------------------------------
  /// (0, 0) -> (1, 0) -> (2, 1): a corner of 45 degrees at s = 1.
  InterfaceCurve
  corner_curve()
  {
    return InterfaceCurve({segment_piece(Point<2>(0, 0), Point<2>(1, 0)),
                           segment_piece(Point<2>(1, 0), Point<2>(2, 1))},
                          0.);
  }

  void
  polygonal_sigma()
  {
    std::cout << "InterfaceCurve: polygon (0, 0) -> (1, 0) -> (2, 1)\n";
    const InterfaceCurve curve = corner_curve();
    const double         r2    = std::sqrt(2.);
    std::cout << "  s_begin = " << curve.s_begin()
              << " s_end = " << std::setprecision(10) << curve.s_end()
              << std::setprecision(6) << "\n";
    print_pieces(curve);
    check("pieces: segments of length 1 and sqrt(2), s0 = 0 and 1",
          curve.pieces().size() == 2 && curve.pieces()[1].s0 == 1. &&
            close(curve.pieces()[1].length, r2) &&
            close(curve.s_end(), 1 + r2));
    const Tensor<1, 2> nu0({0., 1.}), nu1({-1 / r2, 1 / r2});
    Tensor<1, 2>       before, after;
    const bool         at_corner = curve.corner(1., before, after);
    std::cout << "  corner(1): " << at_corner << " before " << str(before)
              << " after " << str(after) << "\n";
    check("corner at s = 1 with normals (0, 1) and (-1, 1)/sqrt(2)",
          at_corner && close(before, nu0) && close(after, nu1));
    check("corner found within the tolerance (s = 1 + 1e-12)",
          curve.corner(1. + 1e-12, before, after));
    check("no corner at s = 0.5, 1.5 nor at the ends",
          !curve.corner(0.5, before, after) &&
            !curve.corner(1.5, before, after) &&
            !curve.corner(0., before, after) &&
            !curve.corner(1 + r2, before, after));
    const Tensor<1, 2> n = curve.normal(1.);
    std::cout << "  normal(1) = " << str(n) << "\n";
    check("normal(1) = unit bisector (nu0 + nu1) / |nu0 + nu1|",
          close(n, (nu0 + nu1) / (nu0 + nu1).norm()) && close(n.norm(), 1));
    check("normal(0.5) = (0, 1), normal(1.5) = (-1, 1)/sqrt(2)",
          close(curve.normal(0.5), nu0) && close(curve.normal(1.5), nu1));
    const Point<2> m = curve.point(1 + r2 / 2);
    std::cout << "  point(1 + sqrt(2)/2) = " << str(m) << "\n";
    check("point(1 + sqrt(2)/2) = (1.5, 0.5), point(0.25) = (0.25, 0)",
          close(m, Point<2>(1.5, 0.5)) &&
            close(curve.point(0.25), Point<2>(0.25, 0)));
    const double d0 = InterfaceCurve::distance(curve.pieces()[0], m),
                 d1 = InterfaceCurve::distance(curve.pieces()[1], m);
    std::cout << "  distance(piece 0, (1.5, 0.5)) = " << d0
              << " distance(piece 1, (1.5, 0.5)) = " << d1 << "\n";
    check("distances: |(1.5, 0.5) - (1, 0)| = sqrt(1/2) and 0",
          close(d0, std::sqrt(0.5)) && close(d1, 0));
    check("distance of (0.5, -0.3) is 0.3, parameter 0.5",
          close(curve.distance(Point<2>(0.5, -0.3)), 0.3) &&
            close(curve.parameter(Point<2>(0.5, -0.3)), 0.5));
    // The same polygon as chords of one curve: no corner.
    auto pieces         = curve.pieces();
    pieces[1].continues = true;
    const InterfaceCurve chords(pieces, 0.);
    check("chords of one curve (continues): no corner at s = 1",
          !chords.corner(1., before, after));
    // Reversed: s_begin kept, s_end the same, normals flipped.
    InterfaceCurve reversed = curve;
    reversed.set_crack(CrackSet({{0.5, 2.}}, curve.tolerance()));
    reversed.reverse();
    check("reversed: same s range, normal(0.5 + sqrt(2)) = -(0, 1), crack "
          "(1 + sqrt(2) - 2, 1 + sqrt(2) - 0.5)",
          close(reversed.s_begin(), 0) && close(reversed.s_end(), 1 + r2) &&
            close(reversed.normal(r2 + 0.5), -nu0) &&
            close(reversed.crack().pieces()[0].start, r2 - 1) &&
            close(reversed.crack().pieces()[0].end, r2 + 0.5));
  }

  /// The ends of Sigma on Gamma_D and the chord flags under reverse().
  void
  ends_and_reverse()
  {
    std::cout << "InterfaceCurve: clamped ends and reverse()\n";
    InterfaceCurve curve = corner_curve();
    const double   r2    = std::sqrt(2.);
    // Omega- clamped at s_begin only, Omega+ at both ends.
    curve.set_clamped_ends({{{{true, false}}, {{true, true}}}});
    check("on Gamma_D: s_begin (both sides), not s_end (Omega- free there)",
          curve.on_gamma_d(0.) && !curve.on_gamma_d(1 + r2) &&
            curve.on_gamma_d(1 + r2, 1) && !curve.on_gamma_d(1 + r2, 0) &&
            !curve.on_gamma_d(1.));
    curve.reverse();
    check("reversed: the ends swap (s_end on Gamma_D, s_begin only for "
          "Omega+)",
          curve.on_gamma_d(1 + r2) && !curve.on_gamma_d(0.) &&
            curve.on_gamma_d(0., 1));
    // Three chords of one curve, the second junction a true corner: the
    // flags follow their junctions when the direction is reversed.
    auto pieces = std::vector<InterfaceCurve::Piece>(
      {segment_piece(Point<2>(0, 0), Point<2>(1, 0)),
       segment_piece(Point<2>(1, 0), Point<2>(2, 0.1)),
       segment_piece(Point<2>(2, 0.1), Point<2>(2, 1))});
    pieces[1].continues = true;
    InterfaceCurve chords(pieces, 0.);
    const double   l0 = 1, l1 = std::sqrt(1.01), l2 = 0.9;
    Tensor<1, 2>   before, after;
    check("chords: no corner at s = 1, a corner at s = 1 + sqrt(1.01)",
          !chords.corner(l0, before, after) &&
            chords.corner(l0 + l1, before, after));
    chords.reverse();
    check("reversed chords: a corner at s = 0.9, none at 0.9 + sqrt(1.01)",
          chords.corner(l2, before, after) &&
            !chords.corner(l2 + l1, before, after));
    std::cout << "  description: " << chords.description() << "\n";
  }

  // ------------------------------------------------------------------
  void
  circular_arc()
  {
    std::cout << "InterfaceCurve: arc of radius 2 about (0, 0), 0 -> pi/2\n";
    const Point<2>       c(0, 0);
    const double         R = 2;
    const InterfaceCurve ccw({arc_piece(c, R, 0, pi / 2)}, 0.);
    print_pieces(ccw);
    check("length R pi/2 = pi, s_end = pi",
          close(ccw.length(), pi) && close(ccw.s_end(), pi));
    bool on_circle = true, unit = true, orthogonal = true, inward = true,
         frame = true;
    for (const double s : {0., 0.3, pi / 2, 2.5, pi})
      {
        const Point<2>     p = ccw.point(s);
        const Tensor<1, 2> n = ccw.normal(s);
        std::cout << "  s = " << s << " point " << str(p) << " normal "
                  << str(n) << "\n";
        // dp/ds by central differences inside, one-sided at the ends.
        const double       h  = 1e-6;
        const double       sa = std::max(s - h, 0.), sb = std::min(s + h, pi);
        const Tensor<1, 2> dp = (ccw.point(sb) - ccw.point(sa)) / (sb - sa);
        on_circle             = on_circle && close(p.distance(c), R, 1e-14);
        unit                  = unit && close(n.norm(), 1, 1e-14);
        orthogonal            = orthogonal && std::abs(n * dp) < 1e-6;
        frame                 = frame && close(tangent_of(n), dp, 1e-6);
        inward                = inward && close(n, -(p - c) / R, 1e-14);
        // The angle of the point is s / R.
        on_circle =
          on_circle &&
          close(p, Point<2>(R * std::cos(s / R), R * std::sin(s / R)));
      }
    check("|p - c| = R and p = c + R (cos s/R, sin s/R)", on_circle);
    check("normals of unit length", unit);
    check("normal orthogonal to dp/ds, tangent_of(normal) = dp/ds",
          orthogonal && frame);
    check("counter-clockwise: normal = -(p - c)/R (to the centre)", inward);
    // The same quarter circle run clockwise: the normal points outward.
    const InterfaceCurve cw({arc_piece(c, R, pi / 2, -pi / 2)}, 0.);
    check("clockwise: point(0) = (0, 2), normal(1) = (p - c)/R",
          close(cw.point(0), Point<2>(0, 2)) &&
            close(cw.normal(1.), (cw.point(1.) - c) / R));
    const auto &arc = ccw.pieces()[0];
    std::cout << "  distance(arc, (3, 0)) = "
              << InterfaceCurve::distance(arc, Point<2>(3, 0))
              << " distance(arc, (0, 0)) = "
              << InterfaceCurve::distance(arc, Point<2>(0, 0))
              << " distance(arc, (1, -3)) = "
              << InterfaceCurve::distance(arc, Point<2>(1, -3)) << "\n";
    check("distance |R - |p - c||: 1 from (3, 0), 2 from the centre",
          close(InterfaceCurve::distance(arc, Point<2>(3, 0)), 1) &&
            close(InterfaceCurve::distance(arc, Point<2>(0, 0)), 2));
    check("outside the arc's angles: the nearer end, |(1, -3) - (2, 0)| = "
          "sqrt(10)",
          close(InterfaceCurve::distance(arc, Point<2>(1, -3)),
                std::sqrt(10.)));
    check("parameter of (1, 1) is R pi/4",
          close(ccw.parameter(Point<2>(1, 1)), R * pi / 4));
    // An arc followed by a segment along its end tangent (-1, 0): a smooth
    // junction, no corner; a segment going down from (0, 2) is a corner.
    const InterfaceCurve smooth({arc_piece(c, R, 0, pi / 2),
                                 segment_piece(Point<2>(0, 2),
                                               Point<2>(-1, 2))},
                                0.);
    Tensor<1, 2>         before, after;
    check("arc + tangent segment: no corner at s = pi, normal (0, -1)",
          !smooth.corner(pi, before, after) &&
            close(smooth.normal(pi), Tensor<1, 2>({0., -1.})) &&
            close(smooth.normal(pi + 0.5), Tensor<1, 2>({0., -1.})));
    const InterfaceCurve kinked({arc_piece(c, R, 0, pi / 2),
                                 segment_piece(Point<2>(0, 2), Point<2>(0, 3))},
                                0.);
    check("arc + segment along +y: a corner at s = pi, normals (0, -1), "
          "(-1, 0)",
          kinked.corner(pi, before, after) &&
            close(before, Tensor<1, 2>({0., -1.})) &&
            close(after, Tensor<1, 2>({-1., 0.})));
  }

  // ------------------------------------------------------------------
  void
  mortar_choice()
  {
    std::cout << "MultiplierSpace::choose\n";
    const double              tol   = 1e-12;
    const std::vector<double> half  = {0, 0.5, 1},
                              third = {0, 1. / 3, 2. / 3, 1};
    const auto mu                   = [&](const std::vector<double> &m,
                        const std::vector<double> &p,
                        const MultiplierMesh       rule) {
      return MultiplierSpace::choose(
        Topology(), {InterfaceTraces{{m, p}}}, {2, 1}, rule, tol);
    };
    const auto fine = mu(half, third, MultiplierMesh::finer_trace);
    std::cout << "  2:3 finer: " << str(fine[0].breakpoints) << "\n";
    check("2:3, finer trace: the 3-cell Omega+ trace, degree p1 = 2",
          fine[0].breakpoints == third && fine[0].degree == 2);
    check("gluing blocks: each side's trace, degree min(p1, p2) = 1",
          fine[1].breakpoints == half && fine[2].breakpoints == third &&
            fine[1].degree == 1 && fine[2].degree == 1);
    check("2:3, coarser trace: the 2-cell Omega- trace",
          mu(half, third, MultiplierMesh::coarser_trace)[0].breakpoints ==
            half);
    check("3:2, finer trace: the 3-cell Omega- trace",
          mu(third, half, MultiplierMesh::finer_trace)[0].breakpoints == third);
    check("matching traces: Omega- (tie), either rule",
          mu(half, half, MultiplierMesh::finer_trace)[0].breakpoints == half &&
            mu(half, half, MultiplierMesh::coarser_trace)[0].breakpoints ==
              half);
    // A tie between different traces: 2 segments each on the one macro
    // segment [0, 1] (only the ends shared).
    check("tie between 0 0.25 1 and 0 0.75 1: Omega-, either rule",
          mu({0, 0.25, 1}, {0, 0.75, 1}, MultiplierMesh::finer_trace)[0]
                .breakpoints == std::vector<double>({0, 0.25, 1}) &&
            mu({0, 0.25, 1}, {0, 0.75, 1}, MultiplierMesh::coarser_trace)[0]
                .breakpoints == std::vector<double>({0, 0.25, 1}));
    // Macro segments [0, 0.5] (Omega- finer) and [0.5, 1] (Omega+ finer).
    const std::vector<double> left  = {0, 0.25, 0.5, 1},
                              right = {0, 0.5, 0.75, 1};
    const auto mixed = mu(left, right, MultiplierMesh::finer_trace);
    std::cout << "  mixed finer: " << str(mixed[0].breakpoints) << "\n";
    check("per macro segment the finer side: 0 0.25 0.5 0.75 1",
          mixed[0].breakpoints == std::vector<double>({0, 0.25, 0.5, 0.75, 1}));
    check("per macro segment the coarser side: 0 0.5 1",
          mu(left, right, MultiplierMesh::coarser_trace)[0].breakpoints ==
            std::vector<double>({0, 0.5, 1}));
    check("points closer than tol are shared (0.5 + 1e-13)",
          mu({0, 0.25, 0.5, 1},
             {0, 0.5 + 1e-13, 0.75, 1},
             MultiplierMesh::finer_trace)[0]
              .breakpoints.size() == 5);
  }

  void
  multiplier_nodes()
  {
    std::cout << "MultiplierSpace::reinit: polygon with a crack corner\n";
    InterfaceCurve curve = corner_curve();
    const double   r2    = std::sqrt(2.);
    // Crack (0.5, 2): the corner s = 1 and s = 1 + sqrt(2)/2 inside, the
    // node 0.5 a crack tip (glued).
    curve.set_crack(CrackSet({{0.5, 2.}}, curve.tolerance()));
    ContactParameters         contact;
    MultiplierSpace           space;
    const std::vector<double> minus = {0, 0.5, 1, 1 + r2 / 2, 1 + r2},
                              plus  = {0, 1, 1 + r2};
    space.reinit(Topology(),
                 {curve},
                 contact,
                 {InterfaceTraces{{minus, plus}}},
                 {1, 1},
                 {true, false, false});
    std::cout << "  nodes per block: " << space.n_nodes(0) << " "
              << space.n_nodes(1) << " " << space.n_nodes(2) << "\n";
    check("mu_1 on the finer (Omega-) trace: 5 nodes; no layer 2: 0, 0",
          space.n_nodes(0) == 5 && space.n_nodes(1) == 0 &&
            space.n_nodes(2) == 0 && space.breakpoints(0) == minus);
    check("both traces nested in the mesh: nodal on both sides",
          space.nodal(0, 0) && space.nodal(0, 1));
    std::vector<double> weights,
      expected = {0.25, 0.5, 0.25 + r2 / 4, r2 / 2, r2 / 4};
    bool d_ok  = true;
    for (unsigned int a = 0; a < 5; ++a)
      {
        weights.push_back(space.node_weight(a, 0));
        d_ok = d_ok && close(weights[a], expected[a]) &&
               close(space.node_mass(a, 0), expected[a]);
      }
    std::cout << "  D = " << str(weights) << "\n";
    check("D = int phi_a = (h_l + h_r)/2, summing to the length", d_ok);
    std::cout << "  on crack:";
    for (unsigned int a = 0; a < 5; ++a)
      std::cout << " " << space.on_crack(a);
    std::cout << "  corner:";
    for (unsigned int a = 0; a < 5; ++a)
      std::cout << " " << space.corner(a);
    std::cout << "\n";
    check("crack nodes 2, 3 (the tip node 1 glued); corner node 2",
          !space.on_crack(1) && space.on_crack(2) && space.on_crack(3) &&
            !space.on_crack(4) && space.corner(2) && !space.corner(3));
    const auto &f = space.node_frame(2);
    std::cout << "  node_frame(2) = " << str(f[0]) << " " << str(f[1])
              << " node_normal(2) = " << str(space.node_normal(2)) << "\n";
    check("corner frame: the normals (0, 1) and (-1, 1)/sqrt(2)",
          close(f[0], Tensor<1, 2>({0., 1.})) &&
            close(f[1], Tensor<1, 2>({-1 / r2, 1 / r2})));
    check("corner node normal (-1, 2)/sqrt(5) (chords weighted by int phi)",
          close(space.node_normal(2),
                Tensor<1, 2>({-1 / std::sqrt(5.), 2 / std::sqrt(5.)})));
    const std::pair<double, double> in_0_p = {0., contact.multiplier_bound};
    const std::pair<double, double> fixed  = {0., 0.};
    check("corner: two contact components in [0, p]",
          space.contact_components(2).size() == 2 &&
            space.set().contact(0, Layout::entry(2, 0)) &&
            space.set().contact(0, Layout::entry(2, 1)) &&
            space.set().box(0, Layout::entry(2, 0)) == in_0_p &&
            space.set().box(0, Layout::entry(2, 1)) == in_0_p);
    const auto &g = space.node_frame(3);
    check("crack node 3: frame (tangent, normal) of piece 1, normal in "
          "[0, p], tangential fixed to 0",
          close(g[1], Tensor<1, 2>({-1 / r2, 1 / r2})) &&
            close(g[0], Tensor<1, 2>({1 / r2, 1 / r2})) &&
            space.contact_components(3).size() == 1 &&
            !space.set().free(0, Layout::entry(3, 0)) &&
            space.set().box(0, Layout::entry(3, 0)) == fixed &&
            space.set().box(0, Layout::entry(3, 1)) == in_0_p);
    check("glued nodes: both components in [-p, p]; n_free = 3 x 2 + 2 + 1",
          space.set().box(0, Layout::entry(1, 0)) ==
              std::make_pair(-contact.multiplier_bound,
                             contact.multiplier_bound) &&
            !space.set().contact(0, Layout::entry(1, 0)) &&
            space.contact_components(1).empty() && space.n_free() == 9);

    std::cout << "MultiplierSpace::reinit: P2/P1 on a straight Sigma\n";
    const InterfaceCurve line =
      InterfaceCurve::segment(Point<2>(0, 0), Point<2>(1, 0));
    MultiplierSpace p2;
    p2.reinit(Topology(),
              {line},
              contact,
              {InterfaceTraces{{{0, 0.5, 1}, {0, 1. / 3, 2. / 3, 1}}}},
              {2, 1},
              {true, true, true});
    std::cout << "  nodes per block: " << p2.n_nodes(0) << " " << p2.n_nodes(1)
              << " " << p2.n_nodes(2) << " degrees " << p2.degree(0) << " "
              << p2.degree(1) << " " << p2.degree(2) << "\n";
    check("3 segments x degree 2 + 1 = 7; gluing P1: 3 and 4 nodes",
          p2.n_nodes(0) == 7 && p2.n_nodes(1) == 3 && p2.n_nodes(2) == 4 &&
            p2.degree(0) == 2 && p2.degree(1) == 1);
    // FE_Q numbering: vertices of each segment, then its interior node.
    check("node 1 (interior of segment 0) at 1/6 with Simpson weight 4h/6 "
          "= 2/9; node 0 at 0 with h/6 = 1/18",
          close(p2.node_position(1), 1. / 6) &&
            close(p2.node_weight(1, 0), 2. / 9) &&
            close(p2.node_weight(0, 0), 1. / 18) &&
            close(p2.node_weight(2, 0), 1. / 9));
    check("the 2-cell Omega- trace is not in the mesh (0.5 no break "
          "point); the P1 3-cell Omega+ trace is",
          !p2.nodal(0, 0) && p2.nodal(0, 1));

    std::cout << "MultiplierSpace::reinit: clamped ends, non-nested traces\n";
    InterfaceCurve clamped = line;
    clamped.set_clamped_ends({{{{true, true}}, {{true, true}}}});
    MultiplierSpace ends;
    ends.reinit(Topology(),
                {clamped},
                contact,
                {InterfaceTraces{{{0, 0.5, 1}, {0, 1. / 3, 2. / 3, 1}}}},
                {1, 1},
                {true, false, false});
    std::cout << "  rows " << ends.row(0, 0) << " " << ends.row(1, 0) << " "
              << ends.row(2, 0) << " " << ends.row(3, 0) << " D "
              << ends.node_weight(1, 0) << " free " << ends.n_free() << "\n";
    check("Omega- trace not in the mesh: ends join their neighbours (rows "
          "1 1 2 2), D_1 = 1/3 + 1/6",
          !ends.nodal(0, 0) && ends.row(0, 0) == 1 && ends.row(3, 0) == 2 &&
            ends.row(1, 0) == 1 && close(ends.node_weight(1, 0), 0.5) &&
            close(ends.node_mass(1, 0), 1. / 3));
    check("ends on Gamma_D carry no multiplier: 2 nodes x 2 free",
          ends.n_free() == 4 && !ends.free(Layout::entry(0, 0)));
    MultiplierSpace matching;
    matching.reinit(Topology(),
                    {clamped},
                    contact,
                    {InterfaceTraces{{{0, 0.5, 1}, {0, 0.5, 1}}}},
                    {1, 1},
                    {true, false, false});
    check("matching traces: no modification (row 0 = 0, D_0 = 1/4)",
          matching.row(0, 0) == 0 && close(matching.node_weight(1, 0), 0.5) &&
            close(matching.node_weight(0, 0), 0.25));
  }

  // ------------------------------------------------------------------
  /// The hat function of node j of the P1 mesh @p bp at x.
  double
  hat(const std::vector<double> &bp, const unsigned int j, const double x)
  {
    if (j > 0 && x >= bp[j - 1] && x <= bp[j])
      return (x - bp[j - 1]) / (bp[j] - bp[j - 1]);
    if (j + 1 < bp.size() && x >= bp[j] && x <= bp[j + 1])
      return (bp[j + 1] - x) / (bp[j + 1] - bp[j]);
    return 0;
  }

  /// The dual basis function of node a of the P1 mesh @p bp at x (inside a
  /// segment): 2 phi_a - phi_other on each segment next to a.
  double
  dual(const std::vector<double> &bp, const unsigned int a, const double x)
  {
    for (unsigned int e = 0; e + 1 < bp.size(); ++e)
      if (x > bp[e] && x < bp[e + 1] && (a == e || a == e + 1))
        {
          const double l = (bp[e + 1] - x) / (bp[e + 1] - bp[e]);
          const double r = 1 - l;
          return a == e ? 2 * l - r : 2 * r - l;
        }
    return 0;
  }

  /// int f g over (0, 1), 3-point Gauss rule on each interval of @p bp
  /// (exact for the piecewise quadratics here).
  template <typename F>
  double
  integrate(const std::vector<double> &bp, const F &f)
  {
    const double x[3] = {-std::sqrt(0.6), 0, std::sqrt(0.6)};
    const double w[3] = {5. / 9, 8. / 9, 5. / 9};
    double       sum  = 0;
    for (unsigned int e = 0; e + 1 < bp.size(); ++e)
      for (unsigned int q = 0; q < 3; ++q)
        sum += w[q] * (bp[e + 1] - bp[e]) / 2 *
               f((bp[e] + bp[e + 1]) / 2 + x[q] * (bp[e + 1] - bp[e]) / 2);
    return sum;
  }

  /// The mesh of one subdomain: Omega- = (0, 1) x (-1, 0), Omega+ = (0, 1) x
  /// (0, 1), @p n cells along Sigma, one across, Sigma's faces glued.
  void
  make_mesh(const Subdomain sd, const unsigned int n, Triangulation<2> &tria)
  {
    const bool minus = sd == Subdomain::minus;
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {n, 1},
                                              Point<2>(0, minus ? -1 : 0),
                                              Point<2>(1, minus ? 0 : 1),
                                              true);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            std::abs(cell->face(f)->center()[1]) < 1e-12)
          cell->face(f)->set_boundary_id(BoundaryIds::sigma);
  }

  /// The x coordinate and the component of each dof of @p sub on Sigma
  /// (-1 elsewhere), and the dof values of the field (x, 2x).
  void
  sigma_dofs(const ElasticSubproblem &sub,
             std::vector<double>     &x,
             std::vector<int>        &component,
             Vector<double>          &linear)
  {
    std::map<types::global_dof_index, Point<2>> points;
    DoFTools::map_dofs_to_support_points(sub.mapping(),
                                         sub.dof_handler(),
                                         points);
    x.assign(sub.n_dofs(), 0.);
    component.assign(sub.n_dofs(), -1);
    linear.reinit(sub.n_dofs());
    std::vector<types::global_dof_index> local(sub.fe().n_dofs_per_cell());
    for (const auto &cell : sub.dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            const unsigned int c = sub.fe().system_to_component_index(i).first;
            const Point<2>    &p = points[local[i]];
            linear(local[i])     = (c + 1) * p[0];
            if (std::abs(p[1]) < 1e-12)
              {
                x[local[i]]         = p[0];
                component[local[i]] = c;
              }
          }
      }
  }

  void
  coupling_case(const MultiplierMesh     rule,
                const MultiplierCoupling kind_of_coupling)
  {
    const bool lumped = kind_of_coupling == MultiplierCoupling::lumped;
    std::cout << "TraceCoupling: 2 cells (Omega-) : 3 cells (Omega+), Q1, "
              << (lumped ? "lumped" : "consistent") << ", "
              << (rule == MultiplierMesh::finer_trace ? "finer" : "coarser")
              << " trace\n";
    std::array<Triangulation<2>, 2> tria;
    make_mesh(Subdomain::minus, 2, tria[0]);
    make_mesh(Subdomain::plus, 3, tria[1]);
    const LayerMaterial                               material;
    const Functions::ZeroFunction<2>                  zero(2);
    const std::vector<const Function<2> *>            traction(4, &zero);
    std::array<std::unique_ptr<ElasticSubproblem>, 2> sub;
    for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
      {
        const unsigned int d = static_cast<unsigned int>(sd);
        sub[d]               = std::make_unique<ElasticSubproblem>(
          Layer::first, sd, tria[d], 1, material);
        // Clamped on the side opposite Sigma.
        std::vector<bool> clamped(4, false);
        clamped[sd == Subdomain::minus ? BoundaryIds::bottom :
                                         BoundaryIds::top] = true;
        sub[d]->setup(clamped, zero, traction);
      }
    const InterfaceCurve curve =
      InterfaceCurve::segment(Point<2>(0, 0), Point<2>(1, 0));
    ContactParameters contact;
    contact.mesh     = rule;
    contact.coupling = kind_of_coupling;
    Interface interface(contact);
    interface.setup(Topology(),
                    {{sub[0].get(), sub[1].get(), nullptr, nullptr}},
                    {curve});
    const MultiplierSpace &space    = interface.space();
    const TraceCoupling   &coupling = interface.coupling();

    const std::vector<double> half  = {0, 0.5, 1},
                              third = {0, 1. / 3, 2. / 3, 1};
    const std::vector<double> &mesh =
      rule == MultiplierMesh::finer_trace ? third : half;
    std::cout << "  multiplier mesh: " << str(space.breakpoints(0)) << "\n";
    check("the multiplier mesh is the " +
            std::string(rule == MultiplierMesh::finer_trace ? "3-cell" :
                                                              "2-cell") +
            " trace",
          space.breakpoints(0).size() == mesh.size());
    const unsigned int n = space.n_nodes(0);

    // C_s column by column: differences() with a unit w on one side.
    const std::vector<double>         common = {0, 1. / 3, 0.5, 2. / 3, 1};
    const PerSubproblem<unsigned int> index  = {0, 1, 0, 0};
    double                            worst = 0, worst_adjoint = 0;
    std::vector<std::vector<double>>  sums(2, std::vector<double>(2 * n, 0.));
    std::map<std::tuple<int, unsigned int, unsigned int>, double> printed;
    for (const unsigned int s : {Layout::u_minus, Layout::u_plus})
      {
        const ElasticSubproblem   &sp    = *sub[index[s]];
        const std::vector<double> &trace = index[s] == 0 ? half : third;
        std::vector<double>        x;
        std::vector<int>           component;
        Vector<double>             linear;
        sigma_dofs(sp, x, component, linear);
        Solutions w(Topology().n_subproblems());
        w[Layout::u_minus].reinit(sub[0]->n_dofs());
        w[Layout::u_plus].reinit(sub[1]->n_dofs());
        BlockVector<double> column;
        const double        sign = s == Layout::u_minus ? 1. : -1.;
        for (unsigned int j = 0; j < sp.n_dofs(); ++j)
          {
            w[s]    = 0;
            w[s](j) = 1;
            space.initialize(column);
            coupling.differences(w, true, column);
            for (unsigned int a = 0; a < n; ++a)
              for (unsigned int c = 0; c < 2; ++c)
                {
                  const double value     = sign * column.block(0)(2 * a + c);
                  double       reference = 0;
                  if (component[j] == static_cast<int>(c))
                    {
                      // The vertex k of the trace at x_j.
                      const unsigned int k =
                        std::find_if(trace.begin(),
                                     trace.end(),
                                     [&](const double t) {
                                       return std::abs(t - x[j]) < 1e-12;
                                     }) -
                        trace.begin();
                      reference = integrate(common, [&](const double y) {
                        return (lumped ? dual(mesh, a, y) : hat(mesh, a, y)) *
                               hat(trace, k, y);
                      });
                      sums[index[s]][2 * a + c] += value;
                      if (c == 0)
                        printed[{index[s], a, k}] = value;
                    }
                  worst = std::max(worst, std::abs(value - reference));
                }
            // Adjoint: loads = -+ C^T mu with mu a unit vector.
            for (unsigned int i = 0; i < 2 * n; ++i)
              {
                BlockVector<double> mu;
                space.initialize(mu);
                mu.block(0)(i) = 1;
                Solutions loads;
                coupling.apply_transpose(mu, loads);
                worst_adjoint = std::max(worst_adjoint,
                                         std::abs(-sign * loads[s](j) -
                                                  sign * column.block(0)(i)));
              }
          }
        // The traces of (x, 2x) at the nodes and at the Gauss points.
        Vector<double> at_nodes, at_gauss;
        coupling.trace_at_nodes(s, linear, at_nodes);
        coupling.trace_at_gauss_points(s, linear, at_gauss);
        double trace_error = 0;
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int c = 0; c < 2; ++c)
            trace_error = std::max(trace_error,
                                   std::abs(at_nodes(2 * a + c) -
                                            (c + 1) * space.node_position(a)));
        const auto &gx = coupling.gauss_points();
        for (unsigned int q = 0; q < gx.size(); ++q)
          for (unsigned int c = 0; c < 2; ++c)
            trace_error =
              std::max(trace_error,
                       std::abs(at_gauss(2 * q + c) - (c + 1) * gx[q]));
        check(std::string("trace of ") + Topology().name(s) +
                " of (x, 2x) at the nodes and Gauss points is (x, 2x)",
              trace_error < 1e-14);
      }
    std::cout << "  entries of C (component 0, node x_a, trace vertex x):\n";
    for (const auto &[key, value] : printed)
      if (std::abs(value) > 1e-15)
        std::cout << "    C" << (std::get<0>(key) == 0 ? "-" : "+")
                  << "(x_a = " << std::setprecision(6)
                  << space.node_position(std::get<1>(key)) << ", x = "
                  << (std::get<0>(key) == 0 ? half : third)[std::get<2>(key)]
                  << ") = " << std::setprecision(10) << value << "\n";
    std::cout << std::setprecision(6);
    check("every entry of C- and C+ equals the independent integral "
          "(3-point Gauss on 0 1/3 1/2 2/3 1)",
          worst < 1e-14);
    check("C w and C^T mu adjoint (apply_transpose = transpose of "
          "differences)",
          worst_adjoint < 1e-15);
    bool sums_ok = true;
    for (unsigned int d = 0; d < 2; ++d)
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int c = 0; c < 2; ++c)
          sums_ok =
            sums_ok &&
            close(sums[d][2 * a + c],
                  integrate(mesh,
                            [&](const double y) { return hat(mesh, a, y); })) &&
            close(sums[d][2 * a + c], space.node_mass(a, 0));
    std::vector<double> row_sums;
    for (unsigned int a = 0; a < n; ++a)
      row_sums.push_back(sums[0][2 * a]);
    std::cout << "  row sums of C-: " << str(row_sums) << "\n";
    check("row sums of C- and C+ = int phi_a ds = D_a", sums_ok);
    // Four entries by hand.
    if (rule == MultiplierMesh::finer_trace && lumped)
      check("by hand: C-(1/3, 0) = 7/72, C-(1/3, 1/2) = 1/4, C-(1/3, 1) = "
            "-1/72, C+(1/3, 1/3) = D = 1/3",
            close(printed[{0, 1, 0}], 7. / 72) &&
              close(printed[{0, 1, 1}], 0.25) &&
              close(printed[{0, 1, 2}], -1. / 72) &&
              close(printed[{1, 1, 1}], 1. / 3));
    if (rule == MultiplierMesh::finer_trace && !lumped)
      check("by hand: C-(1/3, 1/2) = int phi_{1/3} phi_{1/2} = 23/108, "
            "C+(1/3, 1/3) = 2h/3 = 2/9, C+(1/3, 2/3) = h/6 = 1/18",
            close(printed[{0, 1, 1}], 23. / 108) &&
              close(printed[{1, 1, 1}], 2. / 9) &&
              close(printed[{1, 1, 2}], 1. / 18));
    if (rule == MultiplierMesh::coarser_trace && lumped)
      check("coarser: C- = D E (nodal): C-(1/2, 1/2) = 1/2, C-(1/2, 0) = 0",
            close(printed[{0, 1, 1}], 0.5) && close(printed[{0, 1, 0}], 0));
    double weight_sum = 0;
    for (const double w : coupling.gauss_weights())
      weight_sum += w;
    std::cout << "  Gauss points: " << coupling.gauss_points().size()
              << " weights sum " << weight_sum << "\n";
    check("QGauss(p + 2) = 3 points on each of the 4 intervals of 0 1/3 "
          "1/2 2/3 1, weights summing to |Sigma| = 1",
          coupling.gauss_points().size() == 12 && close(weight_sum, 1));
  }
} // namespace


int
main()
{
  std::cout << std::setprecision(6);
  straight_sigma();
  polygonal_sigma();
  ends_and_reverse();
  circular_arc();
  mortar_choice();
  multiplier_nodes();
  coupling_case(MultiplierMesh::finer_trace, MultiplierCoupling::lumped);
  coupling_case(MultiplierMesh::finer_trace, MultiplierCoupling::consistent);
  coupling_case(MultiplierMesh::coarser_trace, MultiplierCoupling::lumped);
}
