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
  BoundaryParts::of_gmsh(const std::string &file, const GmshGroupNames &groups)
  {
    // A name becomes the entry "Traction on NAME" and a member of the
    // list Geometry/Clamped sides.
    const std::vector<std::string> &names = groups.parts;
    for (const auto &name : names)
      AssertThrow(!name.empty() && name == Utilities::trim(name) &&
                    name.find_first_of(",|=#\\") == std::string::npos,
                  ExcMessage("Geometry/Gmsh file '" + file +
                             "': the physical curve name '" + name +
                             "' cannot name a boundary part (the entry "
                             "'Traction on NAME'): rename it in the file "
                             "without ',', '|', '=', '#', '\\' and outer "
                             "blanks"));
    return {names,
            true,
            gmsh_region_count(groups.surfaces),
            std::max(1u, groups.interfaces)};
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
    prm.declare_entry(
      "Interfaces above Sigma",
      "",
      Patterns::Anything(),
      "Further horizontal interfaces of the rectangle above Sigma, each "
      "'y' (glued everywhere) or 'y: x_start, x_end' (with a through crack "
      "between the two end points, as Crack interval on Sigma), separated "
      "by ';', by increasing y in (Height of Sigma, y_max) [length]. They "
      "cut Omega+ into regions (bands) stacked from Sigma up: interface k "
      "(Sigma is 1) lies between region k and region k + 1; the regions "
      "above Sigma take the material of Omega+ (its plies by height). "
      "Empty: Sigma is the only interface.");
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
    const std::string further_text = prm.get("Interfaces above Sigma");
    further_interfaces             = parse_further_interfaces(further_text);
    clamped.assign(parts.size(), false);
    for (const auto &name :
         Utilities::split_string_list(prm.get("Clamped sides")))
      for (unsigned int i = 0; i < parts.size(); ++i)
        if (name == parts.names[i])
          clamped[i] = true;
    prm.leave_subsection();
    AssertThrow(further_interfaces.empty() || gmsh_file.empty(),
                ExcMessage("Geometry/Interfaces above Sigma = '" +
                           further_text +
                           "' applies to the rectangle; a Gmsh scene "
                           "(Geometry/Gmsh file) has Sigma as its only "
                           "interface: leave the entry empty"));
    if (!gmsh_file.empty())
      {
        // (No clamped curve: a free specimen; a region without one floats,
        // docs/floating.md.)
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
    check_crack_range("Geometry/Crack interval on Sigma",
                      crack_text,
                      crack_start,
                      crack_end);
    check_crack_ends("Geometry/Crack interval on Sigma",
                     "Sigma",
                     crack_text,
                     clamped_text,
                     crack_start,
                     crack_end);
    double below = sigma_height;
    for (unsigned int k = 0; k < further_interfaces.size(); ++k)
      {
        FurtherInterface &f    = further_interfaces[k];
        const std::string name = "interface " + std::to_string(k + 2);
        const std::string what = "Geometry/Interfaces above Sigma: " + name;
        AssertThrow(std::abs(f.height) <= 1e100 && below < f.height &&
                      f.height < y_max,
                    ExcMessage(what + " lies at y = " + number(f.height) +
                               "; allowed: above the interface below it (y = " +
                               number(below) + ") and below y_max = " +
                               number(y_max) + ", by increasing y"));
        const std::string text =
          number(f.crack_start) + ", " + number(f.crack_end);
        check_crack_range(what, text, f.crack_start, f.crack_end);
        check_crack_ends(
          what, name, text, clamped_text, f.crack_start, f.crack_end);
        below = f.height;
      }
  }


  std::vector<GeometryParameters::FurtherInterface>
  GeometryParameters::parse_further_interfaces(const std::string &text) const
  {
    std::vector<FurtherInterface> result;
    const std::string             allowed =
      "Geometry/Interfaces above Sigma must be a list of 'y' or 'y: "
      "x_start, x_end' separated by ';', got '" +
      text + "'";
    for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        const std::size_t              colon = item.find(':');
        const std::vector<std::string> numbers =
          Utilities::split_string_list(colon == std::string::npos ?
                                         item :
                                         item.substr(0, colon) + "," +
                                           item.substr(colon + 1),
                                       ',');
        AssertThrow((colon == std::string::npos && numbers.size() == 1) ||
                      (colon != std::string::npos && numbers.size() == 3),
                    ExcMessage(allowed));
        std::vector<double> values;
        for (const std::string &n : numbers)
          {
            char        *end = nullptr;
            const double v   = std::strtod(n.c_str(), &end);
            AssertThrow(!n.empty() && end != nullptr && *end == '\0' &&
                          std::isfinite(v),
                        ExcMessage(allowed));
            values.push_back(v);
          }
        FurtherInterface f;
        f.height = values[0];
        if (values.size() == 3)
          {
            f.crack_start = values[1];
            f.crack_end   = values[2];
          }
        else
          f.crack_start = f.crack_end = x_min;
        result.push_back(f);
      }
    return result;
  }


  void
  GeometryParameters::check_crack_range(const std::string &what,
                                        const std::string &crack_text,
                                        double            &start,
                                        double            &end) const
  {
    // The crack may reach the left or right side (an edge crack; within
    // the tolerance of the crack's coordinates it is put there).
    const double tol = 1e-10 * (x_max - x_min);
    AssertThrow(x_min - tol <= start && start <= end && end <= x_max + tol,
                ExcMessage(what + " must satisfy " + number(x_min) +
                           " <= x_start <= x_end <= " + number(x_max) +
                           ", got '" + crack_text + "'"));
    for (double *e : {&start, &end})
      for (const double side : {x_min, x_max})
        if (std::abs(*e - side) <= tol)
          *e = side;
  }


  void
  GeometryParameters::check_crack_ends(const std::string &what,
                                       const std::string &curve,
                                       const std::string &crack_text,
                                       const std::string &clamped_text,
                                       const double       start,
                                       const double       end) const
  {
    if (!(end > start))
      return;
    AssertThrow(start > x_min || end < x_max,
                ExcMessage(what + " = '" + crack_text + "' covers all of " +
                           curve + " (" + number(x_min) + " to " +
                           number(x_max) + "): some of " + curve +
                           " must stay glued; end the crack "
                           "inside Omega on one side at least"));
    for (const Side side : {Side::left, Side::right})
      AssertThrow(
        !clamped[static_cast<unsigned int>(side)] ||
          (side == Side::left ? start > x_min : end < x_max),
        ExcMessage(
          what + " = '" + crack_text + "' reaches the " + side_name(side) +
          " side (x = " + number(side == Side::left ? x_min : x_max) +
          "), which is clamped (Geometry/Clamped sides = '" + clamped_text +
          "'): a crack must not reach Gamma_D; an edge crack "
          "needs a free or loaded side at its mouth"));
  }
} // namespace bilayer
