#ifndef bilayer_gmsh_mesh_h
#define bilayer_gmsh_mesh_h

#include <deal.II/base/point.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace bilayer
{
  /// The point @p p as "(x, y)", as messages about a Gmsh scene show it.
  std::string
  point_text(const dealii::Point<2> &p);

  /// A line between two Gmsh nodes, the smaller node first.
  using GmshEdge = std::pair<unsigned int, unsigned int>;

  /// The line between the nodes @p a and @p b.
  inline GmshEdge
  gmsh_edge(const unsigned int a, const unsigned int b)
  {
    return a < b ? GmshEdge(a, b) : GmshEdge(b, a);
  }


  /**
   * A 2d mesh in Gmsh's format 2 (ASCII) with its physical groups, as read
   * from a .msh file or made by the gmsh command from a .geo file. Only the
   * data bilayer needs: nodes, line/triangle/quadrilateral elements with
   * their physical and elementary (entity) tags, and the physical names.
   *
   * Physical names carry the meaning of a specimen (docs/geometry.md):
   * surfaces "Omega-" and "Omega+", curves "Sigma" (the glued part of the
   * interface) and "crack" (its debonded pieces), any other named curve a
   * part of the outer boundary that Geometry/Clamped sides and the tractions
   * of the Loads section refer to.
   */
  struct GmshMesh
  {
    struct Element
    {
      /// Gmsh element type: 1 line, 2 triangle, 3 quadrilateral.
      unsigned int type     = 0;
      int          physical = 0;
      int          entity   = 0;
      /// Indices into nodes (not Gmsh's node tags).
      std::vector<unsigned int> nodes;
    };

    /// The file named in the parameter file (for messages).
    std::string                   file;
    std::vector<dealii::Point<2>> nodes;
    std::vector<Element>          elements;
    /// Physical tag -> name, per dimension (1: curves, 2: surfaces).
    std::map<int, std::string> curve_names, surface_names;
    /// Whether the file has a $PhysicalNames section.
    bool has_physical_names = false;

    /// The physical tag of the curve or surface group @p name (dimension
    /// @p dim), or -1.
    int
    physical_tag(const unsigned int dim, const std::string &name) const;
  };

  /**
   * How a .geo scene is run through gmsh.
   */
  struct GmshOptions
  {
    /// Let the scene run programs and write files (the command-line flag
    /// --allow-gmsh-commands); otherwise scan_geo() refuses such scenes.
    bool allow_commands = false;
    /// Seconds gmsh may run before it is stopped (Mesh/Gmsh time limit).
    double time_limit = 600;
    /// gmsh -clscale (Mesh/Gmsh mesh size factor).
    double size_factor = 1;
  };

  /**
   * Refuse a .geo scene that runs programs, writes, renames or deletes
   * files, loads other files or sets options that do so (SystemCall,
   * Printf(...) > "file", Save, Print, Plugin(...).Run, General.SaveOptions,
   * Solver.*, Print.*, ...), and an Include or Merge whose path is computed:
   * the file and every literal Include (and Merge of a .geo) it reaches, with
   * comments and strings skipped. The message names file:line and the
   * statement. With @p allow_commands only the files are checked for being
   * readable.
   */
  void
  scan_geo(const std::string &file, const bool allow_commands);

  /**
   * Read @p file: a .msh file (format 2 ASCII) directly, a .geo file after
   * scan_geo() by running gmsh in a temporary directory of its own (its
   * working directory and HOME, stdin /dev/null, removed afterwards) within
   * the time limit. The mesh is saved twice by one gmsh run: the
   * physical groups, and all cells (Mesh.SaveAll) so that cells in no group
   * are seen; bilayer's own settings (msh 2.2 ASCII, first order) come after
   * the scene's. Errors name the file and the entry Geometry/Gmsh file.
   */
  GmshMesh
  read_gmsh(const std::string &file, const GmshOptions &options);

  /// The named physical groups of a Gmsh scene.
  struct GmshGroupNames
  {
    /// The physical curves other than the interfaces ("Sigma", "crack",
    /// "Sigma K", "crack K"), in the order of their tags: the boundary
    /// parts of the entries of the Loads section.
    std::vector<std::string> parts;
    /// The physical surfaces, in the order of their tags.
    std::vector<std::string> surfaces;
    /// The interfaces: the largest K of the curves "Sigma K" and "crack
    /// K" (Sigma and crack: 1), 0 without any.
    unsigned int interfaces = 0;
  };

  /**
   * The named physical groups of @p file as Gmsh reports them: the .msh
   * file's $PhysicalNames, or for a .geo file those of the model gmsh builds
   * from it (after scan_geo(), without meshing).
   */
  GmshGroupNames
  gmsh_group_names(const std::string &file, const GmshOptions &options);


  /**
   * The regions and interfaces of a Gmsh scene by name (docs/geometry.md).
   * Region r (from 0, bottom up) is the physical surface "Omega-" (r = 0),
   * "Omega+" (1), "Region 3" (2), "Region 4" (3), ...; interface i joins
   * the two regions whose cells share its edges (Sigma: Omega- and Omega+),
   * its glued part the physical curve "Sigma" (i = 0) or "Sigma K"
   * (K = i + 1), its crack pieces "crack" or "crack K".
   */
  std::string
  gmsh_region_name(const unsigned int r);

  /// The name of the glued part (@p crack false) or of the crack pieces of
  /// interface @p i.
  std::string
  gmsh_interface_name(const unsigned int i, const bool crack);

  /// The number K of the region that @p name states: 1 for "Omega-", 2
  /// for "Omega+", K for "Region K" (any K >= 1, checked by the scene); 0
  /// for any other name.
  unsigned int
  gmsh_region_number(const std::string &name);

  /// The number K of the interface that the curve @p name states: 1 for
  /// "Sigma" and "crack", K for "Sigma K" and "crack K" (any K >= 1,
  /// checked by the scene); 0 for any other name (a boundary part).
  unsigned int
  gmsh_interface_number(const std::string &name);

  /// The regions of a scene whose physical surfaces are @p surfaces:
  /// Omega- and Omega+, then Region 3, 4, ... as far as they run without a
  /// gap (a gap is refused when the meshes are read).
  unsigned int
  gmsh_region_count(const std::vector<std::string> &surfaces);
} // namespace bilayer

#endif
