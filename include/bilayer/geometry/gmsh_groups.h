#ifndef bilayer_geometry_gmsh_groups_h
#define bilayer_geometry_gmsh_groups_h

#include <bilayer/core/layout.h>
#include <bilayer/gmsh/gmsh_mesh.h>

#include <array>
#include <map>
#include <string>
#include <vector>

/**
 * The physical groups of a Gmsh scene checked (docs/geometry.md): the
 * regions 'Omega-', 'Omega+', 'Region 3', ... without gaps, the curves of
 * each interface ('Sigma'/'crack', 'Sigma K'/'crack K'), every cell in one
 * region and every line element in one named group, each interface the
 * edges its two regions share and nothing else shared, the boundary parts
 * on the outer boundary, a conforming mesh. Each check throws a one-line
 * message that starts with @p where (the entry and the file).
 */
namespace bilayer
{
  /// The physical groups of a Gmsh scene that bilayer reads.
  struct GmshGroups
  {
    /// The regions: Omega-, Omega+, Region 3, ... (gmsh_region_name()).
    std::vector<int> surface;
    /// Per interface (Sigma first): the glued part and the crack (-1
    /// where absent).
    std::vector<std::array<int, 2>> interface;
    /// Per interface: the two regions it joins, the lower number first
    /// (found by shared_edges()).
    std::vector<std::array<unsigned int, 2>> between;

    /// The interface of the physical curve @p tag, or -1 (a boundary
    /// part).
    int
    interface_of(const int tag) const
    {
      for (const unsigned int i : Layout::indices(interface.size()))
        if (tag >= 0 && (interface[i][0] == tag || interface[i][1] == tag))
          return i;
      return -1;
    }
  };


  /// The edges of the cells of each region with the number of its cells
  /// that use them.
  using RegionEdges = std::vector<std::map<GmshEdge, unsigned int>>;

  /// The edges of each interface (glued part and crack), by interface.
  using InterfaceEdges =
    std::vector<std::map<GmshEdge, const GmshMesh::Element *>>;


  /// The edges of the cells of the physical surface @p surface with the
  /// number of cells that use them.
  std::map<GmshEdge, unsigned int>
  cell_edges(const GmshMesh &mesh, const int surface);

  /// The groups by name; every named curve an interface's glued part or
  /// crack, or one of the boundary parts @p part_names.
  GmshGroups
  find_groups(const GmshMesh                 &g,
              const std::vector<std::string> &part_names,
              const std::string              &where);

  /// Every cell in exactly one region, every line element of a physical
  /// curve in exactly one named group.
  void
  check_elements(const GmshMesh    &g,
                 const GmshGroups  &groups,
                 const std::string &where);

  /// The edges of the interfaces, checked to be the edges shared by the
  /// cells of the two regions each joins (@p edges), and those regions
  /// (GmshGroups::between).
  InterfaceEdges
  shared_edges(const GmshMesh    &g,
               GmshGroups        &groups,
               const RegionEdges &edges,
               const std::string &where);

  /// The named boundary parts lie on the outer boundary.
  void
  check_boundary_parts(const GmshMesh    &g,
                       const GmshGroups  &groups,
                       const RegionEdges &edges,
                       const std::string &where);

  /// No boundary edge lies along another (hanging nodes, cells that do
  /// not share their nodes).
  void
  check_conforming(const GmshMesh       &g,
                   const RegionEdges    &edges,
                   const InterfaceEdges &on_interface,
                   const std::string    &where);
} // namespace bilayer

#endif
