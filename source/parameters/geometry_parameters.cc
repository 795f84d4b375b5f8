#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/geometry_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

#include <algorithm>
#include <cmath>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


  std::string
  side_name(const Side side)
  {
    static const PerSide<std::string> names = {
      {"left", "right", "bottom", "top"}};
    return names[static_cast<unsigned int>(side)];
  }


  BoundaryParts
  BoundaryParts::of_gmsh(const std::string              &file,
                         const std::vector<std::string> &names)
  {
    // A name becomes the entry "Traction on NAME" and a member of the
    // list Geometry/Clamped sides.
    for (const auto &name : names)
      AssertThrow(!name.empty() && name == Utilities::trim(name) &&
                    name.find_first_of(",|=#\\") == std::string::npos,
                  ExcMessage("Geometry/Gmsh file '" + file +
                             "': the physical curve name '" + name +
                             "' cannot name a boundary part (the entry "
                             "'Traction on NAME'): rename it in the file "
                             "without ',', '|', '=', '#', '\\' and outer "
                             "blanks"));
    return {names, true};
  }


  void
  GeometryParameters::declare_parameters(ParameterHandler    &prm,
                                         const BoundaryParts &parts)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry(
      "Gmsh file",
      "",
      Patterns::Anything(),
      "A Gmsh geometry (.geo, meshed by the gmsh command with Mesh/Gmsh mesh "
      "size factor) or mesh (.msh, format 2) of the specimen, relative to "
      "the parameter file. Its physical groups carry the meaning by name: "
      "surfaces 'Omega-' and 'Omega+', curves 'Sigma' (the glued part of the "
      "interface) and 'crack' (one or several debonded pieces), and any "
      "other named curve a boundary part for Clamped sides and the "
      "'Traction on NAME' entries of the Loads section (docs/geometry.md). "
      "Empty: the rectangle of the entries below.");
    prm.declare_entry("Lower left corner",
                      "-1, -1",
                      Patterns::List(Patterns::Double(), 2, 2),
                      "Corner (x, y) of the rectangle Omega with the smallest "
                      "coordinates [length].");
    prm.declare_entry("Upper right corner",
                      "1, 1",
                      Patterns::List(Patterns::Double(), 2, 2),
                      "Corner (x, y) of the rectangle Omega with the largest "
                      "coordinates [length].");
    prm.declare_entry("Height of Sigma",
                      "0",
                      Patterns::Double(),
                      "y-coordinate of the horizontal line Sigma that splits "
                      "Omega into Omega- (below) and Omega+ (above) [length]. "
                      "The normal nu = (0, 1) points into Omega+.");
    prm.declare_entry("Crack interval on Sigma",
                      "-0.5, 0.5",
                      Patterns::List(Patterns::Double(), 2, 2),
                      "End points (x_start, x_end) of the through crack "
                      "gamma_c on Sigma [length], x_min <= x_start <= x_end "
                      "<= x_max. Equal end points mean no crack. An end "
                      "point inside Omega is a crack tip (G is computed "
                      "there); an end point on the left or right side "
                      "makes an edge crack whose mouth lies on that side, "
                      "no tip: that side must not be clamped (Clamped "
                      "sides), and the crack must not cover all of Sigma.");
    std::string selection;
    for (const auto &name : parts.names)
      selection += (selection.empty() ? "" : "|") + name;
    prm.declare_entry("Clamped sides",
                      parts.gmsh ? "" : "left, right",
                      Patterns::MultipleSelection(selection),
                      "Sides of Omega (the named boundary curves of a Gmsh "
                      "scene) that form Gamma_D (both layers clamped to the "
                      "prescribed displacement). The other parts form "
                      "Gamma_N and carry the tractions of the Loads "
                      "section.");
    prm.leave_subsection();
  }


  void
  GeometryParameters::parse_parameters(ParameterHandler    &prm,
                                       const BoundaryParts &boundary_parts)
  {
    parts = boundary_parts;
    prm.enter_subsection("Geometry");
    gmsh_file        = Utilities::trim(prm.get("Gmsh file"));
    const auto lower = parse_pair(prm, "Geometry", "Lower left corner");
    const auto upper = parse_pair(prm, "Geometry", "Upper right corner");
    x_min            = lower[0];
    y_min            = lower[1];
    x_max            = upper[0];
    y_max            = upper[1];
    sigma_height     = get_double(prm, "Geometry", "Height of Sigma");
    const std::string crack_text   = prm.get("Crack interval on Sigma");
    const std::string clamped_text = prm.get("Clamped sides");
    const auto crack = parse_pair(prm, "Geometry", "Crack interval on Sigma");
    crack_start      = crack[0];
    crack_end        = crack[1];
    clamped.assign(parts.size(), false);
    for (const auto &name :
         Utilities::split_string_list(prm.get("Clamped sides")))
      for (unsigned int i = 0; i < parts.size(); ++i)
        if (name == parts.names[i])
          clamped[i] = true;
    prm.leave_subsection();
    if (!gmsh_file.empty())
      {
        // The file's own checks (Geometry) say which subdomain lacks a
        // clamped part.
        AssertThrow(std::find(clamped.begin(), clamped.end(), true) !=
                      clamped.end(),
                    ExcMessage("Geometry/Clamped sides must name at least one "
                               "boundary curve of '" +
                               gmsh_file + "', got '" + clamped_text + "'"));
        return;
      }

    AssertThrow(x_min < x_max && y_min < y_max,
                ExcMessage("Geometry/Upper right corner must lie above and to "
                           "the right of Geometry/Lower left corner"));
    // Areas, Jacobians and stiffnesses are products of lengths: keep them
    // well inside the range of double.
    for (const double v : {x_min, x_max, y_min, y_max, sigma_height})
      AssertThrow(std::abs(v) <= 1e100,
                  ExcMessage("Geometry: the corners and the height of Sigma "
                             "must lie within +-1e100 [length], got " +
                             number(v) + "; state them in other units"));
    AssertThrow(x_max - x_min >= 1e-100 && y_max - y_min >= 1e-100,
                ExcMessage("Geometry: Omega must be at least 1e-100 wide and "
                           "high [length]; state the corners in other units"));
    AssertThrow(y_min < sigma_height && sigma_height < y_max,
                ExcMessage("Geometry/Height of Sigma must lie in (" +
                           number(y_min) + ", " + number(y_max) + "), got " +
                           number(sigma_height)));
    // The crack may reach the left or right side (an edge crack; within
    // the tolerance of the crack's coordinates it is put there).
    const double tol = 1e-10 * (x_max - x_min);
    AssertThrow(x_min - tol <= crack_start && crack_start <= crack_end &&
                  crack_end <= x_max + tol,
                ExcMessage("Geometry/Crack interval on Sigma must satisfy " +
                           number(x_min) + " <= x_start <= x_end <= " +
                           number(x_max) + ", got '" + crack_text + "'"));
    for (double *end : {&crack_start, &crack_end})
      for (const double side : {x_min, x_max})
        if (std::abs(*end - side) <= tol)
          *end = side;
    const bool sides = clamped[0] || clamped[1];
    AssertThrow(sides || (clamped[2] && clamped[3]),
                ExcMessage("Geometry/Clamped sides must clamp a part of the "
                           "boundary of both Omega- and Omega+ (left or right, "
                           "or both bottom and top), got '" +
                           clamped_text + "'"));
    if (!has_crack())
      return;
    AssertThrow(crack_start > x_min || crack_end < x_max,
                ExcMessage("Geometry/Crack interval on Sigma = '" + crack_text +
                           "' covers all of Sigma (" + number(x_min) + " to " +
                           number(x_max) +
                           "): some of Sigma must stay glued; end the crack "
                           "inside Omega on one side at least"));
    for (const Side side : {Side::left, Side::right})
      AssertThrow(
        !clamped[static_cast<unsigned int>(side)] ||
          (side == Side::left ? crack_start > x_min : crack_end < x_max),
        ExcMessage("Geometry/Crack interval on Sigma = '" + crack_text +
                   "' reaches the " + side_name(side) +
                   " side (x = " + number(side == Side::left ? x_min : x_max) +
                   "), which is clamped (Geometry/Clamped sides = '" +
                   clamped_text +
                   "'): a crack must not reach Gamma_D; an edge crack "
                   "needs a free or loaded side at its mouth"));
  }
} // namespace bilayer
