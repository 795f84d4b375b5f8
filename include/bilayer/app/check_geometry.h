#ifndef bilayer_check_geometry_h
#define bilayer_check_geometry_h

#include <ostream>
#include <string>
#include <vector>

namespace bilayer
{
  /**
   * `bilayer --check-geometry FILE`: mesh the Gmsh scene @p file (.geo or
   * .msh) as a run would (Geometry/Gmsh file = FILE, every boundary part
   * clamped), with every check of Geometry's reading of Gmsh scenes
   * (docs/geometry.md), and write to @p out its physical groups (dimension,
   * tag, name, elements), the cells of Omega- and Omega+ (triangles or
   * quadrilaterals), Sigma (its pieces, length and ends), the crack pieces
   * (end points and length) and the boundary parts (edges), then "PASS".
   * @p overrides are --set assignments of the Mesh section (Gmsh mesh size
   * factor, Gmsh time limit); @p allow_gmsh_commands lets a .geo run
   * programs and write files. A refusal throws the one-line message of the
   * run.
   */
  void
  check_geometry(const std::string              &file,
                 const std::vector<std::string> &overrides,
                 const bool                      allow_gmsh_commands,
                 std::ostream                   &out);
} // namespace bilayer

#endif
