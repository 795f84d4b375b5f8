#include <bilayer/core/boundary_ids.h>
#include <bilayer/postprocess/arc_tangent.h>
#include <bilayer/postprocess/fracture.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    using Piece = InterfaceCurve::Piece;
    using fracture::arc_tangent;

    /// Whether the consecutive pieces @p a and @p b of Sigma (a ends where
    /// b begins) are parts of one straight line or one circle (theta can
    /// move a tip across their junction). Arcs are compared at the junction
    /// by the angle between their tangents and the relative difference of
    /// their signed curvatures: the centre of a circle fitted to the nodes
    /// of a shallow arc (radius R, chord c) is determined only to about
    /// tol R^2 / c^2, its tangent and curvature far better.
    bool
    same_shape(const Piece &a, const Piece &b)
    {
      if (a.kind != b.kind)
        return false;
      if (a.kind == Piece::Kind::segment)
        return std::abs(a.tau[0] * b.tau[1] - a.tau[1] * b.tau[0]) < 1e-12 &&
               a.tau * b.tau > 0;
      const Point<2>     p  = 0.5 * (a.b + b.a);
      const Tensor<1, 2> ta = arc_tangent(a, p), tb = arc_tangent(b, p);
      const double       ka = (a.sweep >= 0 ? 1. : -1.) / a.radius,
                   kb       = (b.sweep >= 0 ? 1. : -1.) / b.radius;
      return ta * tb > 0 && std::abs(ta[0] * tb[1] - ta[1] * tb[0]) < 1e-6 &&
             std::abs(ka - kb) <= 1e-6 * std::max(std::abs(ka), std::abs(kb));
    }

    /// The unit tangent of @p piece at its point @p p, in the direction of
    /// increasing s.
    Tensor<1, 2>
    piece_tangent(const Piece &piece, const Point<2> &p)
    {
      return piece.kind == Piece::Kind::segment ? piece.tau :
                                                  arc_tangent(piece, p);
    }

    /// Whether the consecutive pieces @p a and @p b of Sigma meet with one
    /// tangent (within an angle of 1e-6): Sigma is C1 there, only its
    /// curvature may jump (a segment and a tangent arc, arcs of different
    /// radii), and theta can move a tip across the junction with the field
    /// of the closest point (ThetaField). The chords of a curve given by its
    /// polygon (Piece::continues) turn by O(h): no such junction.
    bool
    smooth_junction(const Piece &a, const Piece &b)
    {
      if (same_shape(a, b))
        return true;
      if (b.continues)
        return false;
      const Point<2>     p  = 0.5 * (a.b + b.a);
      const Tensor<1, 2> ta = piece_tangent(a, p), tb = piece_tangent(b, p);
      return ta * tb > 0 && std::abs(ta[0] * tb[1] - ta[1] * tb[0]) < 1e-6;
    }

    /// The distance of @p p from the segment from @p a to @p b.
    double
    distance_to_segment(const Point<2> &p, const Point<2> &a, const Point<2> &b)
    {
      const Tensor<1, 2> ab = b - a;
      const double       t  = ab.norm_square() > 0 ?
                                std::clamp(((p - a) * ab) / ab.norm_square(), 0., 1.) :
                                0.;
      return (p - (a + t * ab)).norm();
    }

    /// Smallest distance of @p p from the boundary faces of @p tria that
    /// are not on Sigma.
    double
    distance_to_outer_boundary(const Point<2> &p, const Triangulation<2> &tria)
    {
      double d = std::numeric_limits<double>::max();
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && !on_sigma(face))
            d = std::min(
              d, distance_to_segment(p, face->vertex(0), face->vertex(1)));
      return d;
    }
  } // namespace


  namespace
  {
    /// The support radius of @p tip (its free distance set): half the free
    /// distance for @p support_radius = 0, else that radius, refused where
    /// it reaches an obstacle (@p interfaces: other interfaces are some).
    void
    set_support_radius(const double support_radius,
                       const bool   interfaces,
                       const bool   plies,
                       CrackTip    &tip)
    {
      if (support_radius == 0)
        {
          tip.support_radius = 0.5 * tip.free_distance;
          return;
        }
      std::ostringstream range;
      range << std::setprecision(6)
            << "Fracture/Support radius = " << support_radius
            << " reaches another tip, a corner of "
            << "Sigma" << (interfaces ? ", another interface" : "")
            << (plies ? ", a ply boundary across the crack" : "")
            << " or the outer boundary from the crack tip at (x, "
            << "y) = (" << tip.point[0] << ", " << tip.point[1]
            << "); allowed: (0, " << tip.free_distance << "), or 0 (automatic)";
      AssertThrow(support_radius < tip.free_distance, ExcMessage(range.str()));
      tip.support_radius = support_radius;
    }
  } // namespace


  namespace
  {
    /**
     * The distance from @p tip to the nearest of the material boundaries
     * @p faces that its theta would move: all of them (@p all: a support
     * that follows a curve; a tip on an arc), or those across the tip's
     * direction (a straight tip's theta is parallel to it and slides along
     * a ply boundary parallel to the crack).
     */
    double
    distance_to_ply_boundary(const CrackTip             &tip,
                             const std::vector<Segment> &faces,
                             const bool                  all)
    {
      double d = std::numeric_limits<double>::infinity();
      for (const Segment &m : faces)
        {
          const Tensor<1, 2> t = m[1] - m[0];
          if (all || tip.arc ||
              std::abs(t[0] * tip.direction[1] - t[1] * tip.direction[0]) >
                1e-10 * t.norm())
            d = std::min(d, distance_to_segment(tip.point, m[0], m[1]));
        }
      return d;
    }
  } // namespace


  std::vector<CrackTip>
  crack_tips(const InterfaceCurve                          &curve,
             const std::array<const Triangulation<2> *, 2> &meshes,
             const double                                   support_radius,
             const unsigned int                             interface,
             const std::vector<InterfaceCurve>             &other_interfaces,
             const std::vector<Segment>                    &material_boundaries)
  {
    const double          tol    = curve.tolerance();
    const auto           &pieces = curve.pieces();
    std::vector<CrackTip> tips;
    for (const auto &crack : curve.crack().pieces())
      for (const double sign : {-1., 1.})
        {
          const double s = sign < 0 ? crack.start : crack.end;
          // The mouth of an edge crack (an end of Sigma, on the outer
          // boundary, on the crack): no tip, no G.
          if (curve.crack().mouth(s))
            continue;
          CrackTip tip;
          tip.interface = interface;
          tip.s         = s;
          tip.sign      = sign;
          tip.point     = curve.point(s);
          tip.direction = sign * tangent_of(curve.normal(s));
          tips.push_back(tip);
        }
    std::sort(tips.begin(), tips.end(), [](const auto &a, const auto &b) {
      return a.s < b.s;
    });

    for (CrackTip &tip : tips)
      {
        // The chain of pieces of one shape that holds the tip.
        unsigned int k = 0;
        while (k + 1 < pieces.size() &&
               tip.s > pieces[k].s0 + pieces[k].length - tol)
          ++k;
        unsigned int first = k, last = k;
        while (first > 0 && same_shape(pieces[first - 1], pieces[first]))
          --first;
        while (last + 1 < pieces.size() &&
               same_shape(pieces[last], pieces[last + 1]))
          ++last;
        if (pieces[k].kind == Piece::Kind::arc)
          {
            tip.arc    = true;
            tip.centre = pieces[k].centre;
            tip.radius = pieces[k].radius;
          }
        const double across_plies =
                       distance_to_ply_boundary(tip,
                                                material_boundaries,
                                                false),
                     any_ply =
                       distance_to_ply_boundary(tip, material_boundaries, true);
        // Obstacles: the ends of the chain, the other pieces, the other
        // tips, the outer boundary, the material boundaries.
        const auto obstacles = [&](const unsigned int from,
                                   const unsigned int to) {
          double d = std::min((tip.point - pieces[from].a).norm(),
                              (tip.point - pieces[to].b).norm());
          for (unsigned int j = 0; j < pieces.size(); ++j)
            if (j < from || j > to)
              d = std::min(d, InterfaceCurve::distance(pieces[j], tip.point));
          for (const CrackTip &other : tips)
            if (&other != &tip)
              d = std::min(d, (other.point - tip.point).norm());
          for (const auto *tria : meshes)
            if (tria != nullptr)
              d = std::min(d, distance_to_outer_boundary(tip.point, *tria));
          for (const InterfaceCurve &other : other_interfaces)
            d = std::min(d, other.distance(tip.point));
          d = std::min(d, from == first && to == last ? across_plies : any_ply);
          return d;
        };
        double d = obstacles(first, last);
        // The chain across smooth (C1) junctions of pieces of different
        // shape: used only where it lets theta reach farther than the chain
        // of one shape (straight and single-circle Sigma keep the field of
        // one line or one circle). Its support must also stay within the
        // reach of the closest-point projection: below the radius of every
        // arc it meets.
        unsigned int wide_first = first, wide_last = last;
        while (wide_first > 0 &&
               smooth_junction(pieces[wide_first - 1], pieces[wide_first]))
          --wide_first;
        while (wide_last + 1 < pieces.size() &&
               smooth_junction(pieces[wide_last], pieces[wide_last + 1]))
          ++wide_last;
        if (wide_first < first || wide_last > last)
          {
            double wide = obstacles(wide_first, wide_last);
            for (unsigned int j = wide_first; j <= wide_last; ++j)
              if (pieces[j].kind == Piece::Kind::arc &&
                  InterfaceCurve::distance(pieces[j], tip.point) < wide)
                wide = std::min(wide, pieces[j].radius);
            const bool farther =
              support_radius == 0 ? wide > d : support_radius >= d;
            if (farther && wide > tol)
              {
                d = wide;
                // The points of Sigma closest to the support: within 2 R of
                // the tip, R < wide.
                for (unsigned int j = wide_first; j <= wide_last; ++j)
                  if (InterfaceCurve::distance(pieces[j], tip.point) < 2 * wide)
                    tip.chain.push_back(pieces[j]);
              }
          }
        // 0: the tip sits on a corner of Sigma, G is not defined.
        const double free_distance = d > tol ? d : 0.;
        if (free_distance == 0)
          continue;
        tip.free_distance = free_distance;
        set_support_radius(support_radius,
                           !other_interfaces.empty(),
                           !material_boundaries.empty(),
                           tip);
      }
    return tips;
  }


  namespace
  {
    /// Whether @p cell (centre @p center, diameter @p diameter) has @p tip
    /// as a vertex; if so, its size enters @p cells as one of mesh @p m.
    void
    add_tip_cell(const CrackTip                               &tip,
                 const Triangulation<2>::active_cell_iterator &cell,
                 const Point<2>                               &center,
                 const double                                  diameter,
                 const unsigned int                            m,
                 TipCells                                     &cells)
    {
      if ((center - tip.point).norm() > diameter)
        return;
      bool at = false;
      for (const unsigned int v : cell->vertex_indices())
        at = at || (cell->vertex(v) - tip.point).norm() <= 1e-8 * diameter;
      if (!at)
        return;
      const double size = cell_size(cell);
      if (size > cells.size)
        cells.size = size, cells.mesh = m;
    }
  } // namespace


  TipCells
  support_cells(const CrackTip                                &tip,
                const std::array<const Triangulation<2> *, 2> &meshes)
  {
    TipCells cells;
    for (unsigned int m = 0; m < 2; ++m)
      if (meshes[m] != nullptr)
        for (const auto &cell : meshes[m]->active_cell_iterators())
          add_tip_cell(tip, cell, cell->center(), cell->diameter(), m, cells);
    return cells;
  }


  TipCells
  support_cells(const CrackTip                           &tip,
                const std::array<const CellExtents *, 2> &meshes)
  {
    TipCells cells;
    for (unsigned int m = 0; m < 2; ++m)
      if (meshes[m] != nullptr)
        for (unsigned int i = 0; i < meshes[m]->size(); ++i)
          add_tip_cell(tip,
                       meshes[m]->cell(i),
                       meshes[m]->center(i),
                       meshes[m]->diameter(i),
                       m,
                       cells);
    return cells;
  }
} // namespace bilayer
