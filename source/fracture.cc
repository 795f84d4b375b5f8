#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <bilayer/boundary_ids.h>
#include <bilayer/fracture.h>
#include <bilayer/similarity_breaker.h>
#include <bilayer/tasks.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    using Piece = InterfaceCurve::Piece;

    /// The unit tangent of the arc @p piece at its point @p p, in the
    /// direction of increasing s.
    Tensor<1, 2>
    arc_tangent(const Piece &piece, const Point<2> &p)
    {
      const Tensor<1, 2> r    = (p - piece.centre) / (p - piece.centre).norm();
      const double       sign = piece.sweep >= 0 ? 1. : -1.;
      return sign * Tensor<1, 2>({-r[1], r[0]});
    }

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

    /**
     * A Gauss rule with @p n points per direction on each of the m x m
     * (quadrilateral) or m^2 (triangle) congruent pieces of the reference
     * cell: cells much larger than the support of theta see its fall from
     * 1 to 0 with enough points.
     */
    Quadrature<2>
    subdivided_quadrature(const ReferenceCell &cell,
                          const unsigned int   n,
                          const unsigned int   m)
    {
      if (cell == ReferenceCells::Quadrilateral)
        return QIterated<2>(QGauss<1>(n), m);
      const QGaussSimplex<2> base(std::min(n, 4u));
      std::vector<Point<2>>  points;
      std::vector<double>    weights;
      const auto             add = [&](const Point<2>     &origin,
                           const Tensor<1, 2> &e0,
                           const Tensor<1, 2> &e1) {
        for (unsigned int q = 0; q < base.size(); ++q)
          {
            points.push_back(origin + base.point(q)[0] * e0 +
                             base.point(q)[1] * e1);
            weights.push_back(base.weight(q) / (m * m));
          }
      };
      const double h = 1. / m;
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; i + j < m; ++j)
          {
            add(Point<2>(i * h, j * h),
                Tensor<1, 2>({h, 0}),
                Tensor<1, 2>({0, h}));
            if (i + j + 1 < m)
              add(Point<2>((i + 1) * h, (j + 1) * h),
                  Tensor<1, 2>({-h, 0}),
                  Tensor<1, 2>({0, -h}));
          }
      return Quadrature<2>(points, weights);
    }
  } // namespace


  std::vector<CrackTip>
  crack_tips(const InterfaceCurve                          &curve,
             const std::array<const Triangulation<2> *, 2> &meshes,
             const double                                   support_radius)
  {
    const double          tol    = curve.tolerance();
    const auto           &pieces = curve.pieces();
    std::vector<CrackTip> tips;
    for (const auto &crack : curve.crack().pieces())
      for (const double sign : {-1., 1.})
        {
          const double s = sign < 0 ? crack.start : crack.end;
          // An end of Sigma: the crack reaches the outer boundary there.
          if (std::abs(s - curve.s_begin()) <= tol ||
              std::abs(s - curve.s_end()) <= tol)
            continue;
          CrackTip tip;
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
        // Obstacles: the ends of the chain, the other pieces, the other
        // tips, the outer boundary.
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
        if (support_radius == 0)
          tip.support_radius = 0.5 * free_distance;
        else
          {
            std::ostringstream range;
            range << std::setprecision(6)
                  << "Fracture/Support radius = " << support_radius
                  << " reaches another tip, a corner of "
                  << "Sigma or the outer boundary from the crack tip at (x, "
                  << "y) = (" << tip.point[0] << ", " << tip.point[1]
                  << "); allowed: (0, " << free_distance
                  << "), or 0 (automatic)";
            AssertThrow(support_radius < free_distance,
                        ExcMessage(range.str()));
            tip.support_radius = support_radius;
          }
      }
    return tips;
  }


  TipCells
  support_cells(const CrackTip                                &tip,
                const std::array<const Triangulation<2> *, 2> &meshes)
  {
    TipCells cells;
    for (unsigned int m = 0; m < 2; ++m)
      if (meshes[m] != nullptr)
        for (const auto &cell : meshes[m]->active_cell_iterators())
          {
            const double diameter = cell->diameter();
            if ((cell->center() - tip.point).norm() > diameter)
              continue;
            bool at = false;
            for (const unsigned int v : cell->vertex_indices())
              at =
                at || (cell->vertex(v) - tip.point).norm() <= 1e-8 * diameter;
            if (!at)
              continue;
            const double size = cell_size(cell);
            if (size > cells.size)
              cells.size = size, cells.mesh = m;
          }
    return cells;
  }


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


  std::vector<EnergyReleaseRate>
  energy_release_rates(
    const PerSubproblem<const ElasticSubproblem *> &subproblems,
    const Interface                                &interface,
    const Solutions                                &w,
    const BlockVector<double>                      &mu,
    const std::vector<CrackTip>                    &tips)
  {
    const unsigned int             n = tips.size();
    std::vector<EnergyReleaseRate> result(n);
    std::vector<ThetaField>        fields;
    for (unsigned int t = 0; t < n; ++t)
      {
        result[t].tip = tips[t];
        fields.emplace_back(tips[t]);
      }

    // The domain integral of each subproblem at each tip, by its owner.
    PerSubproblem<Vector<double>> integrals;
    Tasks                         tasks;
    for (const unsigned int s : Layout::subproblems)
      if (subproblems[s] != nullptr && subproblems[s]->owned())
        tasks.add([&, s]() {
          const ElasticSubproblem &sub = *subproblems[s];
          integrals[s].reinit(n);
          // FEValues with the rule subdivided m x m times, by m.
          std::map<unsigned int, std::unique_ptr<FEValues<2>>> by_pieces;
          const SimilarityBreaker          fresh(sub.fe().reference_cell());
          const FEValuesExtractors::Vector displacement(0);
          const ElasticLaw                &law = sub.law();
          std::vector<Tensor<2, 2>>        grad_u;
          for (const auto &cell : sub.dof_handler().active_cell_iterators())
            {
              // No point of a cell is farther from its centre than its
              // diameter (the vertex mean lies inside the cell).
              const double diameter   = cell->diameter();
              double       smallest_R = 0;
              for (unsigned int t = 0; t < n; ++t)
                if (tips[t].defined() &&
                    fields[t].reaches(cell->center(), diameter))
                  smallest_R = smallest_R == 0 ?
                                 tips[t].support_radius :
                                 std::min(smallest_R, tips[t].support_radius);
              if (smallest_R == 0)
                continue;
              // Pieces no larger than 1/8 of R: at least four across the
              // fall of theta (R/2 < r < R).
              const unsigned int m =
                std::clamp<unsigned int>(std::ceil(8 * diameter / smallest_R),
                                         1,
                                         32);
              auto &fe_values_m = by_pieces[m];
              if (!fe_values_m)
                fe_values_m = std::make_unique<FEValues<2>>(
                  sub.mapping(),
                  sub.fe(),
                  subdivided_quadrature(sub.fe().reference_cell(),
                                        sub.fe().degree + 3,
                                        m),
                  update_gradients | update_quadrature_points |
                    update_JxW_values);
              FEValues<2> &fe_values = *fe_values_m;
              fresh.apply(fe_values);
              fe_values.reinit(cell);
              grad_u.resize(fe_values.n_quadrature_points);
              fe_values[displacement].get_function_gradients(w[s], grad_u);
              for (unsigned int t = 0; t < n; ++t)
                if (tips[t].defined() &&
                    fields[t].reaches(cell->center(), diameter))
                  {
                    double sum = 0;
                    for (const unsigned int q :
                         fe_values.quadrature_point_indices())
                      {
                        const Tensor<2, 2> grad_theta =
                          fields[t].gradient(fe_values.quadrature_point(q));
                        const SymmetricTensor<2, 2> eps = symmetrize(grad_u[q]);
                        const SymmetricTensor<2, 2> stress = law.stress(eps);
                        const double energy_density = 0.5 * (stress * eps);
                        sum += (scalar_product(Tensor<2, 2>(stress),
                                               grad_u[q] * grad_theta) -
                                energy_density * trace(grad_theta)) *
                               fe_values.JxW(q);
                      }
                    integrals[s](t) += sum;
                  }
            }
        });
    tasks.join_all();
    for (const unsigned int s : Layout::subproblems)
      if (subproblems[s] != nullptr)
        {
          if (!subproblems[s]->owned())
            integrals[s].reinit(n);
          subproblems[s]->processes().share(s, integrals[s]);
          for (unsigned int t = 0; t < n; ++t)
            result[t].G += integrals[s](t);
        }

    // The contact term on a curved crack: -sign int psi kappa mu_c [u].tau
    // over the segments of the mesh of mu_1 (Gauss quadrature, the
    // multiplier and the jump interpolated from its nodes).
    bool curved_contact = false;
    for (const CrackTip &tip : tips)
      curved_contact = curved_contact || (tip.defined() && tip.curved());
    if (curved_contact && interface.contact_parameters().non_penetration)
      {
        const MultiplierSpace &space = interface.space();
        const InterfaceCurve  &curve = interface.curve();
        Vector<double>         tm, tp;
        interface.coupling().trace_at_nodes(Layout::u_minus,
                                            w[Layout::u_minus],
                                            tm);
        interface.coupling().trace_at_nodes(Layout::u_plus,
                                            w[Layout::u_plus],
                                            tp);
        const auto         &bp = space.breakpoints(Layout::across_sigma);
        const QGauss<1>     gauss(space.degree() + 2);
        std::vector<double> shape;
        for (unsigned int t = 0; t < n; ++t)
          if (tips[t].defined() && tips[t].curved())
            for (unsigned int e = 0; e + 1 < bp.size(); ++e)
              {
                const double mid = 0.5 * (bp[e] + bp[e + 1]);
                if (!curve.crack().contains(mid) ||
                    !fields[t].reaches(curve.point(mid), bp[e + 1] - bp[e]))
                  continue;
                for (unsigned int q = 0; q < gauss.size(); ++q)
                  {
                    const double s_q =
                      bp[e] + gauss.point(q)[0] * (bp[e + 1] - bp[e]);
                    space.shape_values(Layout::across_sigma, s_q, shape);
                    double mu_c = 0, jump = 0;
                    for (unsigned int i = 0; i < shape.size(); ++i)
                      {
                        const unsigned int a = space.node(e, i);
                        mu_c += shape[i] * space.contact_multiplier(mu, a);
                        jump +=
                          shape[i] * (tp(Layout::entry(a, Layout::tangential)) -
                                      tm(Layout::entry(a, Layout::tangential)));
                      }
                    const Point<2> x = curve.point(s_q);
                    // kappa: d tau / ds = kappa nu, towards the centre.
                    const double kappa =
                      fields[t].curvature(x, curve.normal(s_q));
                    result[t].contact -=
                      tips[t].sign *
                      fields[t].cutoff((x - tips[t].point).norm()) * kappa *
                      mu_c * jump * gauss.weight(q) * (bp[e + 1] - bp[e]);
                  }
              }
      }

    for (EnergyReleaseRate &r : result)
      if (r.tip.defined())
        r.G += r.contact;
      else
        r.G = std::numeric_limits<double>::quiet_NaN();
    return result;
  }


  double
  g_error_from_cycles(const std::vector<double> &G)
  {
    // The trailing finite values, at most four (a tip not resolved on a
    // cycle breaks the sequence).
    std::size_t n = 0;
    while (n < G.size() && n < 4 && std::isfinite(G[G.size() - 1 - n]))
      ++n;
    if (n < 2)
      return std::numeric_limits<double>::quiet_NaN();
    // The changes e[0] = G_k - G_{k-1}, e[1] = G_{k-1} - G_{k-2}, ...
    const std::size_t   k = G.size() - 1;
    std::vector<double> e;
    for (std::size_t i = 0; i + 1 < n; ++i)
      e.push_back(G[k - i] - G[k - i - 1]);
    // Two values: no contraction observed yet; twice the change (a bound
    // for geometric convergence with a ratio up to 2/3).
    if (e.size() == 1)
      return 2 * std::abs(e[0]);
    // The largest of the last changes: G of adaptive cycles moves
    // irregularly, and a small last change says little of the error.
    double dG = 0;
    for (const double change : e)
      dG = std::max(dG, std::abs(change));
    // Monotone and contracting: the remainder of the geometric sequence
    // with the observed ratio r, G - G_k = e1 (r + r^2 + ...) = e1 r /
    // (1 - r) (Aitken; larger than the changes for r > 1/2).
    const double d1 = std::abs(e[0]), d2 = std::abs(e[1]);
    if (e[0] * e[1] > 0 && d1 < d2)
      {
        const double r = d1 / d2;
        dG             = std::max(dG, d1 * r / (1 - r));
      }
    return dG;
  }


  void
  set_g_error(EnergyReleaseRate &g, const double from_cycles)
  {
    g.error = std::numeric_limits<double>::quiet_NaN();
    if (!g.tip.defined() || !g.unresolved.empty() || !std::isfinite(g.G))
      {
        g.error_estimate = "none: G not reported";
        return;
      }
    const double from_support = std::abs(g.G - g.G_half_support);
    const bool   cycles       = std::isfinite(from_cycles),
               support        = std::isfinite(from_support);
    if (cycles && support)
      {
        g.error          = std::max(from_cycles, from_support);
        g.error_estimate = "cycles and support radius";
      }
    else if (cycles)
      {
        g.error          = from_cycles;
        g.error_estimate = "cycles";
      }
    else if (support)
      {
        g.error          = from_support;
        g.error_estimate = "support radius";
      }
    else
      g.error_estimate =
        "none: first cycle of G and R/2 holds too few cells at the tip";
  }


  std::string
  tip_position(const CrackTip &tip, const bool along_x)
  {
    std::ostringstream x;
    x << std::setprecision(6);
    if (along_x)
      x << "x = " << tip.point[0];
    else
      x << "s = " << tip.s << ", (x, y) = (" << tip.point[0] << ", "
        << tip.point[1] << ")";
    return x.str();
  }


  std::vector<std::string>
  tip_notes(const std::vector<EnergyReleaseRate> &release, const bool along_x)
  {
    std::vector<std::string> notes;
    for (unsigned int t = 0; t < release.size(); ++t)
      {
        const CrackTip    &tip = release[t].tip;
        std::ostringstream line;
        line << std::setprecision(6) << "tip " << t + 1 << ": "
             << tip_position(tip, along_x);
        if (along_x && std::abs(tip.direction[1]) < 1e-12)
          line << ", grows towards " << (tip.direction[0] > 0 ? "+x" : "-x");
        else
          line << ", grows along (" << tip.direction[0] + 0. << ", "
               << tip.direction[1] + 0. << ")";
        notes.push_back(line.str());
      }
    return notes;
  }


  std::vector<std::string>
  release_notes(const std::vector<EnergyReleaseRate> &release,
                const bool                            along_x)
  {
    std::vector<std::string> notes;
    for (unsigned int t = 0; t < release.size(); ++t)
      {
        const EnergyReleaseRate &g = release[t];
        std::ostringstream       line;
        line << std::setprecision(10) << "crack tip " << t + 1 << " at "
             << tip_position(g.tip, along_x) << ", growing along ("
             << g.tip.direction[0] + 0. << ", " << g.tip.direction[1] + 0.
             << "): energy release rate G = " << g.G
             << " [stress x length] (contact term " << g.contact
             << "), error bar dG = ";
        if (std::isfinite(g.error))
          line << std::setprecision(2) << g.error << std::setprecision(10)
               << " (estimate from the " << g.error_estimate << ")";
        else
          line << "? (estimate " << g.error_estimate << ")";
        line << ", support radius " << g.tip.support_radius;
        if (!g.unresolved.empty())
          line << " (G not resolved: " << g.unresolved << ")";
        notes.push_back(line.str());
      }
    return notes;
  }
} // namespace bilayer
