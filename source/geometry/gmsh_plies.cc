// Gmsh scenes: the ply groups (physical surfaces inside the regions that
// Materials/Layer k/Ply groups names) taken out of the mesh and kept as the
// cells' material ids.

#include <bilayer/geometry/geometry.h>

#include <algorithm>
#include <map>
#include <set>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The nodes of @p e sorted: a cell's key, whatever its orientation.
    std::vector<unsigned int>
    sorted_nodes(const GmshMesh::Element &e)
    {
      std::vector<unsigned int> key = e.nodes;
      std::sort(key.begin(), key.end());
      return key;
    }
  } // namespace


  void
  Geometry::take_ply_groups(GmshMesh &g, const std::string &where)
  {
    ply_cells.clear();
    unlisted_surfaces.clear();
    // The cells of the regions (the surfaces named as regions: Omega-,
    // Omega+, Region K), by nodes.
    std::set<int> regions;
    for (const auto &[tag, name] : g.surface_names)
      if (gmsh_region_number(name) > 0)
        regions.insert(tag);
    std::set<std::vector<unsigned int>> in_regions;
    for (const auto &e : g.elements)
      if ((e.type == 2 || e.type == 3) && regions.count(e.physical) > 0)
        in_regions.insert(sorted_nodes(e));
    std::map<int, types::material_id> id_of;
    for (unsigned int k = 0; k < ply_groups.size(); ++k)
      {
        const int   tag = g.physical_tag(2, ply_groups[k]);
        std::string surfaces;
        for (const auto &[t, name] : g.surface_names)
          surfaces += (surfaces.empty() ? "'" : ", '") + name + "'";
        AssertThrow(tag >= 0,
                    ExcMessage(
                      "Materials/Layer k/Ply groups names '" + ply_groups[k] +
                      "', which is not a physical surface of " + where +
                      " (its physical surfaces: " + surfaces + ")"));
        id_of[tag] = k + 1;
      }
    // The ply groups' cells, and those of the other named surfaces inside
    // the regions (not read: a note names them), leave the mesh; a cell of
    // a surface outside the regions stays, and check_elements() refuses it.
    std::set<int>                  unlisted;
    std::vector<GmshMesh::Element> kept;
    for (const auto &e : g.elements)
      {
        const bool cell  = e.type == 2 || e.type == 3;
        const auto group = id_of.find(e.physical);
        if (cell && group == id_of.end() && regions.count(e.physical) == 0 &&
            g.surface_names.count(e.physical) > 0 &&
            in_regions.count(sorted_nodes(e)) > 0)
          {
            unlisted.insert(e.physical);
            continue;
          }
        if (!cell || group == id_of.end())
          {
            kept.push_back(e);
            continue;
          }
        const auto [it, added] =
          ply_cells.emplace(sorted_nodes(e), group->second);
        Point<2> centre;
        for (const unsigned int n : e.nodes)
          centre += g.nodes[n] / double(e.nodes.size());
        AssertThrow(added || it->second == group->second,
                    ExcMessage(where + ": the cell at " + point_text(centre) +
                               " (Gmsh surface " + std::to_string(e.entity) +
                               ") is in two ply groups, '" +
                               ply_groups[it->second - 1] + "' and '" +
                               ply_groups[group->second - 1] +
                               "' (Materials/Layer k/Ply groups): a cell "
                               "lies in one ply"));
      }
    g.elements = std::move(kept);
    for (const int tag : unlisted)
      {
        unlisted_surfaces.push_back(g.surface_names.at(tag));
        g.surface_names.erase(tag);
      }
    for (const auto &[tag, id] : id_of)
      g.surface_names.erase(tag);
    // Every ply cell a cell of a region (where Omega- and Omega+ exist;
    // else the region checks refuse the scene).
    if (g.physical_tag(2, "Omega-") >= 0 && g.physical_tag(2, "Omega+") >= 0)
      for (const auto &[nodes, id] : ply_cells)
        if (in_regions.count(nodes) == 0)
          {
            Point<2> centre;
            for (const unsigned int n : nodes)
              centre += g.nodes[n] / double(nodes.size());
            AssertThrow(false,
                        ExcMessage(
                          where + ": the cell at " + point_text(centre) +
                          " of the ply group '" + ply_groups[id - 1] +
                          "' (Materials/Layer k/Ply groups) is in no "
                          "region ('Omega-', 'Omega+', 'Region K'): a ply is "
                          "a part of a region; add its surfaces to one of "
                          "them"));
          }
  }


} // namespace bilayer
