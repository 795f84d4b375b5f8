// Gmsh scenes: the groups of a Gmsh mesh checked, Sigma and its crack
// pieces, arcs and clamped ends read from it (the subdomain meshes are built
// in gmsh_subdomain.cc).

#include <bilayer/geometry/geometry.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {

    /// The edges of the cells of one physical surface with the number of
    /// cells that use them.
    std::map<GmshEdge, unsigned int>
    cell_edges(const GmshMesh &mesh, const int surface)
    {
      std::map<GmshEdge, unsigned int> edges;
      for (const auto &e : mesh.elements)
        if ((e.type == 2 || e.type == 3) && e.physical == surface)
          for (unsigned int k = 0; k < e.nodes.size(); ++k)
            ++edges[gmsh_edge(e.nodes[k], e.nodes[(k + 1) % e.nodes.size()])];
      return edges;
    }
  } // namespace

  namespace
  {
    /// The physical groups of a Gmsh scene that bilayer reads.
    struct GmshGroups
    {
      /// Omega- and Omega+.
      std::array<int, 2> surface;
      /// The glued part of Sigma and the crack (-1 where absent).
      int sigma, crack;
    };


    /// The groups by name; every named curve a boundary part, Sigma or the
    /// crack.
    GmshGroups
    find_groups(const GmshMesh                 &g,
                const std::vector<std::string> &part_names,
                const std::string              &where)
    {
      // The groups by name.
      std::array<int, 2> surface;
      for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
        {
          const std::string name = s == Subdomain::minus ? "Omega-" : "Omega+";
          surface[static_cast<unsigned int>(s)] = g.physical_tag(2, name);
          AssertThrow(surface[static_cast<unsigned int>(s)] >= 0,
                      ExcMessage(where + ": no physical surface named '" +
                                 name + "' (the subdomain " +
                                 (s == Subdomain::minus ? "below" : "above") +
                                 " Sigma)"));
        }
      const int sigma = g.physical_tag(1, "Sigma"),
                crack = g.physical_tag(1, "crack");
      AssertThrow(sigma >= 0 || crack >= 0,
                  ExcMessage(where +
                             ": no physical curve named 'Sigma' (the "
                             "glued part of the interface) or 'crack'"));
      for (const auto &[tag, name] : g.curve_names)
        AssertThrow(name == "Sigma" || name == "crack" ||
                      std::find(part_names.begin(), part_names.end(), name) !=
                        part_names.end(),
                    ExcMessage(where + ": the physical curve '" + name +
                               "' is not among the boundary parts read from "
                               "the file"));

      return {surface, sigma, crack};
    }


    void
    check_elements(const GmshMesh    &g,
                   const GmshGroups  &groups,
                   const std::string &where)
    {
      const auto &surface = groups.surface;
      // Every cell in exactly one of Omega- and Omega+, every line element
      // of a physical curve in exactly one named group.
      const auto mid_point = [&](const GmshMesh::Element &e) {
        Point<2> centre;
        for (const unsigned int n : e.nodes)
          centre += g.nodes[n] / double(e.nodes.size());
        return point_text(centre);
      };
      const auto group = [&](const GmshMesh::Element &e) {
        const auto &names = e.type == 1 ? g.curve_names : g.surface_names;
        return names.count(e.physical) > 0 ?
                 "'" + names.at(e.physical) + "'" :
                 "number " + std::to_string(e.physical) + " (without a name)";
      };
      std::map<std::vector<unsigned int>, const GmshMesh::Element *> seen;
      for (const auto &e : g.elements)
        {
          const bool cell = e.type == 2 || e.type == 3;
          if (!cell && e.physical == 0)
            continue;
          const std::string entity =
            std::string(cell ? "Gmsh surface " : "Gmsh curve ") +
            std::to_string(e.entity);
          if (cell)
            {
              AssertThrow(
                e.physical != 0,
                ExcMessage(
                  where + ": the cells of " + entity + " (e.g. at " +
                  mid_point(e) +
                  ") are in no physical surface: add the surface to "
                  "Physical Surface(\"Omega-\") or (\"Omega+\"), or remove it"));
              AssertThrow(e.physical == surface[0] || e.physical == surface[1],
                          ExcMessage(where + ": the cells of " + entity +
                                     " (e.g. at " + mid_point(e) +
                                     ") are in the physical surface " +
                                     group(e) +
                                     "; bilayer reads only 'Omega-' and "
                                     "'Omega+': put the surface into one of "
                                     "them (a ply inside a region: name its "
                                     "group in Materials/Layer k/Ply "
                                     "groups)"));
            }
          else
            AssertThrow(g.curve_names.count(e.physical) > 0,
                        ExcMessage(where + ": the line elements of " + entity +
                                   " (e.g. at " + mid_point(e) +
                                   ") are in the physical curve " + group(e) +
                                   "; give the group a name (Physical "
                                   "Curve(\"NAME\")) or remove it"));
          std::vector<unsigned int> key = e.nodes;
          std::sort(key.begin(), key.end());
          key.push_back(cell ? 2 : 1);
          const auto [it, added] = seen.emplace(key, &e);
          AssertThrow(added,
                      ExcMessage(
                        where + ": the " + (cell ? "cell" : "edge") + " at " +
                        mid_point(e) + " (" + entity + ") is in two physical " +
                        (cell ? "surfaces" : "curves") + ", " +
                        group(*it->second) + " and " + group(e) +
                        (cell ? std::string() :
                                std::string("; a curve must be in one of "
                                            "'Sigma', 'crack' or one "
                                            "boundary part")) +
                        ": remove it from all but one"));
        }
    }


    /// The edges of Sigma and the crack, checked to be the edges shared by
    /// the cells of the two surfaces (@p minus, @p plus).
    std::map<GmshEdge, const GmshMesh::Element *>
    shared_edges(const GmshMesh                         &g,
                 const GmshGroups                       &groups,
                 const std::map<GmshEdge, unsigned int> &minus,
                 const std::map<GmshEdge, unsigned int> &plus,
                 const std::string                      &where)
    {
      const int sigma = groups.sigma, crack = groups.crack;
      // Sigma and the crack are the edges the two surfaces share, and
      // nothing else is shared; every other edge of a surface belongs to one
      // cell or two.
      for (const auto &[name, edges] :
           {std::make_pair("Omega-", &minus), std::make_pair("Omega+", &plus)})
        {
          AssertThrow(!edges->empty(),
                      ExcMessage(where + ": the physical surface '" + name +
                                 "' has no triangles or quadrilaterals"));
          for (const auto &[e, n] : *edges)
            AssertThrow(n <= 2,
                        ExcMessage(where + ": more than two cells of '" + name +
                                   "' share the edge at " +
                                   point_text(0.5 * (g.nodes[e.first] +
                                                     g.nodes[e.second])) +
                                   " (overlapping cells)"));
        }
      std::map<GmshEdge, const GmshMesh::Element *> on_sigma;
      for (const auto &e : g.elements)
        if (e.type == 1 && (e.physical == sigma || e.physical == crack))
          on_sigma[gmsh_edge(e.nodes[0], e.nodes[1])] = &e;
      for (const auto &[e, element] : on_sigma)
        {
          const auto m = minus.find(e), p = plus.find(e);
          AssertThrow(
            m != minus.end() && p != plus.end() && m->second == 1 &&
              p->second == 1,
            ExcMessage(
              where + ": the '" +
              (element->physical == sigma ? "Sigma" : "crack") + "' edge at " +
              point_text(0.5 * (g.nodes[e.first] + g.nodes[e.second])) +
              " is not a boundary edge of both Omega- and "
              "Omega+: Sigma must separate the two "
              "subdomains (curves shared by both surfaces)"));
        }
      for (const auto &[e, n] : minus)
        AssertThrow(plus.count(e) == 0 || on_sigma.count(e) == 1,
                    ExcMessage(
                      where + ": Omega- and Omega+ share the edge at " +
                      point_text(0.5 * (g.nodes[e.first] + g.nodes[e.second])) +
                      ", which is in neither 'Sigma' nor 'crack'"));
      return on_sigma;
    }


    void
    check_boundary_parts(const GmshMesh                         &g,
                         const GmshGroups                       &groups,
                         const std::map<GmshEdge, unsigned int> &minus,
                         const std::map<GmshEdge, unsigned int> &plus,
                         const std::string                      &where)
    {
      const int sigma = groups.sigma, crack = groups.crack;
      // The named boundary parts lie on the outer boundary: each edge is an
      // edge of one cell.
      for (const auto &e : g.elements)
        if (e.type == 1 && e.physical != sigma && e.physical != crack &&
            g.curve_names.count(e.physical) > 0)
          {
            const GmshEdge     k = gmsh_edge(e.nodes[0], e.nodes[1]);
            const auto         m = minus.find(k), p = plus.find(k);
            const unsigned int cells = (m == minus.end() ? 0 : m->second) +
                                       (p == plus.end() ? 0 : p->second);
            AssertThrow(cells == 1,
                        ExcMessage(
                          where + ": the '" + g.curve_names.at(e.physical) +
                          "' edge at " +
                          point_text(0.5 *
                                     (g.nodes[k.first] + g.nodes[k.second])) +
                          " (Gmsh curve " + std::to_string(e.entity) +
                          ") is an edge of " + std::to_string(cells) +
                          " cells, not of the outer boundary: a boundary "
                          "part must lie on the boundary of Omega- or "
                          "Omega+"));
          }
    }


    void
    check_conforming(
      const GmshMesh                                      &g,
      const std::map<GmshEdge, unsigned int>              &minus,
      const std::map<GmshEdge, unsigned int>              &plus,
      const std::map<GmshEdge, const GmshMesh::Element *> &on_sigma,
      const std::string                                   &where)
    {
      // Non-conforming meshes: a boundary edge along another boundary edge
      // (a hanging node, or cells that do not share their nodes).
      std::vector<GmshEdge> boundary;
      for (const auto *edges : {&minus, &plus})
        for (const auto &[e, n] : *edges)
          if (n == 1 && on_sigma.count(e) == 0)
            boundary.push_back(e);
      for (const auto &[e, n] : minus)
        if (n == 1 && on_sigma.count(e) == 1)
          boundary.push_back(e);
      double size = 0;
      for (const auto &e : boundary)
        size = std::max(size, g.nodes[e.first].distance(g.nodes[e.second]));
      for (const auto &e : boundary)
        {
          const Point<2> mid = 0.5 * (g.nodes[e.first] + g.nodes[e.second]);
          for (const auto &f : boundary)
            if (f != e)
              {
                const Point<2>     a = g.nodes[f.first], b = g.nodes[f.second];
                const Tensor<1, 2> t = b - a;
                const double       l = (mid - a) * t / t.norm_square();
                const double       d = (a + l * t).distance(mid);
                AssertThrow(!(l > 1e-8 && l < 1 - 1e-8 && d < 1e-8 * size),
                            ExcMessage(where + ": the boundary edge at " +
                                       point_text(mid) +
                                       " lies along another edge: the mesh is "
                                       "not conforming (a hanging node, or "
                                       "cells that do not share their nodes)"));
              }
        }
    }


    /// Sigma and the crack as one chain of edges from one end to the other,
    /// with its nodes in order.
    struct SigmaChain
    {
      std::vector<const GmshMesh::Element *> edges;
      std::vector<unsigned int>              nodes;
    };


    SigmaChain
    sigma_chain(const GmshMesh                                      &g,
                const std::map<GmshEdge, const GmshMesh::Element *> &on_sigma,
                const std::string                                   &where)
    {
      // Sigma as a chain: walk from one end through the Sigma and crack
      // edges.
      std::map<unsigned int, std::vector<const GmshMesh::Element *>> at_node;
      for (const auto &[e, element] : on_sigma)
        for (const unsigned int n : element->nodes)
          at_node[n].push_back(element);
      std::vector<unsigned int> ends;
      for (const auto &[n, elements] : at_node)
        {
          AssertThrow(elements.size() <= 2,
                      ExcMessage(where + ": Sigma and the crack branch at " +
                                 point_text(g.nodes[n]) +
                                 "; they must form one open curve"));
          if (elements.size() == 1)
            ends.push_back(n);
        }
      AssertThrow(ends.size() == 2,
                  ExcMessage(where +
                             ": Sigma and the crack must form one open "
                             "curve from the outer boundary to the outer "
                             "boundary (found " +
                             std::to_string(ends.size()) + " ends)"));
      std::vector<const GmshMesh::Element *> chain;
      std::vector<unsigned int>              nodes = {ends[0]};
      for (const GmshMesh::Element *previous = nullptr;;)
        {
          const GmshMesh::Element *next = nullptr;
          for (const auto *e : at_node[nodes.back()])
            if (e != previous)
              next = e;
          if (next == nullptr)
            break;
          chain.push_back(next);
          nodes.push_back(next->nodes[0] == nodes.back() ? next->nodes[1] :
                                                           next->nodes[0]);
          previous = next;
        }
      AssertThrow(chain.size() == on_sigma.size(),
                  ExcMessage(where + ": Sigma and the crack must form one "
                                     "connected curve"));

      return {chain, nodes};
    }


    std::vector<InterfaceCurve::Piece>
    sigma_pieces(const GmshMesh                &g,
                 const SigmaChain              &sigma,
                 const std::map<int, Point<2>> &arc_centres,
                 const std::map<int, double>   &arc_radii)
    {
      const auto &chain = sigma.edges;
      const auto &nodes = sigma.nodes;
      // Pieces: a circular curve one arc, a straight curve one segment, any
      // other curve one segment per edge (the polygon of its nodes).
      std::vector<InterfaceCurve::Piece> pieces;
      for (unsigned int i = 0; i < chain.size();)
        {
          unsigned int j = i;
          while (j < chain.size() && chain[j]->entity == chain[i]->entity)
            ++j;
          const int             entity = chain[i]->entity;
          std::vector<Point<2>> points;
          for (unsigned int k = i; k <= j; ++k)
            points.push_back(g.nodes[nodes[k]]);
          bool straight = true;
          for (const auto &q : points)
            {
              const Tensor<1, 2> t = points.back() - points.front();
              const Tensor<1, 2> d = q - points.front();
              straight = straight && std::abs(d[0] * t[1] - d[1] * t[0]) <=
                                       1e-10 * t.norm_square();
            }
          InterfaceCurve::Piece piece;
          if (straight)
            {
              piece.a = points.front();
              piece.b = points.back();
              pieces.push_back(piece);
            }
          else if (arc_centres.count(entity) > 0)
            {
              piece.kind   = InterfaceCurve::Piece::Kind::arc;
              piece.a      = points.front();
              piece.b      = points.back();
              piece.centre = arc_centres.at(entity);
              piece.radius = arc_radii.at(entity);
              for (unsigned int k = 0; k + 1 < points.size(); ++k)
                {
                  const Tensor<1, 2> u = points[k] - piece.centre,
                                     v = points[k + 1] - piece.centre;
                  piece.sweep += std::atan2(u[0] * v[1] - u[1] * v[0], u * v);
                }
              pieces.push_back(piece);
            }
          else
            for (unsigned int k = 0; k + 1 < points.size(); ++k)
              {
                piece.a         = points[k];
                piece.b         = points[k + 1];
                piece.continues = k > 0;
                pieces.push_back(piece);
              }
          i = j;
        }

      return pieces;
    }


    CrackSet
    crack_pieces(const GmshMesh       &g,
                 const SigmaChain     &sigma,
                 const int             crack,
                 const InterfaceCurve &curve,
                 const std::string    &where)
    {
      const auto &chain = sigma.edges;
      const auto &nodes = sigma.nodes;
      // The crack pieces: runs of crack edges, inside Sigma.
      std::vector<CrackSet::Piece> cracks;
      for (unsigned int i = 0; i < chain.size(); ++i)
        if (chain[i]->physical == crack &&
            (i == 0 || chain[i - 1]->physical != crack))
          {
            unsigned int j = i;
            while (j < chain.size() && chain[j]->physical == crack)
              ++j;
            // A piece may reach an end of Sigma (an edge crack: its mouth
            // on the outer boundary, checked by check_crack_mouths()), but
            // not both: some of Sigma stays glued.
            AssertThrow(i > 0 || j < chain.size(),
                        ExcMessage(where + ": the crack piece from " +
                                   point_text(g.nodes[nodes[i]]) + " to " +
                                   point_text(g.nodes[nodes[j]]) +
                                   " covers all of Sigma: some of Sigma must "
                                   "stay glued (the physical curve 'Sigma')"));
            cracks.push_back({curve.parameter(g.nodes[nodes[i]]),
                              curve.parameter(g.nodes[nodes[j]])});
          }
      return CrackSet(cracks, curve.tolerance());
    }


    std::array<std::array<bool, 2>, 2>
    clamped_ends(const GmshMesh                         &g,
                 const GmshGroups                       &groups,
                 const std::vector<std::string>         &part_names,
                 const std::vector<bool>                &clamped,
                 const std::map<GmshEdge, unsigned int> &minus,
                 const std::map<GmshEdge, unsigned int> &plus,
                 const SigmaChain                       &sigma_chain)
    {
      const int   sigma = groups.sigma, crack = groups.crack;
      const auto &nodes = sigma_chain.nodes;
      // The clamped ends: the end node of a subdomain is clamped if it lies
      // on an edge of a clamped part that is an edge of that subdomain's
      // cells (its Dirichlet data fix that node alone). The gluing across
      // Sigma drops its multiplier at an end only where both sides are
      // clamped (InterfaceCurve::on_gamma_d).
      std::array<std::array<bool, 2>, 2> clamped_end = {
        {{{false, false}}, {{false, false}}}};
      for (const auto &e : g.elements)
        if (e.type == 1 && e.physical != sigma && e.physical != crack &&
            g.curve_names.count(e.physical) > 0 && e.nodes.size() == 2)
          {
            const auto &names = part_names;
            const auto  part  = std::find(names.begin(),
                                        names.end(),
                                        g.curve_names.at(e.physical)) -
                              names.begin();
            if (clamped[part])
              for (unsigned int d = 0; d < 2; ++d)
                if ((d == 0 ? minus : plus)
                      .count(gmsh_edge(e.nodes[0], e.nodes[1])) > 0)
                  for (unsigned int k = 0; k < 2; ++k)
                    for (const unsigned int n : e.nodes)
                      clamped_end[d][k] =
                        clamped_end[d][k] ||
                        n == (k == 0 ? nodes.front() : nodes.back());
          }
      return clamped_end;
    }


    /// The boundary parts (indices into @p part_names) with an edge at the
    /// node @p node.
    std::vector<unsigned int>
    parts_at_node(const GmshMesh                 &g,
                  const GmshGroups               &groups,
                  const std::vector<std::string> &part_names,
                  const unsigned int              node)
    {
      std::vector<unsigned int> parts;
      for (const auto &e : g.elements)
        if (e.type == 1 && e.physical != groups.sigma &&
            e.physical != groups.crack && g.curve_names.count(e.physical) > 0 &&
            std::count(e.nodes.begin(), e.nodes.end(), node) > 0)
          {
            const unsigned int part = std::find(part_names.begin(),
                                                part_names.end(),
                                                g.curve_names.at(e.physical)) -
                                      part_names.begin();
            if (part < part_names.size() &&
                std::count(parts.begin(), parts.end(), part) == 0)
              parts.push_back(part);
          }
      return parts;
    }


    /// The ends of the chain @p sigma (0: its first node, 1: its last) that
    /// a piece of @p cracks reaches: the mouths of edge cracks (@p curve
    /// runs from the first node at s_begin, not yet reversed).
    std::array<bool, 2>
    crack_mouths(const CrackSet &cracks, const InterfaceCurve &curve)
    {
      return {{cracks.mouth(curve.s_begin()), cracks.mouth(curve.s_end())}};
    }


    /**
     * An edge crack's mouth (an end of Sigma that a crack piece reaches)
     * must not lie on Gamma_D of either side (gamma_c and Gamma_D are
     * disjoint): refused naming the end and the clamped parts there.
     */
    void
    check_crack_mouths(const GmshMesh                           &g,
                       const GmshGroups                         &groups,
                       const SigmaChain                         &sigma,
                       const std::array<bool, 2>                &mouths,
                       const std::array<std::array<bool, 2>, 2> &clamped_end,
                       const std::vector<std::string>           &part_names,
                       const std::vector<bool>                  &clamped,
                       const std::string                        &where)
    {
      for (const unsigned int k : {0u, 1u})
        if (mouths[k] && (clamped_end[0][k] || clamped_end[1][k]))
          {
            const unsigned int node =
              k == 0 ? sigma.nodes.front() : sigma.nodes.back();
            std::string names;
            for (const unsigned int part :
                 parts_at_node(g, groups, part_names, node))
              if (clamped[part])
                names += (names.empty() ? "'" : ", '") + part_names[part] + "'";
            AssertThrow(false,
                        ExcMessage(where + ": a crack piece reaches the end " +
                                   point_text(g.nodes[node]) +
                                   " of Sigma, which lies on the clamped "
                                   "part " +
                                   names +
                                   " (Geometry/Clamped sides): a crack must "
                                   "not reach Gamma_D; an edge crack needs a "
                                   "free or loaded boundary at its mouth"));
          }
    }


    /// Whether the normal of @p curve points into Omega- (then the curve
    /// is to be reversed).
    bool
    against_orientation(const GmshMesh       &g,
                        const GmshGroups     &groups,
                        const SigmaChain     &sigma,
                        const InterfaceCurve &curve)
    {
      const auto &chain   = sigma.edges;
      const auto &surface = groups.surface;
      // Orientation: the normal points out of Omega-.
      {
        const auto    &first = *chain.front();
        const Point<2> mid =
          0.5 * (g.nodes[first.nodes[0]] + g.nodes[first.nodes[1]]);
        for (const auto &e : g.elements)
          if ((e.type == 2 || e.type == 3) && e.physical == surface[0] &&
              std::count(e.nodes.begin(), e.nodes.end(), first.nodes[0]) > 0 &&
              std::count(e.nodes.begin(), e.nodes.end(), first.nodes[1]) > 0)
            {
              Point<2> centre;
              for (const unsigned int n : e.nodes)
                centre += g.nodes[n] / double(e.nodes.size());
              if ((centre - mid) * curve.normal(curve.parameter(mid)) > 0)
                return true;
              return false;
            }
      }
      return false;
    }
  } // namespace


  void
  Geometry::load_gmsh()
  {
    const std::string file  = geometry.gmsh_file;
    const std::string where = "Geometry/Gmsh file '" + file + "'";
    GmshOptions       options;
    options.allow_commands = geometry.allow_gmsh_commands;
    options.time_limit     = this->mesh.gmsh_time_limit;
    options.size_factor    = this->mesh.gmsh_size_factor;
    GmshMesh read          = read_gmsh(file, options);
    take_ply_groups(read, where);
    const auto      mesh_ptr = std::make_shared<GmshMesh>(std::move(read));
    const GmshMesh &g        = *mesh_ptr;

    // The groups, every cell and line element in exactly one, Sigma the
    // edges the surfaces share, the boundary parts on the outer boundary,
    // a conforming mesh.
    const GmshGroups groups = find_groups(g, geometry.parts.names, where);
    check_elements(g, groups, where);
    const auto minus    = cell_edges(g, groups.surface[0]),
               plus     = cell_edges(g, groups.surface[1]);
    const auto on_sigma = shared_edges(g, groups, minus, plus, where);
    check_boundary_parts(g, groups, minus, plus, where);
    check_conforming(g, minus, plus, on_sigma, where);

    // The circular curves (by their nodes), for the manifolds and Sigma.
    std::map<int, std::vector<Point<2>>> entity_nodes;
    for (const auto &e : g.elements)
      if (e.type == 1)
        for (const unsigned int n : e.nodes)
          entity_nodes[e.entity].push_back(g.nodes[n]);
    arc_centres.clear();
    std::map<int, double> arc_radii;
    for (const auto &[entity, points] : entity_nodes)
      if (const auto circle = fit_circle(points))
        {
          arc_centres[entity] = circle->first;
          arc_radii[entity]   = circle->second;
        }


    // Sigma: its pieces, crack pieces, clamped ends and orientation.
    const SigmaChain chain = sigma_chain(g, on_sigma, where);
    InterfaceCurve  &curve = curves[0];
    curve = InterfaceCurve(sigma_pieces(g, chain, arc_centres, arc_radii), 0.);
    curve.set_crack(crack_pieces(g, chain, groups.crack, curve, where));
    // An edge crack's mouth must stay free. --check-geometry takes every
    // part as clamped but those at a mouth, which it names instead.
    const std::array<bool, 2> mouths  = crack_mouths(curve.crack(), curve);
    std::vector<bool>         clamped = geometry.clamped;
    if (geometry.free_parts_at_crack_mouths)
      for (const unsigned int k : {0u, 1u})
        if (mouths[k])
          for (const unsigned int part :
               parts_at_node(g,
                             groups,
                             geometry.parts.names,
                             k == 0 ? chain.nodes.front() : chain.nodes.back()))
            clamped[part] = false;
    const auto clamped_end = clamped_ends(
      g, groups, geometry.parts.names, clamped, minus, plus, chain);
    check_crack_mouths(g,
                       groups,
                       chain,
                       mouths,
                       clamped_end,
                       geometry.parts.names,
                       clamped,
                       where);
    curve.set_clamped_ends(clamped_end);
    if (against_orientation(g, groups, chain, curve))
      curve.reverse();
    gmsh = mesh_ptr;
  }
} // namespace bilayer
