// Gmsh scenes: each interface's chain of edges, its pieces, crack pieces,
// arcs, clamped ends and orientation read from the mesh whose groups
// gmsh_groups.cc checks (the region meshes are built in
// gmsh_subdomain.cc).

#include <bilayer/geometry/geometry.h>
#include <bilayer/geometry/gmsh_groups.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// Sigma and the crack as one chain of edges from one end to the other,
    /// with its nodes in order.
    struct SigmaChain
    {
      std::vector<const GmshMesh::Element *> edges;
      std::vector<unsigned int>              nodes;
    };


    /// The curves of interface @p i in messages: "Sigma and the crack",
    /// "'Sigma 2' and 'crack 2'".
    std::string
    chain_label(const unsigned int i)
    {
      return i == 0 ? "Sigma and the crack" :
                      "'" + gmsh_interface_name(i, false) + "' and '" +
                        gmsh_interface_name(i, true) + "'";
    }


    SigmaChain
    sigma_chain(const GmshMesh                                      &g,
                const std::map<GmshEdge, const GmshMesh::Element *> &on_sigma,
                const unsigned int                                   i,
                const std::string                                   &where)
    {
      const std::string label = chain_label(i);
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
                      ExcMessage(where + ": " + label + " branch at " +
                                 point_text(g.nodes[n]) +
                                 "; they must form one open curve"));
          if (elements.size() == 1)
            ends.push_back(n);
        }
      AssertThrow(ends.size() == 2,
                  ExcMessage(where + ": " + label +
                             " must form one open "
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
                  ExcMessage(where + ": " + label +
                             " must form one connected curve"));

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
                 const unsigned int    k,
                 const std::string    &where)
    {
      const std::string whole =
        k == 0 ? "all of Sigma: some of Sigma" :
                 "all of interface " + std::to_string(k + 1) + ": some of it";
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
                                   point_text(g.nodes[nodes[j]]) + " covers " +
                                   whole +
                                   " must stay glued (the physical curve '" +
                                   gmsh_interface_name(k, false) + "')"));
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
      const auto &nodes = sigma_chain.nodes;
      // The clamped ends: the end node of a subdomain is clamped if it lies
      // on an edge of a clamped part that is an edge of that subdomain's
      // cells (its Dirichlet data fix that node alone). The gluing across
      // Sigma drops its multiplier at an end only where both sides are
      // clamped (InterfaceCurve::on_gamma_d).
      std::array<std::array<bool, 2>, 2> clamped_end = {
        {{{false, false}}, {{false, false}}}};
      for (const auto &e : g.elements)
        if (e.type == 1 && groups.interface_of(e.physical) < 0 &&
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
        if (e.type == 1 && groups.interface_of(e.physical) < 0 &&
            g.curve_names.count(e.physical) > 0 &&
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
                       const unsigned int                        i,
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
                                   point_text(g.nodes[node]) + " of " +
                                   (i == 0 ?
                                      std::string("Sigma") :
                                      "interface " + std::to_string(i + 1)) +
                                   ", which lies on the clamped part " + names +
                                   " (Geometry/Clamped sides): a crack must "
                                   "not reach Gamma_D; an edge crack needs a "
                                   "free or loaded boundary at its mouth"));
          }
    }


    /// The nodes of the outer boundary: those of the edges of one cell
    /// (@p edges: the edges of each region with their cells).
    std::set<unsigned int>
    outer_nodes(const RegionEdges &edges)
    {
      std::map<GmshEdge, unsigned int> cells;
      for (const auto &region : edges)
        for (const auto &[e, n] : region)
          cells[e] += n;
      std::set<unsigned int> outer;
      for (const auto &[e, n] : cells)
        if (n == 1)
          outer.insert({e.first, e.second});
      return outer;
    }


    /// An end of interface @p i inside the specimen (not in @p outer) is a
    /// point where it meets other interfaces (three regions or more meet
    /// there, a cross-point): a crack piece that reaches it (@p mouths) is
    /// refused, a crack ends before.
    void
    check_cross_points(const GmshMesh               &g,
                       const SigmaChain             &sigma,
                       const std::array<bool, 2>    &mouths,
                       const std::set<unsigned int> &outer,
                       const unsigned int            i,
                       const std::string            &where)
    {
      for (const unsigned int k : {0u, 1u})
        {
          const unsigned int node =
            k == 0 ? sigma.nodes.front() : sigma.nodes.back();
          AssertThrow(!mouths[k] || outer.count(node) == 1,
                      ExcMessage(where + ": a piece of '" +
                                 gmsh_interface_name(i, true) + "' reaches " +
                                 point_text(g.nodes[node]) +
                                 ", where its interface meets other "
                                 "interfaces inside the specimen: a crack "
                                 "must end before a point where three "
                                 "regions meet"));
        }
    }


    /// Whether the normal of @p curve, interface @p i, points into its
    /// first region (then the curve is to be reversed).
    bool
    against_orientation(const GmshMesh       &g,
                        const GmshGroups     &groups,
                        const SigmaChain     &sigma,
                        const InterfaceCurve &curve,
                        const unsigned int    i)
    {
      const auto &chain   = sigma.edges;
      const auto &surface = groups.surface;
      // Orientation: the normal points out of the first region of the
      // interface (Sigma: Omega-).
      {
        const auto    &first = *chain.front();
        const Point<2> mid =
          0.5 * (g.nodes[first.nodes[0]] + g.nodes[first.nodes[1]]);
        for (const auto &e : g.elements)
          if ((e.type == 2 || e.type == 3) &&
              e.physical == surface[groups.between[i][0]] &&
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

    // The groups, every cell and line element in exactly one, each
    // interface the edges its two regions share, the boundary parts on the
    // outer boundary, a conforming mesh.
    GmshGroups groups = find_groups(g, geometry.parts.names, where);
    AssertThrow(groups.surface.size() == triangulations.size() &&
                  groups.interface.size() == curves.size(),
                ExcMessage(
                  where + ": the file changed while it was read (" +
                  std::to_string(groups.surface.size()) + " regions and " +
                  std::to_string(groups.interface.size()) + " interfaces, " +
                  std::to_string(triangulations.size()) + " and " +
                  std::to_string(curves.size()) + " before)"));
    check_elements(g, groups, where);
    RegionEdges edges;
    for (const int surface : groups.surface)
      edges.push_back(cell_edges(g, surface));
    const InterfaceEdges on_interface = shared_edges(g, groups, edges, where);
    check_boundary_parts(g, groups, edges, where);
    check_conforming(g, edges, on_interface, where);

    // The circular curves (by their nodes), for the manifolds and the
    // interfaces.
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

    const std::set<unsigned int> outer = outer_nodes(edges);

    // Each interface: its pieces, crack pieces, clamped ends and
    // orientation.
    for (const unsigned int i : Layout::indices(curves.size()))
      {
        const SigmaChain chain = sigma_chain(g, on_interface[i], i, where);
        InterfaceCurve  &curve = curves[i];
        curve =
          InterfaceCurve(sigma_pieces(g, chain, arc_centres, arc_radii), 0.);
        curve.set_crack(
          crack_pieces(g, chain, groups.interface[i][1], curve, i, where));
        // An edge crack's mouth must stay free. --check-geometry takes
        // every part as clamped but those at a mouth, which it names
        // instead.
        const std::array<bool, 2> mouths = crack_mouths(curve.crack(), curve);
        check_cross_points(g, chain, mouths, outer, i, where);
        std::vector<bool> clamped = geometry.clamped;
        if (geometry.free_parts_at_crack_mouths)
          for (const unsigned int k : {0u, 1u})
            if (mouths[k])
              for (const unsigned int part :
                   parts_at_node(g,
                                 groups,
                                 geometry.parts.names,
                                 k == 0 ? chain.nodes.front() :
                                          chain.nodes.back()))
                clamped[part] = false;
        const auto clamped_end = clamped_ends(g,
                                              groups,
                                              geometry.parts.names,
                                              clamped,
                                              edges[groups.between[i][0]],
                                              edges[groups.between[i][1]],
                                              chain);
        check_crack_mouths(g,
                           groups,
                           chain,
                           mouths,
                           clamped_end,
                           geometry.parts.names,
                           clamped,
                           i,
                           where);
        curve.set_clamped_ends(clamped_end);
        curve.set_inner_ends({{outer.count(chain.nodes.front()) == 0,
                               outer.count(chain.nodes.back()) == 0}});
        if (against_orientation(g, groups, chain, curve, i))
          curve.reverse();
      }
    between = groups.between;
    gmsh    = mesh_ptr;
  }
} // namespace bilayer
