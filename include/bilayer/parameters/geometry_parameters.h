#ifndef bilayer_geometry_parameters_h
#define bilayer_geometry_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <bilayer/core/layout.h>
#include <bilayer/gmsh/gmsh_mesh.h>

#include <array>
#include <string>
#include <vector>

/**
 * The subsection Geometry: the rectangle Omega, Sigma and the crack, or a
 * Gmsh scene, and the boundary parts that are clamped.
 */
namespace bilayer
{
  /// The four sides of the rectangle Omega.
  enum class Side
  {
    left   = 0,
    right  = 1,
    bottom = 2,
    top    = 3
  };

  constexpr unsigned int n_sides = 4;

  /// One value per side of the rectangle, indexed by Side.
  template <typename T>
  using PerSide = std::array<T, n_sides>;

  /// Name of a side as written in parameter files ("left", ...).
  std::string
  side_name(const Side side);

  /**
   * The named parts of the outer boundary: the rectangle's four sides, or
   * the physical curves of a Gmsh scene other than Sigma and crack. Part i
   * has boundary id i in both subdomain meshes.
   */
  struct BoundaryParts
  {
    std::vector<std::string> names = {"left", "right", "bottom", "top"};
    /// Whether the parts come from a Gmsh file (entries "Traction on NAME")
    /// or are the rectangle's sides ("Traction on NAME side").
    bool gmsh = false;
    /// The regions of the scene: 2 (Omega- and Omega+), or those of the
    /// Gmsh file (Omega-, Omega+, Region 3, ...: gmsh_region_count()).
    unsigned int regions = 2;
    /// The interfaces of the scene: 1 (Sigma), or those of the Gmsh file
    /// (Sigma, Sigma 2, ...: GmshGroupNames::interfaces), each joining the
    /// two regions whose cells share its edges.
    unsigned int interfaces = 1;

    unsigned int
    size() const
    {
      return names.size();
    }

    /// The Loads entry of part @p i.
    std::string
    traction_entry(const unsigned int i) const
    {
      return "Traction on " + names[i] + (gmsh ? "" : " side");
    }

    /**
     * The parts of the Gmsh scene @p file: the boundary curves of its
     * groups @p names, and its regions. A name becomes the entry "Traction
     * on NAME" and a member of the list Geometry/Clamped sides: names with
     * ',', '|', '=', '#', '\\' or outer blanks are refused.
     */
    static BoundaryParts
    of_gmsh(const std::string &file, const GmshGroupNames &names);
  };

  struct GeometryParameters
  {
    /**
     * A Gmsh geometry (.geo) or mesh (.msh, format 2) of the specimen, its
     * physical groups naming the subdomains, Sigma, the crack and the
     * boundary parts (docs/geometry.md); empty: the rectangle below.
     * Relative paths are relative to the parameter file.
     */
    std::string   gmsh_file;
    BoundaryParts parts;
    /// The scene file may run programs and write files (the command-line
    /// flag --allow-gmsh-commands; not a parameter entry).
    bool allow_gmsh_commands = false;
    /// bilayer --check-geometry (not a parameter entry): every boundary part
    /// is taken as clamped but those at the mouth of an edge crack (an end
    /// of Sigma that a crack piece reaches), which a run must leave free.
    bool free_parts_at_crack_mouths = false;

    double x_min        = -1.0;
    double x_max        = 1.0;
    double y_min        = -1.0;
    double y_max        = 1.0;
    double sigma_height = 0.0;
    double crack_start  = -0.5;
    double crack_end    = 0.5;

    /// An interface of the rectangle above Sigma: the horizontal line at
    /// height with the crack (crack_start, crack_end) on it (none where
    /// they are equal).
    struct FurtherInterface
    {
      double height = 0, crack_start = 0, crack_end = 0;
    };
    /// Geometry/Interfaces above Sigma, by increasing height.
    std::vector<FurtherInterface> further_interfaces;

    /// clamped[i] is true if boundary part i belongs to Gamma_D.
    std::vector<bool> clamped = {true, true, false, false};

    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const BoundaryParts      &parts = BoundaryParts());
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const BoundaryParts      &parts = BoundaryParts());

  private:
    /// The interfaces of the entry Interfaces above Sigma = @p text (not
    /// yet checked against the rectangle).
    std::vector<FurtherInterface>
    parse_further_interfaces(const std::string &text) const;

    /// Refuse the crack (@p start, @p end) of the entry @p what unless it
    /// lies on its interface; an end within the tolerance of a side is put
    /// there.
    void
    check_crack_range(const std::string &what,
                      const std::string &crack_text,
                      double            &start,
                      double            &end) const;

    /// Refuse the crack (@p start, @p end) of the entry @p what (on the
    /// interface @p curve) unless it leaves some of it glued and reaches no
    /// clamped side.
    void
    check_crack_ends(const std::string &what,
                     const std::string &curve,
                     const std::string &crack_text,
                     const std::string &clamped_text,
                     const double       start,
                     const double       end) const;

  public:
    /// The regions of the plane: Omega- and Omega+, and one more above
    /// each interface above Sigma (bands of the rectangle, from the bottom),
    /// or those of the Gmsh file (Omega-, Omega+, Region 3, ...).
    unsigned int
    n_regions() const
    {
      return parts.regions + further_interfaces.size();
    }

    /// The interfaces: Sigma and those above it (the rectangle: one below
    /// each region but the lowest), or those of the Gmsh file.
    unsigned int
    n_interfaces() const
    {
      return parts.interfaces + further_interfaces.size();
    }

    /// The height of interface @p i of the rectangle (Sigma: 0).
    double
    interface_height(const unsigned int i) const
    {
      return i == 0 ? sigma_height : further_interfaces[i - 1].height;
    }

    /// The heights (bottom, top) of region @p r of the rectangle.
    std::array<double, 2>
    region_heights(const unsigned int r) const
    {
      return {{r == 0 ? y_min : interface_height(r - 1),
               r + 1 == n_regions() ? y_max : interface_height(r)}};
    }

    /// The end points of the crack of interface @p i of the rectangle.
    std::array<double, 2>
    crack_interval(const unsigned int i) const
    {
      if (i == 0)
        return {{crack_start, crack_end}};
      return {{further_interfaces[i - 1].crack_start,
               further_interfaces[i - 1].crack_end}};
    }

    /// The rectangle's crack on interface @p i is not empty (Gmsh scenes:
    /// see the file).
    bool
    has_crack(const unsigned int i = 0) const
    {
      return crack_interval(i)[1] > crack_interval(i)[0];
    }

    /// The crack of interface @p i as a set of pieces (coordinate x),
    /// compared with a tolerance of 1e-10 times the width of Omega.
    CrackSet
    crack(const unsigned int i = 0) const
    {
      return has_crack(i) ?
               CrackSet({{crack_interval(i)[0], crack_interval(i)[1]}},
                        1e-10 * (x_max - x_min)) :
               CrackSet();
    }
  };
} // namespace bilayer

#endif
