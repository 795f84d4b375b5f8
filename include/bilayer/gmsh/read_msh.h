#ifndef bilayer_read_msh_h
#define bilayer_read_msh_h

#include <bilayer/gmsh/gmsh_mesh.h>

#include <istream>
#include <string>

/**
 * @file
 * Reading a mesh of Gmsh's format 2 (ASCII), for gmsh_mesh.cc: the .msh
 * file of the entry Geometry/Gmsh file, or the files gmsh writes from a .geo
 * scene.
 */
namespace bilayer
{
  /**
   * Read the sections of a format-2 ASCII mesh from @p in: $MeshFormat,
   * $PhysicalNames, $Nodes and $Elements, the nodes checked to lie in the
   * plane z = 0. With @p names_only the reading ends at $Nodes. Messages
   * name @p file.
   */
  GmshMesh
  parse_msh(std::istream      &in,
            const std::string &file,
            const bool         names_only = false);
} // namespace bilayer

#endif
