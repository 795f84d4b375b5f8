#ifndef bilayer_gmsh_file_entry_h
#define bilayer_gmsh_file_entry_h

#include <fstream>
#include <string>

/**
 * @file
 * The entry Geometry/Gmsh file in messages, and opening its file: shared by
 * gmsh_mesh.cc, read_msh.cc, scan_geo.cc and gmsh_process.cc. Only these
 * files include it.
 */
namespace bilayer
{
  /// "Geometry/Gmsh file '@p file'", the start of every message about a
  /// Gmsh file.
  std::string
  where(const std::string &file);

  /// @p file opened for reading, refused (naming the entry) when it is
  /// missing, not a regular file or unreadable.
  std::ifstream
  open(const std::string &file);
} // namespace bilayer

#endif
