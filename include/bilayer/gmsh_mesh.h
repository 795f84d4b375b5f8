#ifndef bilayer_gmsh_mesh_h
#define bilayer_gmsh_mesh_h

#include <deal.II/base/point.h>

#include <map>
#include <string>
#include <vector>

namespace bilayer
{
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

    /// The physical tag of the curve or surface group @p name (dimension
    /// @p dim), or -1.
    int
    physical_tag(const unsigned int dim, const std::string &name) const;
  };

  /**
   * Read @p file: a .msh file (format 2 ASCII) directly, a .geo file by
   * running `gmsh -2 -format msh2 -clscale size_factor` into a temporary
   * directory that is removed afterwards. Errors name the file and the
   * entry Geometry/Gmsh file.
   */
  GmshMesh
  read_gmsh(const std::string &file, const double size_factor);

  /**
   * The names of the physical curves of @p file other than "Sigma" and
   * "crack", in the order of their tags (read from the .msh file's
   * $PhysicalNames or from the Physical Curve/Line statements of a .geo
   * file, without meshing), for the entries of the Loads section.
   */
  std::vector<std::string>
  gmsh_boundary_names(const std::string &file);
} // namespace bilayer

#endif
