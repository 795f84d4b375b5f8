// Gmsh scenes: the physical groups of a Gmsh mesh checked, the regions
// without gaps, each interface the edges its two regions share, the
// boundary parts on the outer boundary, a conforming mesh.

#include <bilayer/core/boundary_ids.h>
#include <bilayer/geometry/gmsh_groups.h>

#include <algorithm>
#include <map>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The names of the glued part and the crack of interface @p i, for
    /// messages: "'Sigma 2' or 'crack 2'".
    std::string
    interface_names(const unsigned int i)
    {
      return "'" + gmsh_interface_name(i, false) + "' or '" +
             gmsh_interface_name(i, true) + "'";
    }


    /// The regions of the file by name, checked to run without a gap.
    std::vector<int>
    find_regions(const GmshMesh &g, const std::string &where)
    {
      std::vector<std::string> names;
      for (const auto &[tag, name] : g.surface_names)
        names.push_back(name);
      const unsigned int n = gmsh_region_count(names);
      AssertThrow(n <= BoundaryIds::max_interfaces + 1,
                  ExcMessage(where + ": " + std::to_string(n) +
                             " regions; a scene may have at most " +
                             std::to_string(BoundaryIds::max_interfaces + 1)));
      for (const std::string &name : names)
        if (const unsigned int k = gmsh_region_number(name);
            k > 0 && (k > n || name != gmsh_region_name(k - 1)))
          AssertThrow(false,
                      ExcMessage(
                        where + ": the physical surface '" + name + "' " +
                        (k <= 2 ? "names a region that is called '" +
                                    gmsh_region_name(k - 1) + "'" :
                                  "has no region '" + gmsh_region_name(n) +
                                    "' below it") +
                        ": the regions are 'Omega-', 'Omega+', 'Region 3', "
                        "'Region 4', ... from the bottom, without gaps"));
      std::vector<int> surface(n);
      for (const unsigned int r : Layout::indices(n))
        {
          surface[r] = g.physical_tag(2, gmsh_region_name(r));
          AssertThrow(surface[r] >= 0,
                      ExcMessage(where + ": no physical surface named '" +
                                 gmsh_region_name(r) + "' (the region " +
                                 (r == 0 ? "below Sigma" : "above Sigma") +
                                 ")"));
        }
      return surface;
    }


  } // namespace


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


  /// The groups by name; every named curve an interface's glued part or
  /// crack, or a boundary part.
  GmshGroups
  find_groups(const GmshMesh                 &g,
              const std::vector<std::string> &part_names,
              const std::string              &where)
  {
    GmshGroups groups;
    groups.surface            = find_regions(g, where);
    unsigned int n_interfaces = 1;
    for (const auto &[tag, name] : g.curve_names)
      n_interfaces = std::max(n_interfaces, gmsh_interface_number(name));
    AssertThrow(n_interfaces <= BoundaryIds::max_interfaces,
                ExcMessage(where + ": " + std::to_string(n_interfaces) +
                           " interfaces; a scene may have at most " +
                           std::to_string(BoundaryIds::max_interfaces)));
    for (const unsigned int i : Layout::indices(n_interfaces))
      {
        const std::array<int, 2> tags = {
          {g.physical_tag(1, gmsh_interface_name(i, false)),
           g.physical_tag(1, gmsh_interface_name(i, true))}};
        AssertThrow(tags[0] >= 0 || tags[1] >= 0,
                    ExcMessage(where + ": no physical curve named " +
                               interface_names(i) +
                               (i == 0 ? " (the glued part of the interface "
                                         "between 'Omega-' and 'Omega+', its "
                                         "crack)" :
                                         " (the interfaces are 'Sigma', "
                                         "'Sigma 2', 'Sigma 3', ... without "
                                         "gaps)")));
        groups.interface.push_back(tags);
      }
    for (const auto &[tag, name] : g.curve_names)
      {
        const unsigned int k = gmsh_interface_number(name);
        if (k > 0)
          {
            AssertThrow(groups.interface_of(tag) == int(k) - 1,
                        ExcMessage(where + ": the physical curve '" + name +
                                   "' names interface " + std::to_string(k) +
                                   ", whose curves are " +
                                   interface_names(k - 1)));
          }
        else
          AssertThrow(std::find(part_names.begin(), part_names.end(), name) !=
                        part_names.end(),
                      ExcMessage(where + ": the physical curve '" + name +
                                 "' is not among the boundary parts read "
                                 "from the file"));
      }
    return groups;
  }


  void
  check_elements(const GmshMesh    &g,
                 const GmshGroups  &groups,
                 const std::string &where)
  {
    const auto &surface = groups.surface;
    // Every cell in exactly one region, every line element of a physical
    // curve in exactly one named group.
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
            AssertThrow(std::count(surface.begin(), surface.end(), e.physical) >
                          0,
                        ExcMessage(where + ": the cells of " + entity +
                                   " (e.g. at " + mid_point(e) +
                                   ") are in the physical surface " + group(e) +
                                   "; bilayer reads only the regions "
                                   "'Omega-', 'Omega+' (and 'Region 3', "
                                   "...): put the surface into one of "
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
                                          "'Sigma', 'crack' (or another "
                                          "interface's groups) or one "
                                          "boundary part")) +
                      ": remove it from all but one"));
      }
  }


  /// The edges of the interfaces, checked to be the edges shared by the
  /// cells of the two regions each joins (@p edges).
  InterfaceEdges
  shared_edges(const GmshMesh    &g,
               GmshGroups        &groups,
               const RegionEdges &edges,
               const std::string &where)
  {
    const auto edge_text = [&](const GmshEdge &e) {
      return point_text(0.5 * (g.nodes[e.first] + g.nodes[e.second]));
    };
    // Every edge of a region belongs to one cell or two.
    for (const unsigned int r : Layout::indices(edges.size()))
      {
        const std::string name = gmsh_region_name(r);
        AssertThrow(!edges[r].empty(),
                    ExcMessage(where + ": the physical surface '" + name +
                               "' has no triangles or quadrilaterals"));
        for (const auto &[e, n] : edges[r])
          AssertThrow(n <= 2,
                      ExcMessage(where + ": more than two cells of '" + name +
                                 "' share the edge at " + edge_text(e) +
                                 " (overlapping cells)"));
      }
    InterfaceEdges on_interface(groups.interface.size());
    for (const auto &e : g.elements)
      if (const int i = groups.interface_of(e.physical); e.type == 1 && i >= 0)
        on_interface[i][gmsh_edge(e.nodes[0], e.nodes[1])] = &e;
    // The regions of each edge.
    std::map<GmshEdge, std::vector<unsigned int>> regions_of;
    for (const unsigned int r : Layout::indices(edges.size()))
      for (const auto &[e, n] : edges[r])
        regions_of[e].push_back(r);
    // Interface i joins the two regions whose cells share its edges: every
    // edge of it a boundary edge of the same two regions.
    groups.between.assign(on_interface.size(), {{0, 0}});
    for (const unsigned int i : Layout::indices(on_interface.size()))
      {
        AssertThrow(!on_interface[i].empty(),
                    ExcMessage(where + ": the physical curves " +
                               interface_names(i) + " have no line elements"));
        bool first = true;
        for (const auto &[e, element] : on_interface[i])
          {
            const std::string name =
              gmsh_interface_name(i,
                                  element->physical == groups.interface[i][1]);
            const auto it = regions_of.find(e);
            AssertThrow(it != regions_of.end() && it->second.size() == 2 &&
                          edges[it->second[0]].at(e) == 1 &&
                          edges[it->second[1]].at(e) == 1,
                        ExcMessage(
                          where + ": the '" + name + "' edge at " +
                          edge_text(e) +
                          " is not a boundary edge of two regions: an "
                          "interface must separate the two regions it joins "
                          "(curves shared by both surfaces)"));
            const std::array<unsigned int, 2> pair = {
              {it->second[0], it->second[1]}};
            if (first)
              groups.between[i] = pair;
            first = false;
            AssertThrow(
              pair == groups.between[i],
              ExcMessage(
                where + ": the '" + name + "' edge at " + edge_text(e) +
                " separates '" + gmsh_region_name(pair[0]) + "' and '" +
                gmsh_region_name(pair[1]) + "', other edges of interface " +
                std::to_string(i + 1) + " '" +
                gmsh_region_name(groups.between[i][0]) + "' and '" +
                gmsh_region_name(groups.between[i][1]) +
                "': an interface joins two regions (give the curves between "
                "other regions an interface of their own, 'Sigma K')"));
          }
      }
    AssertThrow(groups.between[0] == (std::array<unsigned int, 2>{{0, 1}}),
                ExcMessage(where + ": Sigma separates '" +
                           gmsh_region_name(groups.between[0][0]) + "' and '" +
                           gmsh_region_name(groups.between[0][1]) +
                           "'; Sigma is the interface between 'Omega-' and "
                           "'Omega+'"));
    // Two regions share only the edges of the interfaces between them;
    // every region meets another along an interface.
    std::vector<bool> joined(edges.size(), false);
    for (const auto &pair : groups.between)
      joined[pair[0]] = joined[pair[1]] = true;
    for (const unsigned int r : Layout::indices(edges.size()))
      AssertThrow(joined[r],
                  ExcMessage(where + ": the region '" + gmsh_region_name(r) +
                             "' lies on no interface: every region meets "
                             "another along an interface ('Sigma K', "
                             "'crack K')"));
    for (const auto &[e, regions] : regions_of)
      if (regions.size() > 1)
        {
          AssertThrow(regions.size() == 2,
                      ExcMessage(where + ": the edge at " + edge_text(e) +
                                 " is an edge of " +
                                 std::to_string(regions.size()) +
                                 " regions (overlapping cells)"));
          bool on_one = false;
          for (const auto &interface : on_interface)
            on_one = on_one || interface.count(e) == 1;
          AssertThrow(on_one,
                      ExcMessage(
                        where + ": '" + gmsh_region_name(regions[0]) +
                        "' and '" + gmsh_region_name(regions[1]) +
                        "' share the edge at " + edge_text(e) +
                        ", which is in no interface's curves ('Sigma', "
                        "'crack', 'Sigma K', 'crack K')"));
        }
    return on_interface;
  }


  void
  check_boundary_parts(const GmshMesh    &g,
                       const GmshGroups  &groups,
                       const RegionEdges &edges,
                       const std::string &where)
  {
    // The named boundary parts lie on the outer boundary: each edge is an
    // edge of one cell.
    for (const auto &e : g.elements)
      if (e.type == 1 && groups.interface_of(e.physical) < 0 &&
          g.curve_names.count(e.physical) > 0)
        {
          const GmshEdge k     = gmsh_edge(e.nodes[0], e.nodes[1]);
          unsigned int   cells = 0;
          for (const auto &region : edges)
            if (const auto m = region.find(k); m != region.end())
              cells += m->second;
          AssertThrow(
            cells == 1,
            ExcMessage(
              where + ": the '" + g.curve_names.at(e.physical) + "' edge at " +
              point_text(0.5 * (g.nodes[k.first] + g.nodes[k.second])) +
              " (Gmsh curve " + std::to_string(e.entity) + ") is an edge of " +
              std::to_string(cells) +
              " cells, not of the outer boundary: a boundary "
              "part must lie on the boundary of a region"));
        }
  }


  void
  check_conforming(const GmshMesh       &g,
                   const RegionEdges    &edges,
                   const InterfaceEdges &on_interface,
                   const std::string    &where)
  {
    // Non-conforming meshes: a boundary edge along another boundary edge
    // (a hanging node, or cells that do not share their nodes).
    const auto on_any = [&](const GmshEdge &e) {
      for (const auto &interface : on_interface)
        if (interface.count(e) == 1)
          return true;
      return false;
    };
    std::vector<GmshEdge> boundary;
    for (const auto &region : edges)
      for (const auto &[e, n] : region)
        if (n == 1 && !on_any(e))
          boundary.push_back(e);
    for (const auto &interface : on_interface)
      for (const auto &[e, element] : interface)
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
} // namespace bilayer
