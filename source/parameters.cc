#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <bilayer/gmsh_mesh.h>
#include <bilayer/parameters.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <set>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The range of load energies (stress x area) the rectangle's loads
    /// may reach, 10^-290 to 10^290: 1e18 inside the range of double
    /// precision (1.8e308, 2.2e-308), room for sums of squares over many
    /// unknowns.
    constexpr int max_load_energy_log10 = 290;

    const PerSide<Side> all_sides = {
      {Side::left, Side::right, Side::bottom, Side::top}};

    /**
     * The number @p text of the entry @p entry (its pattern has checked the
     * format). Values beyond the range of double and denormal numbers, which
     * the patterns let through, are refused naming the entry.
     */
    double
    to_double(const std::string &text, const std::string &entry)
    {
      const std::string trimmed = Utilities::trim(text);
      errno                     = 0;
      char        *end          = nullptr;
      const double value        = std::strtod(trimmed.c_str(), &end);
      AssertThrow(!trimmed.empty() && end == trimmed.c_str() + trimmed.size(),
                  ExcMessage(entry + ": cannot read '" + text +
                             "' as a number"));
      AssertThrow(errno != ERANGE && std::isfinite(value) &&
                    (value == 0 || std::isnormal(value)),
                  ExcMessage(entry + ": '" + text +
                             "' is outside the range of normal double "
                             "numbers (0 or 2.3e-308 <= |value| <= 1.7e308)"));
      return value;
    }

    /// The number of the entry @p name of the subsection @p section (the
    /// current one of @p prm).
    double
    get_double(const ParameterHandler &prm,
               const std::string      &section,
               const std::string      &name)
    {
      return to_double(prm.get(name), section + "/" + name);
    }

    /// The entry "a, b" as two numbers.
    std::array<double, 2>
    parse_pair(const ParameterHandler &prm,
               const std::string      &section,
               const std::string      &name)
    {
      const auto parts = Utilities::split_string_list(prm.get(name), ',');
      AssertThrow(parts.size() == 2,
                  ExcMessage(section + "/" + name +
                             " must be two numbers 'a, b', got '" +
                             prm.get(name) + "'"));
      return {{to_double(parts[0], section + "/" + name),
               to_double(parts[1], section + "/" + name)}};
    }

    /// A number as a user would write it.
    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    std::string
    layer_subsection(const unsigned int layer)
    {
      return "Layer " + std::to_string(layer + 1);
    }


    /// The longest expression text read (Loads section) [characters].
    constexpr std::size_t max_expression_length = 10000;

    bool
    is_identifier(const std::string &name)
    {
      if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0])))
        return false;
      for (const char ch : name)
        if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'))
          return false;
      return true;
    }

    /// Variables and functions of the expressions (muparser and deal.II's
    /// additions), which a constant may not shadow.
    bool
    is_reserved_name(const std::string &name)
    {
      static const std::set<std::string> reserved = {
        "x",         "y",     "z",    "t",    "sin",  "cos",   "tan",   "asin",
        "acos",      "atan",  "sinh", "cosh", "tanh", "asinh", "acosh", "atanh",
        "log2",      "log10", "log",  "ln",   "exp",  "sqrt",  "sign",  "rint",
        "abs",       "min",   "max",  "sum",  "avg",  "if",    "int",   "ceil",
        "cot",       "csc",   "sec",  "pow",  "erfc", "rand",  "floor", "atan2",
        "rand_seed", "fmod",  "_pi",  "_e"};
      return reserved.count(name) > 0;
    }

    /// Build a two-component parser from "f_x; f_y" and evaluate it once so
    /// that syntax errors surface while the entry's name is known.
    std::unique_ptr<FunctionParser<2>>
    make_vector_function(const std::string                   &expression,
                         const std::map<std::string, double> &constants,
                         const std::string                   &entry)
    {
      AssertThrow(expression.size() <= max_expression_length,
                  ExcMessage(entry + ": longer than " +
                             std::to_string(max_expression_length) +
                             " characters"));
      const auto parts = Utilities::split_string_list(expression, ';');
      AssertThrow(parts.size() == 2,
                  ExcMessage(entry +
                             " must have two components separated "
                             "by ';' (x-component; y-component), got '" +
                             expression + "'"));
      auto function = std::make_unique<FunctionParser<2>>(2);
      // muparser reports syntax errors on std::cerr before deal.II throws;
      // keep them off the terminal, the message below names the entry.
      std::ostringstream muparser_noise;
      std::streambuf    *cerr_buffer = std::cerr.rdbuf(muparser_noise.rdbuf());
      const auto         restore     = [&]() { std::cerr.rdbuf(cerr_buffer); };
      try
        {
          function->initialize("x,y", parts, constants);
          Vector<double> value(2);
          function->vector_value(Point<2>(0.123, 0.456), value);
          restore();
        }
      catch (...)
        {
          restore();
          AssertThrow(false,
                      ExcMessage(entry + ": cannot evaluate '" + expression +
                                 "' as a function of x and y (known constants: "
                                 "material constants E1, nu1, mu1, lambda1, "
                                 "E2, nu2, mu2, lambda2 and Loads/Constants)"));
        }
      return function;
    }
  } // namespace


  std::string
  side_name(const Side side)
  {
    static const PerSide<std::string> names = {
      {"left", "right", "bottom", "top"}};
    return names[static_cast<unsigned int>(side)];
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
                      "gamma_c on Sigma [length]. Equal end points mean no "
                      "crack. The crack must lie strictly inside Omega.");
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
    AssertThrow(x_min < crack_start && crack_start <= crack_end &&
                  crack_end < x_max,
                ExcMessage("Geometry/Crack interval on Sigma must satisfy " +
                           number(x_min) + " < x_start <= x_end < " +
                           number(x_max) + ", got '" + crack_text + "'"));
    const bool sides = clamped[0] || clamped[1];
    AssertThrow(sides || (clamped[2] && clamped[3]),
                ExcMessage("Geometry/Clamped sides must clamp a part of the "
                           "boundary of both Omega- and Omega+ (left or right, "
                           "or both bottom and top), got '" +
                           clamped_text + "'"));
  }


  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Element shape",
                      "quadrilaterals",
                      Patterns::Selection("quadrilaterals|triangles"),
                      "Cells of both subdomain meshes: quadrilaterals (Q_k) or "
                      "triangles (P_k, each rectangle cut into two).");
    prm.declare_entry("Cells along Sigma",
                      "16",
                      Patterns::Integer(1, 100000),
                      "Number of cell edges along Sigma on the coarsest mesh "
                      "[-]. The crack end points must be mesh vertices.");
    prm.declare_entry("Cells across each subdomain",
                      "0",
                      Patterns::Integer(0, 100000),
                      "Number of cells between Sigma and the top (bottom) side "
                      "of each subdomain on the coarsest mesh [-]; 0 chooses "
                      "the number that makes the cells closest to squares.");
    prm.declare_entry(
      "Fit crack tips",
      "false",
      Patterns::Bool(),
      "Structured meshes: true moves the column of vertices "
      "nearest to each crack end point onto it (the cells in "
      "between stretched piecewise linearly), so that any crack "
      "interval can be meshed, e.g. for crack-length sweeps "
      "(scripts/crack_growth); false refuses crack end points "
      "that are not vertices.");
    prm.declare_entry("Polynomial degree of layer 1",
                      "1",
                      Patterns::Integer(1, 4),
                      "Degree of the Lagrange elements of layer 1 (u) [-].");
    prm.declare_entry("Polynomial degree of layer 2",
                      "1",
                      Patterns::Integer(1, 4),
                      "Degree of the Lagrange elements of layer 2 (v) [-].");
    prm.declare_entry(
      "Mesh files",
      "",
      Patterns::List(Patterns::Anything(), 0),
      "Gmsh (.msh, format 2) meshes of Omega- and Omega+, one "
      "entry per cycle, with {side} standing for 'minus' and "
      "'plus', e.g. 'meshes/a_{side}.msh, meshes/b_{side}.msh'. "
      "Empty: structured meshes from Element shape and Cells "
      "along Sigma. Relative paths are relative to the "
      "parameter file; cycles beyond the list refine the last "
      "meshes uniformly. Boundary ids are assigned from the "
      "coordinates.");
    prm.declare_entry("Gmsh mesh size factor",
                      "1",
                      Patterns::Double(0),
                      "Factor on the mesh sizes of a Gmsh geometry "
                      "(Geometry/Gmsh file, .geo), passed to gmsh as "
                      "-clscale [-], > 0: the coarsest mesh, which the cycles "
                      "refine (globally or adaptively) with deal.II, curved "
                      "boundaries and Sigma staying on their circles.");
    prm.declare_entry("Gmsh time limit",
                      "600",
                      Patterns::Double(0),
                      "Seconds gmsh may run on a Gmsh geometry (Geometry/"
                      "Gmsh file, .geo) before bilayer stops it and refuses "
                      "the scene [s], in [1, 1e6]: a scene that loops "
                      "forever or a gmsh that hangs ends with a message.");
    prm.declare_entry("Number of cycles",
                      "1",
                      Patterns::Integer(1, 40),
                      "Number of meshes in the sequence; with global "
                      "refinement cycle k halves the cells of cycle k-1 in "
                      "each direction, with adaptive refinement it refines "
                      "the cells the estimator marks [-].");
    prm.declare_entry("Cells along Sigma on the plus side",
                      "0",
                      Patterns::Integer(0, 100000),
                      "Cells of the structured Omega+ mesh along Sigma (its "
                      "cells across follow from them); 0: as Cells along "
                      "Sigma. Other numbers make the traces on Sigma "
                      "non-matching [-].");
    prm.declare_entry("Refinement",
                      "global",
                      Patterns::Selection("global|adaptive"),
                      "From one cycle to the next: global (every cell "
                      "split) or adaptive (cells marked from the error "
                      "indicators, each subdomain refined on its own with "
                      "hanging nodes; quadrilaterals only).");
    prm.declare_entry("Marking",
                      "bulk",
                      Patterns::Selection("bulk|fixed number|fixed fraction"),
                      "Adaptive marking over the cells of both subdomains, "
                      "named as in deal.II's GridRefinement: bulk (Doerfler "
                      "marking, deal.II's fixed fraction: the fewest cells "
                      "whose squared indicators make up Refinement fraction "
                      "of the total) or fixed number (deal.II's fixed "
                      "number: Refinement fraction of the cells). fixed "
                      "fraction, the spelling of earlier versions, is still "
                      "accepted and means fixed number (not deal.II's "
                      "fixed fraction).");
    prm.declare_entry("Refinement fraction",
                      "0.5",
                      Patterns::Double(0, 1),
                      "The bulk parameter or the fraction of cells refined "
                      "per adaptive cycle [-], in (0, 1].");
    prm.declare_entry("Interface terms in the estimator",
                      "true",
                      Patterns::Bool(),
                      "Add to Kelly's indicators the residual of the "
                      "multiplier tractions on the Sigma faces (sigma(w) n - "
                      "multiplier load) and, on the crack, the "
                      "complementarity |int mu_c [u].nu| / (2 mu), which "
                      "mark the crack tips and the end of the contact zone.");
    prm.declare_entry(
      "Refuse above available memory",
      "true",
      Patterns::Bool(),
      "true refuses a scene (before cycle 0) or stops a run (before a "
      "cycle) whose estimated peak memory exceeds the memory available to "
      "the process (MemAvailable, the address-space limit ulimit -v, a "
      "cgroup's memory.max); false runs it anyway. The estimate lies within "
      "25 % of the measured peak resident memory from 1e4 to 6.6e6 dofs "
      "(docs/performance.md); a run beyond the memory is killed by the "
      "system. Nothing runs where no memory at all is left.");
    prm.declare_entry("Weight of the contact term",
                      "1",
                      Patterns::Double(0),
                      "Factor on the complementarity term of the estimator "
                      "(1: the energy-norm indicator; larger values refine "
                      "the end of the contact zone further, for the contact "
                      "pressure and the extent of the contact zone) [-], "
                      ">= 0.");
    prm.leave_subsection();
  }


  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    shape             = prm.get("Element shape") == "triangles" ?
                          ElementShape::triangle :
                          ElementShape::quadrilateral;
    cells_along_sigma = prm.get_integer("Cells along Sigma");
    cells_across      = prm.get_integer("Cells across each subdomain");
    fit_crack_tips    = prm.get_bool("Fit crack tips");
    degree_first      = prm.get_integer("Polynomial degree of layer 1");
    degree_second     = prm.get_integer("Polynomial degree of layer 2");
    n_cycles          = prm.get_integer("Number of cycles");
    mesh_files        = Utilities::split_string_list(prm.get("Mesh files"));
    gmsh_size_factor  = get_double(prm, "Mesh", "Gmsh mesh size factor");
    AssertThrow(gmsh_size_factor >= 1e-3 && gmsh_size_factor <= 1e3,
                ExcMessage("Mesh/Gmsh mesh size factor must lie in [1e-3, "
                           "1e3], got " +
                           prm.get("Gmsh mesh size factor")));
    gmsh_time_limit = get_double(prm, "Mesh", "Gmsh time limit");
    AssertThrow(gmsh_time_limit >= 1 && gmsh_time_limit <= 1e6,
                ExcMessage("Mesh/Gmsh time limit must lie in [1, 1e6] "
                           "seconds, got " +
                           prm.get("Gmsh time limit")));
    if (!mesh_files.empty())
      shape = ElementShape::triangle;
    cells_along_sigma_plus =
      prm.get_integer("Cells along Sigma on the plus side");
    refinement = prm.get("Refinement") == "adaptive" ? Refinement::adaptive :
                                                       Refinement::global;
    marking =
      prm.get("Marking") == "bulk" ? Marking::bulk : Marking::fixed_number;
    marking_spelled_fixed_fraction = prm.get("Marking") == "fixed fraction";
    refinement_fraction = get_double(prm, "Mesh", "Refinement fraction");
    AssertThrow(refinement_fraction > 0 && refinement_fraction <= 1,
                ExcMessage("Mesh/Refinement fraction must lie in (0, 1], got " +
                           prm.get("Refinement fraction")));
    interface_terms     = prm.get_bool("Interface terms in the estimator");
    contact_weight      = get_double(prm, "Mesh", "Weight of the contact term");
    refuse_above_memory = prm.get_bool("Refuse above available memory");
    AssertThrow(refinement == Refinement::global ||
                  shape == ElementShape::quadrilateral,
                ExcMessage("Mesh/Refinement = adaptive needs Mesh/Element "
                           "shape = quadrilaterals and no Mesh files (deal.II "
                           "9.4 refines triangle meshes only globally)"));
    prm.leave_subsection();
  }


  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    const MaterialParameters defaults;
    prm.declare_entry("Number of layers",
                      "2",
                      Patterns::Integer(1, 2),
                      "2: the two glued layers of the paper; 1: layer 2 is "
                      "absent, a single elastic body with a through crack "
                      "(only the layer-1 subproblems and the crack and "
                      "gluing multipliers are built; Materials/Layer 2 and "
                      "Loads/Layer 2 are not used) [-].");
    for (unsigned int l = 0; l < 2; ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        prm.declare_entry("Young's modulus",
                          Patterns::Tools::to_string(
                            defaults.layer[l].youngs_modulus),
                          Patterns::Double(0),
                          "Young's modulus E of the layer [stress, e.g. GPa; "
                          "tractions use the same unit].");
        prm.declare_entry("Poisson's ratio",
                          Patterns::Tools::to_string(
                            defaults.layer[l].poisson_ratio),
                          Patterns::Double(-1, 0.5),
                          "Poisson's ratio nu of the layer, plane strain "
                          "[-], in (-1, 0.5).");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    n_layers = prm.get_integer("Number of layers");
    for (unsigned int l = 0; l < 2; ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        layer[l].youngs_modulus = get_double(prm,
                                             "Materials/" + layer_subsection(l),
                                             "Young's modulus");
        layer[l].poisson_ratio  = get_double(prm,
                                            "Materials/" + layer_subsection(l),
                                            "Poisson's ratio");
        const std::string where = "Materials/" + layer_subsection(l) + "/";
        AssertThrow(layer[l].youngs_modulus > 0,
                    ExcMessage(where + "Young's modulus must be > 0, got " +
                               prm.get("Young's modulus")));
        AssertThrow(layer[l].poisson_ratio > -1 && layer[l].poisson_ratio < 0.5,
                    ExcMessage(where +
                               "Poisson's ratio must lie in "
                               "(-1, 0.5), got " +
                               prm.get("Poisson's ratio")));
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  LoadParameters::LoadParameters()
  {
    for (auto &layer : traction)
      layer.assign(parts.size(), "0; 0");
  }


  void
  LoadParameters::declare_parameters(ParameterHandler    &prm,
                                     const BoundaryParts &parts)
  {
    prm.enter_subsection("Loads");
    prm.declare_entry(
      "Constants",
      "",
      Patterns::Anything(),
      "Named constants for the expressions below, as 'name = expression; "
      "name = expression'. An expression may use E1, nu1, mu1, lambda1, E2, "
      "nu2, mu2, lambda2 (the Lame constants of the layers, from Materials) "
      "and the constants defined before it, e.g. 'c = 1e-3*mu1'.");
    for (unsigned int l = 0; l < 2; ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        for (unsigned int i = 0; i < parts.size(); ++i)
          prm.declare_entry(parts.traction_entry(i),
                            "0; 0",
                            Patterns::Anything(),
                            "Traction (x-component; y-component) on this part "
                            "of the boundary of the layer as expressions of x "
                            "and y [stress]. Used where the part is not "
                            "clamped; must be '0; 0' on clamped parts.");
        prm.declare_entry("Prescribed displacement",
                          "0; 0",
                          Patterns::Anything(),
                          "Displacement (x-component; y-component) of the "
                          "layer on the clamped sides Gamma_D as expressions "
                          "of x and y [length].");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  void
  LoadParameters::parse_parameters(ParameterHandler         &prm,
                                   const MaterialParameters &materials,
                                   const BoundaryParts      &boundary_parts)
  {
    parts = boundary_parts;
    constant_values.clear();
    std::set<std::string> materials_constants;
    for (unsigned int l = 0; l < 2; ++l)
      {
        const std::string n = std::to_string(l + 1);
        for (const auto &[name, value] :
             make_elastic_law(materials.layer[l])->load_constants())
          {
            constant_values[name + n] = value;
            materials_constants.insert(name + n);
          }
      }

    prm.enter_subsection("Loads");
    constants = prm.get("Constants");
    AssertThrow(constants.size() <= max_expression_length,
                ExcMessage("Loads/Constants: longer than " +
                           std::to_string(max_expression_length) +
                           " characters"));
    for (const auto &item : Utilities::split_string_list(constants, ';'))
      {
        if (Utilities::trim(item).empty())
          continue;
        const auto        equal = item.find('=');
        const std::string name =
          Utilities::trim(item.substr(0, std::min(equal, item.size())));
        const std::string value = equal == std::string::npos ?
                                    "" :
                                    Utilities::trim(item.substr(equal + 1));
        AssertThrow(equal != std::string::npos && is_identifier(name) &&
                      !value.empty(),
                    ExcMessage("Loads/Constants must read 'name = expression; "
                               "...' with names of letters, digits and '_', "
                               "cannot read '" +
                               item + "'"));
        AssertThrow(!is_reserved_name(name) &&
                      materials_constants.count(name) == 0,
                    ExcMessage("Loads/Constants: the name '" + name +
                               "' is reserved (the coordinates x, y, the "
                               "material constants E1, nu1, mu1, lambda1, E2, "
                               "nu2, mu2, lambda2 and the functions of the "
                               "expressions): choose another name"));
        FunctionParser<1>  parser(1);
        std::ostringstream muparser_noise;
        std::streambuf *cerr_buffer = std::cerr.rdbuf(muparser_noise.rdbuf());
        double          result      = 0;
        bool            evaluated   = true;
        try
          {
            parser.initialize("t", value, constant_values);
            result = parser.value(Point<1>());
          }
        catch (...)
          {
            evaluated = false;
          }
        std::cerr.rdbuf(cerr_buffer);
        AssertThrow(evaluated,
                    ExcMessage("Loads/Constants: cannot evaluate '" + value +
                               "' for constant '" + name + "'"));
        AssertThrow(std::isfinite(result),
                    ExcMessage("Loads/Constants: constant '" + name + "' = '" +
                               value + "' is not a finite number"));
        constant_values[name] = result;
      }

    for (unsigned int l = 0; l < 2; ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        traction[l].assign(parts.size(), "0; 0");
        for (unsigned int i = 0; i < parts.size(); ++i)
          traction[l][i] = prm.get(parts.traction_entry(i));
        prescribed[l] = prm.get("Prescribed displacement");
        prm.leave_subsection();
      }
    prm.leave_subsection();

    // Evaluate every expression once now, so that errors name the entry.
    for (const Layer layer : {Layer::first, Layer::second})
      {
        prescribed_function(layer);
        for (unsigned int i = 0; i < parts.size(); ++i)
          traction_function(layer, i);
      }
  }


  std::unique_ptr<FunctionParser<2>>
  LoadParameters::traction_function(const Layer        layer,
                                    const unsigned int part) const
  {
    const unsigned int l = static_cast<unsigned int>(layer);
    return make_vector_function(traction[l][part],
                                constant_values,
                                "Loads/" + layer_subsection(l) + "/" +
                                  parts.traction_entry(part));
  }


  std::unique_ptr<FunctionParser<2>>
  LoadParameters::prescribed_function(const Layer layer) const
  {
    const unsigned int l = static_cast<unsigned int>(layer);
    return make_vector_function(prescribed[l],
                                constant_values,
                                "Loads/" + layer_subsection(l) +
                                  "/Prescribed displacement");
  }


  bool
  LoadParameters::traction_is_zero(const Layer        layer,
                                   const unsigned int part) const
  {
    const auto components = Utilities::split_string_list(
      traction[static_cast<unsigned int>(layer)][part], ';');
    for (const auto &p : components)
      if (p != "0" && p != "0.0" && p != "0.")
        return false;
    return true;
  }


  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Non-penetration on the crack",
                      "true",
                      Patterns::Bool(),
                      "true: the crack faces of layer 1 must not penetrate "
                      "each other ([u].nu >= 0, multiplier lambda_c). false: "
                      "the linear problem with traction-free crack faces that "
                      "may interpenetrate (the gluing multipliers stay).");
    prm.declare_entry("Multiplier bound p",
                      "1e7",
                      Patterns::Double(0),
                      "Bound p of the multiplier sets: 0 <= lambda_c <= p, "
                      "-p <= lambda_g, lambda-, lambda+ <= p [stress].");
    prm.declare_entry("Multiplier coupling",
                      "lumped",
                      Patterns::Selection("lumped|consistent"),
                      "How the multipliers act on the traces: lumped (nodal "
                      "quadrature of the multiplier mesh, node-to-node "
                      "constraints) or consistent (Gauss quadrature on the "
                      "common refinement of the trace meshes, mortar "
                      "constraints).");
    prm.declare_entry("Jump sampling",
                      "weighted",
                      Patterns::Selection("weighted|nodal"),
                      "Jump used in the multiplier update: weighted (the weak "
                      "jump D^-1 C w, D the lumped multiplier mass) or nodal "
                      "(the traces evaluated at the multiplier nodes). Both "
                      "agree for lumped coupling on matching meshes.");
    prm.declare_entry(
      "Multiplier mesh",
      "finer trace",
      Patterns::Selection("finer trace|coarser trace"),
      "Which trace of layer 1 on Sigma carries the mesh of the multipliers "
      "across Sigma (mu_c, mu_g) where the Omega- and Omega+ meshes do not "
      "match: finer trace (the side with more segments; contact tested at "
      "more points) or coarser trace (fewer constraints, a better "
      "conditioned dual problem). The layer-gluing multipliers always live "
      "on their own side's trace (docs/multipliers.md).");
    prm.leave_subsection();
  }


  void
  FractureParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fracture");
    prm.declare_entry("Energy release rate",
                      "true",
                      Patterns::Bool(),
                      "true: compute the energy release rate G = -dPi/dl at "
                      "every crack tip of every cycle (of both layers "
                      "together; each layer's share is not a domain "
                      "integral: scripts/crack_growth) by the domain "
                      "integral of docs/fracture.md [stress x length], "
                      "with an error bar dG [stress x length]: the largest "
                      "of the last three changes of G over the cycles, "
                      "their geometric extrapolation where they contract, "
                      "and |G(R) - G(R/2)| on the same mesh (R the support "
                      "radius), where available (docs/fracture.md, section "
                      "4: an estimate of the error, not a guaranteed "
                      "bound).");
    prm.declare_entry("Support radius",
                      "0",
                      Patterns::Double(0),
                      "Outer radius R of the support of the velocity field "
                      "theta around each tip [length]: theta moves the tip "
                      "rigidly for r <= R/2 and falls smoothly to zero at r = "
                      "R. 0 chooses half the distance from the tip to the "
                      "nearest other crack tip, corner of Sigma (a kink: "
                      "smooth junctions of segments and arcs are crossed, "
                      "then R is at most half the smallest arc radius "
                      "within reach), other piece of Sigma or point of "
                      "the outer boundary; a given R must be smaller than that "
                      "distance. G is also evaluated with R/2 (where R/2 holds "
                      "a cell at the tip) for its error bar.");
    prm.leave_subsection();
  }


  void
  FractureParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fracture");
    energy_release_rate = prm.get_bool("Energy release rate");
    support_radius      = get_double(prm, "Fracture", "Support radius");
    AssertThrow(std::isfinite(support_radius) && support_radius >= 0,
                ExcMessage("Fracture/Support radius must be >= 0 (0: "
                           "automatic), got " +
                           prm.get("Support radius")));
    prm.leave_subsection();
  }


  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    non_penetration  = prm.get_bool("Non-penetration on the crack");
    multiplier_bound = get_double(prm, "Contact", "Multiplier bound p");
    AssertThrow(multiplier_bound > 0,
                ExcMessage("Contact/Multiplier bound p must be > 0, got " +
                           prm.get("Multiplier bound p")));
    coupling = prm.get("Multiplier coupling") == "consistent" ?
                 MultiplierCoupling::consistent :
                 MultiplierCoupling::lumped;
    sampling = prm.get("Jump sampling") == "nodal" ? JumpSampling::nodal :
                                                     JumpSampling::weighted;
    mesh     = prm.get("Multiplier mesh") == "coarser trace" ?
                 MultiplierMesh::coarser_trace :
                 MultiplierMesh::finer_trace;
    prm.leave_subsection();
  }


  void
  SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry("Method",
                      "uzawa",
                      Patterns::Selection("uzawa|accelerated|active set"),
                      "Outer solver on the multipliers: uzawa (the paper's "
                      "projected Uzawa iteration, docs/problem.md section 4), "
                      "accelerated (the same projected step with FISTA "
                      "momentum and adaptive restart; with theta = auto its "
                      "step is Auto theta fraction / lambda_max) or active "
                      "set (primal-dual active set / semismooth Newton on "
                      "the dual problem, preconditioned conjugate gradients "
                      "through the subdomain solves; stops on the KKT "
                      "residual, see the subsection Active set).");
    prm.declare_entry("Uzawa step theta",
                      "65",
                      Patterns::Anything(),
                      "Step theta of the multiplier update [stress/length: "
                      "multiplier units per unit jump], a number > 0 or "
                      "'auto': Auto theta fraction * 2 / lambda_max of the "
                      "dual operator S = D^-1 C A^-1 C^T, estimated by a "
                      "power iteration. The paper uses 65 with moduli in "
                      "GPa.");
    prm.declare_entry("Auto theta fraction",
                      "0.9",
                      Patterns::Double(0, 1),
                      "theta = fraction * 2 / lambda_max for 'auto' [-], in "
                      "(0, 1).");
    prm.declare_entry("Auto theta steps",
                      "adaptive",
                      Patterns::Selection("adaptive|constant"),
                      "Steps of Method = uzawa with theta = auto [-]: "
                      "adaptive (projected gradient ascent on the dual with "
                      "Barzilai-Borwein steps, the first one theta = auto, "
                      "and a non-monotone line search along the projected "
                      "direction, no extra subdomain solves; it needs far "
                      "fewer iterations under material contrast and on "
                      "fine or graded meshes) or constant (the step theta = "
                      "auto in every iteration). A given theta is always "
                      "constant.");
    prm.declare_entry("Spectrum estimate iterations",
                      "30",
                      Patterns::Integer(1, 1000),
                      "Most power iterations for lambda_max of S (each is "
                      "four subdomain solves); it stops earlier when the "
                      "estimate changes by less than 1e-4 [-].");
    prm.declare_entry("Dual spectrum steps",
                      "0",
                      Patterns::Integer(0, 100000),
                      "Most Lanczos steps (each four subdomain solves) for "
                      "the smallest and largest eigenvalues of the dual "
                      "operator S on the free multipliers, printed and "
                      "written to summary.json per cycle with the condition "
                      "number and lambda_min / h (a diagnostic of the "
                      "multiplier spaces; 0: not estimated) [-].");
    prm.declare_entry("Maximum iterations",
                      "100000",
                      Patterns::Integer(1),
                      "Iteration limit of the outer solver [-]; reaching it "
                      "is reported as non-convergence.");
    prm.declare_entry("Stopping rule",
                      "paper",
                      Patterns::Selection("paper|paper with norm|relative|kkt"),
                      "Stopping rule of uzawa and accelerated. paper: max "
                      "||w^k - w^(k-1)|| / ||w^k||^2 < Tolerance over u-, "
                      "u+, v-, v+ in the energy norm, as printed; paper with "
                      "norm: the same with ||w^k||; relative: relative "
                      "change of the multipliers and relative constraint "
                      "violation both < Tolerance; kkt: relative KKT "
                      "residual (constraint violation, negative mu_c, "
                      "complementarity) < Tolerance, the rule of active "
                      "set.");
    prm.declare_entry("Tolerance",
                      "1e-6",
                      Patterns::Double(0),
                      "Tolerance of the stopping rule [-, or 1/energy^(1/2) "
                      "for the paper's rule].");
    prm.declare_entry("Divergence growth factor",
                      "1000",
                      Patterns::Double(1),
                      "The iteration is declared divergent when the norm of "
                      "the multiplier increment exceeds its smallest value so "
                      "far by this factor [-].");
    prm.declare_entry("Acceptance tolerance",
                      "1e-6",
                      Patterns::Double(0),
                      "Bound on the relative constraint violation, relative "
                      "interpenetration and complementarity of the final "
                      "solution; a run beyond it fails [-].");
    prm.declare_entry("Shared subproblem solver",
                      "mumps",
                      Patterns::Selection("mumps|klu"),
                      "Direct solver (Trilinos Amesos) of a subproblem that "
                      "a group of MPI processes shares (more than four "
                      "processes): mumps (MUMPS, the factorisation "
                      "distributed over the group) or klu (KLU on one "
                      "process of the group, the others send their rows).");
    prm.declare_entry("Warm start",
                      "false",
                      Patterns::Bool(),
                      "Start each cycle after the first from the previous "
                      "cycle's multipliers, interpolated onto the new "
                      "multiplier meshes and projected onto the multiplier "
                      "sets (false: from zero, as in the paper).");
    prm.declare_entry(
      "Solve on Sigma",
      "true",
      Patterns::Bool(),
      "Iterate on Sigma alone: each subproblem's factorisation eliminates "
      "its Sigma dofs last and keeps the dense Cholesky factor of its Schur "
      "complement S on them, so that a solve for multiplier loads costs two "
      "dense triangular solves on the Sigma dofs instead of a sparse forward "
      "and back substitution, the Dirichlet preconditioner needs no "
      "factorisation of its own (it applies S), and the whole solutions are "
      "computed once, at the end. For the active set method, and for uzawa "
      "and accelerated with the stopping rules kkt and relative (the paper's "
      "energy-norm rules need whole solutions in every iteration). A "
      "subproblem keeps S only where its |Sigma dofs|^2 entries are no more "
      "than those of its sparse factor. false: sparse solves in every "
      "iteration (the same solution, other rounding).");
    prm.enter_subsection("Active set");
    prm.declare_entry("Preconditioner",
                      "dirichlet",
                      Patterns::Selection("dirichlet|lumped|none"),
                      "Preconditioner of the conjugate gradients on the "
                      "dual operator: dirichlet (FETI Dirichlet: Schur "
                      "complements of the subproblems on Sigma; with Solve "
                      "on Sigma the factors already kept, else one extra "
                      "factorisation and one Dirichlet solve per subproblem "
                      "and iteration), lumped (stiffness on Sigma, no "
                      "solves) or none.");
    prm.declare_entry("Inner tolerance",
                      "1e-2",
                      Patterns::Double(0, 1),
                      "Relative residual reduction of the conjugate "
                      "gradients while the active set changes [-], in "
                      "(0, 1); once it stays the same they run to "
                      "Solver/Tolerance.");
    prm.declare_entry("Maximum Newton iterations",
                      "50",
                      Patterns::Integer(1),
                      "Limit of the active-set (Newton) steps [-]; reaching "
                      "it is reported as non-convergence.");
    prm.declare_entry("Maximum inner iterations",
                      "1000",
                      Patterns::Integer(1),
                      "Limit of the conjugate-gradient iterations of one "
                      "Newton step [-].");
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    const std::string name = prm.get("Method");
    method                 = name == "accelerated" ? SolverMethod::accelerated :
                             name == "active set"  ? SolverMethod::active_set :
                                                     SolverMethod::uzawa;
    const std::string step = prm.get("Uzawa step theta");
    auto_theta             = step == "auto";
    if (!auto_theta)
      {
        AssertThrow(Patterns::Double(0).match(step),
                    ExcMessage("Solver/Uzawa step theta must be a number > 0 "
                               "or 'auto', got '" +
                               step + "'"));
        theta = to_double(step, "Solver/Uzawa step theta");
        AssertThrow(theta > 0,
                    ExcMessage("Solver/Uzawa step theta must be > 0 or "
                               "'auto', got " +
                               step));
      }
    auto_theta_fraction = get_double(prm, "Solver", "Auto theta fraction");
    AssertThrow(auto_theta_fraction > 0 && auto_theta_fraction < 1,
                ExcMessage("Solver/Auto theta fraction must lie in (0, 1), "
                           "got " +
                           prm.get("Auto theta fraction")));
    adaptive_auto_steps = prm.get("Auto theta steps") == "adaptive";
    spectrum_iterations = prm.get_integer("Spectrum estimate iterations");
    dual_spectrum_steps = prm.get_integer("Dual spectrum steps");
    max_iterations      = prm.get_integer("Maximum iterations");
    const auto rule     = prm.get("Stopping rule");
    stopping_rule       = rule == "paper"           ? StoppingRule::paper :
                          rule == "paper with norm" ? StoppingRule::paper_norm :
                          rule == "relative"        ? StoppingRule::relative :
                                                      StoppingRule::kkt;
    tolerance           = get_double(prm, "Solver", "Tolerance");
    AssertThrow(tolerance > 0,
                ExcMessage("Solver/Tolerance must be > 0, got " +
                           prm.get("Tolerance")));
    divergence_factor = get_double(prm, "Solver", "Divergence growth factor");
    acceptance_tolerance = get_double(prm, "Solver", "Acceptance tolerance");
    AssertThrow(acceptance_tolerance > 0,
                ExcMessage("Solver/Acceptance tolerance must be > 0, got " +
                           prm.get("Acceptance tolerance")));
    warm_start     = prm.get_bool("Warm start");
    solve_on_sigma = prm.get_bool("Solve on Sigma");
    shared_solver  = prm.get("Shared subproblem solver") == "klu" ?
                       "Amesos_Klu" :
                       "Amesos_Mumps";
    prm.enter_subsection("Active set");
    const std::string p = prm.get("Preconditioner");
    preconditioner      = p == "dirichlet" ? DualPreconditioner::dirichlet :
                          p == "lumped"    ? DualPreconditioner::lumped :
                                             DualPreconditioner::none;
    inner_tolerance = get_double(prm, "Solver/Active set", "Inner tolerance");
    AssertThrow(inner_tolerance > 0 && inner_tolerance < 1,
                ExcMessage("Solver/Active set/Inner tolerance must lie in "
                           "(0, 1), got " +
                           prm.get("Inner tolerance")));
    max_newton_iterations = prm.get_integer("Maximum Newton iterations");
    max_inner_iterations  = prm.get_integer("Maximum inner iterations");
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Output directory",
                      "results",
                      Patterns::Anything(),
                      "Directory for all output files, relative to the "
                      "working directory, written whole: the run writes into "
                      "DIR.partial, which replaces DIR when every cycle "
                      "passes its checks and becomes DIR.failed when one "
                      "does not (DIR then stays as it was).");
    prm.declare_entry("Write VTU",
                      "true",
                      Patterns::Bool(),
                      "Write solution.pvd with one .pvtu per cycle and one "
                      ".vtu per layer and subdomain.");
    prm.declare_entry("Write HDF5",
                      "false",
                      Patterns::Bool(),
                      "Write one .h5 file per layer, subdomain and cycle "
                      "(deal.II's HDF5 writer) and solution.xdmf over all "
                      "cycles, for ParaView's XDMF reader: compact binary "
                      "output for large meshes.");
    prm.declare_entry("Written cycles",
                      "every cycle",
                      Patterns::Selection("every cycle|last cycle|none"),
                      "The cycles whose solution fields (Write VTU, Write "
                      "HDF5: the layers' displacements and stresses, the "
                      "interface polyline) are written: every cycle, the "
                      "last cycle (or the cycle whose checks fail, where the "
                      "run ends), or none. The interface CSV, the table and "
                      "summary.json are written for every cycle.");
    prm.declare_entry("Compression",
                      "best speed",
                      Patterns::Selection(
                        "none|best speed|default|best compression"),
                      "zlib compression of the VTU data: none (largest files, "
                      "fastest), best speed, default or best compression "
                      "(smallest files, several times slower to write).");
    prm.declare_entry("Write interface CSV",
                      "true",
                      Patterns::Bool(),
                      "Write interface-NN.csv (jumps, gaps and multipliers "
                      "at the multiplier nodes on Sigma) per cycle.");
    prm.declare_entry("Progress interval",
                      "100",
                      Patterns::Integer(0),
                      "Print the iteration, the stopping value and the "
                      "constraint violation every this many iterations; 0 "
                      "prints none [-].");
    prm.declare_entry("Terminal output",
                      "full",
                      Patterns::Selection("full|checks"),
                      "full: progress, per-cycle report, table and timings; "
                      "checks: only the pass/fail lines of the acceptance "
                      "checks (for regression tests).");
    prm.leave_subsection();
  }


  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Output directory");
    AssertThrow(!directory.empty(),
                ExcMessage("Output/Output directory must not be empty"));
    write_vtu                = prm.get_bool("Write VTU");
    write_hdf5               = prm.get_bool("Write HDF5");
    write_interface          = prm.get_bool("Write interface CSV");
    const std::string cycles = prm.get("Written cycles");
    written_cycles           = cycles == "every cycle" ? WrittenCycles::every :
                               cycles == "last cycle"  ? WrittenCycles::last :
                                                         WrittenCycles::none;
    const std::string level  = prm.get("Compression");
    compression              = level == "none"       ? Compression::none :
                               level == "best speed" ? Compression::best_speed :
                               level == "default"    ? Compression::standard :
                                                       Compression::best;
    progress_interval        = prm.get_integer("Progress interval");
    terminal = prm.get("Terminal output") == "checks" ? TerminalOutput::checks :
                                                        TerminalOutput::full;
    prm.leave_subsection();
  }


  void
  Scene::declare_parameters(ParameterHandler &prm, const BoundaryParts &parts)
  {
    GeometryParameters::declare_parameters(prm, parts);
    MeshParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    LoadParameters::declare_parameters(prm, parts);
    ContactParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    FractureParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
  }


  void
  Scene::parse_parameters(ParameterHandler &prm, const BoundaryParts &parts)
  {
    geometry.parse_parameters(prm, parts);
    mesh.parse_parameters(prm);
    materials.parse_parameters(prm);
    loads.parse_parameters(prm, materials, parts);
    contact.parse_parameters(prm);
    solver.parse_parameters(prm);
    fracture.parse_parameters(prm);
    output.parse_parameters(prm);

    AssertThrow(solver.method != SolverMethod::active_set ||
                  contact.sampling == JumpSampling::weighted ||
                  contact.coupling == MultiplierCoupling::lumped,
                ExcMessage("Solver/Method = active set needs a symmetric "
                           "dual operator: Contact/Jump sampling = weighted, "
                           "or Contact/Multiplier coupling = lumped (where "
                           "both samplings agree)"));
    for (const Layer layer : {Layer::first, Layer::second})
      AssertThrow(mesh.shape == ElementShape::quadrilateral ||
                    mesh.degree(layer) <= 2,
                  ExcMessage("Mesh/Polynomial degree of layer " +
                             std::to_string(static_cast<int>(layer) + 1) +
                             " must be 1 or 2 on triangles, got " +
                             std::to_string(mesh.degree(layer))));
    AssertThrow(geometry.gmsh_file.empty() || mesh.mesh_files.empty(),
                ExcMessage("Mesh/Mesh files and Geometry/Gmsh file exclude "
                           "each other: give the specimen by one of them"));
    for (unsigned int i = 0; i < parts.size(); ++i)
      AssertThrow(materials.n_layers == 2 ||
                    loads.traction_is_zero(Layer::second, i),
                  ExcMessage("Loads/Layer 2/" + parts.traction_entry(i) +
                             " must be '0; 0': layer 2 is absent "
                             "(Materials/Number of layers = 1)"));
    for (const Layer layer : {Layer::first, Layer::second})
      for (unsigned int i = 0; i < parts.size(); ++i)
        AssertThrow(
          !geometry.clamped[i] || loads.traction_is_zero(layer, i),
          ExcMessage(
            "Loads/Layer " + std::to_string(static_cast<int>(layer) + 1) + "/" +
            parts.traction_entry(i) + " must be '0; 0': " +
            (parts.gmsh ? parts.names[i] : "the " + parts.names[i] + " side") +
            " is clamped (Geometry/Clamped sides)"));
    // Gmsh scenes: the loads are checked where they act, on the assembled
    // loads (ElasticSubproblem).
    if (parts.gmsh)
      return;

    // Every load must be finite where it acts: tractions on their sides,
    // the prescribed displacement on the clamped sides (1001 points each).
    for (const Layer layer : {Layer::first, Layer::second})
      for (const Side side : all_sides)
        {
          const unsigned int s = static_cast<unsigned int>(side);
          const std::string  where =
            "Loads/Layer " + std::to_string(static_cast<int>(layer) + 1) + "/" +
            (geometry.clamped[s] ? std::string("Prescribed displacement") :
                                   parts.traction_entry(s));
          const auto f       = geometry.clamped[s] ?
                                 loads.prescribed_function(layer) :
                                 loads.traction_function(layer, s);
          double     largest = 0;
          Point<2>   largest_at;
          for (unsigned int i = 0; i <= 1000; ++i)
            {
              // The point a fraction i/1000 along the side.
              const double t       = i / 1000.;
              const bool   at_side = side == Side::left || side == Side::right;
              const double x =
                at_side ?
                  (side == Side::left ? geometry.x_min : geometry.x_max) :
                  geometry.x_min + t * (geometry.x_max - geometry.x_min);
              const double y =
                !at_side ?
                  (side == Side::bottom ? geometry.y_min : geometry.y_max) :
                  geometry.y_min + t * (geometry.y_max - geometry.y_min);
              for (unsigned int c = 0; c < 2; ++c)
                {
                  const double value = f->value(Point<2>(x, y), c);
                  if (!std::isfinite(value))
                    {
                      std::ostringstream point;
                      point << "(" << x << ", " << y << ")";
                      AssertThrow(false,
                                  ExcMessage(where + " must be finite on the " +
                                             side_name(side) + " side, got " +
                                             std::to_string(value) + " at " +
                                             point.str()));
                    }
                  if (std::abs(value) > largest)
                    largest = std::abs(value), largest_at = Point<2>(x, y);
                }
            }
          if (!materials.has_layer(layer) || largest == 0)
            continue;
          // The energy of the loads (per unit thickness), to within factors
          // of order one: a traction t on a body of size D and modulus E
          // displaces by t D / E and stores t^2 D^2 / E; a prescribed
          // displacement g stores E g^2. Its squares (energies, norms of the
          // residuals, the error estimate) must be representable in double
          // precision, with room for sums over millions of unknowns.
          const double D = std::max(geometry.x_max - geometry.x_min,
                                    geometry.y_max - geometry.y_min);
          const double E =
            materials.layer[static_cast<unsigned int>(layer)].youngs_modulus;
          // (In logarithms: the energy itself may overflow.)
          const double log_energy =
            geometry.clamped[s] ?
              std::log10(E) + 2 * std::log10(largest) :
              2 * std::log10(largest) + 2 * std::log10(D) - std::log10(E);
          // (Moduli beyond that range are refused where the stiffness is
          // assembled, naming the modulus.)
          if ((log_energy <= max_load_energy_log10 &&
               log_energy >= -max_load_energy_log10) ||
              std::abs(std::log10(E)) > max_load_energy_log10)
            continue;
          std::ostringstream message;
          message << std::setprecision(3) << where << " reaches " << largest
                  << " at (" << largest_at[0] << ", " << largest_at[1]
                  << "): the energy of such a load, about "
                  << (geometry.clamped[s] ? "E g^2" : "t^2 D^2 / E") << " = 10^"
                  << std::lround(log_energy) << ", is "
                  << (log_energy > 0 ? "above 10^" : "below 10^-")
                  << max_load_energy_log10
                  << ", beyond what double precision represents with its "
                     "squares; the problem is linear in the loads: scale "
                     "them (Loads/Constants or the expressions) by a power "
                     "of ten into that range and scale the results back "
                     "(displacements, stresses and multipliers with the "
                     "loads, the energy and G with their square)";
          AssertThrow(false, ExcMessage(message.str()));
        }
  }


  namespace
  {
    /**
     * Refuse a parameter file that is not a regular readable file, and
     * follow its "include" lines (ParameterHandler opens them relative to
     * the working directory) to refuse missing, unreadable or recursive
     * includes before ParameterHandler would recurse into them. Appends the
     * files read to @p files.
     */
    void
    check_parameter_file(const std::string        &filename,
                         std::vector<std::string> &chain,
                         std::vector<std::string> &files)
    {
      namespace fs = std::filesystem;
      const std::string where =
        chain.empty() ?
          "parameter file '" + filename + "'" :
          "file '" + filename + "' included from '" + chain.back() + "'";
      std::error_code error;
      const auto      status = fs::status(filename, error);
      AssertThrow(fs::exists(status),
                  ExcMessage("cannot open " + where + ": no such file"));
      AssertThrow(!fs::is_directory(status),
                  ExcMessage("cannot read " + where + ": it is a directory"));
      AssertThrow(fs::is_regular_file(status),
                  ExcMessage("cannot read " + where +
                             ": it is not a regular file (a device, pipe or "
                             "socket)"));
      constexpr std::uintmax_t limit = 1 << 24;
      AssertThrow(fs::file_size(filename, error) <= limit,
                  ExcMessage("cannot read " + where +
                             ": larger than 16 MiB, not a parameter file"));
      const std::string canonical = fs::canonical(filename, error).string();
      for (const auto &open : chain)
        AssertThrow(fs::canonical(open, error).string() != canonical,
                    ExcMessage("the " + where +
                               " includes itself (directly or through other "
                               "files)"));
      AssertThrow(chain.size() < 16,
                  ExcMessage("the " + where +
                             " is included more than 16 levels deep"));
      std::ifstream in(filename);
      AssertThrow(in,
                  ExcMessage("cannot read " + where + ": " +
                             std::strerror(errno)));
      files.push_back(filename);
      chain.push_back(filename);
      std::string  line;
      unsigned int n = 0;
      while (std::getline(in, line))
        {
          ++n;
          const auto comment = line.find('#');
          if (comment != std::string::npos)
            line.erase(comment);
          line = Utilities::trim(line);
          if (line.rfind("include ", 0) == 0 || line.rfind("INCLUDE ", 0) == 0)
            check_parameter_file(Utilities::trim(line.substr(8)), chain, files);
        }
      AssertThrow(!in.bad(),
                  ExcMessage("reading " + where + " failed at line " +
                             std::to_string(n + 1) + ": " +
                             std::strerror(errno)));
      chain.pop_back();
    }
  } // namespace


  namespace
  {
    /**
     * The boundary parts of the scene: the rectangle's sides, or the named
     * curves of Geometry/Gmsh file, read from the parameter file (or text)
     * and the overrides before the other entries are declared (they name
     * the Loads entries). Relative paths are relative to @p base.
     */
    BoundaryParts
    boundary_parts(const std::function<void(ParameterHandler &)> &parse,
                   const std::vector<std::string>                &overrides,
                   const std::filesystem::path                   &base,
                   std::string                                   &gmsh_file,
                   const bool allow_gmsh_commands)
    {
      ParameterHandler first;
      first.enter_subsection("Geometry");
      first.declare_entry("Gmsh file", "", Patterns::Anything());
      first.leave_subsection();
      first.enter_subsection("Mesh");
      first.declare_entry("Gmsh time limit", "600", Patterns::Anything());
      first.leave_subsection();
      try
        {
          parse(first);
        }
      catch (...)
        {
          // A broken file: the full parse reports it.
          return BoundaryParts();
        }
      first.enter_subsection("Geometry");
      gmsh_file = Utilities::trim(first.get("Gmsh file"));
      first.leave_subsection();
      first.enter_subsection("Mesh");
      std::string time_limit = first.get("Gmsh time limit");
      first.leave_subsection();
      for (const auto &assignment : overrides)
        {
          const auto equal = assignment.find('=');
          const auto path =
            equal == std::string::npos ?
              std::vector<std::string>() :
              Utilities::split_string_list(assignment.substr(0, equal), '/');
          if (path == std::vector<std::string>{"Geometry", "Gmsh file"})
            gmsh_file = Utilities::trim(assignment.substr(equal + 1));
          if (path == std::vector<std::string>{"Mesh", "Gmsh time limit"})
            time_limit = assignment.substr(equal + 1);
        }
      if (gmsh_file.empty())
        return BoundaryParts();
      if (std::filesystem::path(gmsh_file).is_relative())
        gmsh_file = (base / gmsh_file).string();
      // The full parse checks the limit; gmsh runs within it already now.
      GmshOptions options;
      options.allow_commands = allow_gmsh_commands;
      try
        {
          const double limit = std::stod(Utilities::trim(time_limit));
          if (limit >= 1 && limit <= 1e6)
            options.time_limit = limit;
        }
      catch (const std::exception &)
        {}
      const auto names = gmsh_boundary_names(gmsh_file, options);
      // A name becomes the entry "Traction on NAME" and a member of the
      // list Geometry/Clamped sides.
      for (const auto &name : names)
        AssertThrow(!name.empty() && name == Utilities::trim(name) &&
                      name.find_first_of(",|=#\\") == std::string::npos,
                    ExcMessage("Geometry/Gmsh file '" + gmsh_file +
                               "': the physical curve name '" + name +
                               "' cannot name a boundary part (the entry "
                               "'Traction on NAME'): rename it in the file "
                               "without ',', '|', '=', '#', '\\' and outer "
                               "blanks"));
      return BoundaryParts::of_gmsh(names);
    }


    /// Levenshtein distance of @p a and @p b, letters compared without case.
    std::size_t
    edit_distance(const std::string &a, const std::string &b)
    {
      std::vector<std::size_t> row(b.size() + 1);
      std::iota(row.begin(), row.end(), std::size_t(0));
      for (std::size_t i = 1; i <= a.size(); ++i)
        {
          std::size_t diagonal = row[0];
          row[0]               = i;
          for (std::size_t j = 1; j <= b.size(); ++j)
            {
              const std::size_t above = row[j];
              const bool        same  = std::tolower((unsigned char)a[i - 1]) ==
                                std::tolower((unsigned char)b[j - 1]);
              row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + !same});
              diagonal = above;
            }
        }
      return row[b.size()];
    }


    /**
     * The declared names of @p prm as paths "Section/.../Entry"
     * (@p subsections false) or "Section/.../Subsection" (true), read from
     * its ShortPRM listing.
     */
    std::vector<std::string>
    declared_paths(const ParameterHandler &prm, const bool subsections)
    {
      std::ostringstream listing;
      prm.print_parameters(listing, ParameterHandler::ShortPRM);
      std::istringstream       in(listing.str());
      std::vector<std::string> open, paths;
      const auto               joined = [&](const std::string &last) {
        std::string path;
        for (const auto &name : open)
          path += name + "/";
        return path + last;
      };
      for (std::string line; std::getline(in, line);)
        {
          line = Utilities::trim(line);
          if (line.rfind("subsection ", 0) == 0)
            {
              const std::string name = Utilities::trim(line.substr(11));
              if (subsections)
                paths.push_back(joined(name));
              open.push_back(name);
            }
          else if (line == "end" && !open.empty())
            open.pop_back();
          else if (line.rfind("set ", 0) == 0 && !subsections)
            paths.push_back(
              joined(Utilities::trim(line.substr(4, line.find('=') - 4))));
        }
      return paths;
    }


    /**
     * The text of @p message between the first @p before and the next
     * @p after, "" where either is missing.
     */
    std::string
    text_between(const std::string &message,
                 const std::string &before,
                 const std::string &after)
    {
      const auto a = message.find(before);
      if (a == std::string::npos)
        return "";
      const auto b = message.find(after, a + before.size());
      return b == std::string::npos ?
               "" :
               message.substr(a + before.size(), b - a - before.size());
    }


    /**
     * "; did you mean 'a', 'b' or 'c'?" for @p names, "" for none.
     */
    std::string
    suggestion(const std::vector<std::string> &names)
    {
      if (names.empty())
        return "";
      std::string text = "; did you mean ";
      for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0                ? "'" :
                 i + 1 == names.size() ? " or '" :
                                         ", '") +
                names[i] + "'";
      return text + "?";
    }


    /**
     * "; did you mean ...?" naming the declared paths closest to @p name
     * (compared as a whole path when @p name contains '/', else by their
     * last part) when they differ from it by a few letters (at most a third
     * of its length, at least 2, at most 4), else the pointer to the README's
     * table of what bilayer models (also for a name about physics that
     * bilayer does not model, however close to a real entry).
     */
    std::string
    did_you_mean(const ParameterHandler &prm,
                 const std::string      &name,
                 const bool              subsection)
    {
      // What bilayer does not model (README, "What bilayer models - and
      // what not"): a name about it is no misspelling of a real entry.
      const std::string not_modelled =
        "; what bilayer models and what not: the README's table 'What "
        "bilayer models - and what not'; every entry: bilayer "
        "--print-parameters";
      std::string lower;
      for (const char c : name)
        lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      for (const char *word :
           {"friction",         "thermal",     "temperature", "expansion",
            "plane stress",     "plane state", "orthotropic", "anisotropic",
            "stiffness tensor", "toughness",   "critical",    "body force",
            "gravity",          "density",     "cohesive",    "growth",
            "debond",           "eigenstrain", "plasticity",  "time step",
            "load step"})
        if (lower.find(word) != std::string::npos)
          return not_modelled;
      // A plausible misspelling: a few letters apart (at most a third of
      // the name, at least 2, at most 4), not added or missing words.
      const bool  whole = name.find('/') != std::string::npos;
      std::size_t best =
        std::min<std::size_t>(4, std::max<std::size_t>(2, name.size() / 3)) + 1;
      std::vector<std::string> closest;
      for (const std::string &path : declared_paths(prm, subsection))
        {
          const std::string compared =
            whole ? path : path.substr(path.rfind('/') + 1);
          const std::size_t d = edit_distance(name, compared);
          if (d < best)
            best = d, closest.clear();
          if (d == best && closest.size() < 3)
            closest.push_back(path);
        }
      // (A whole path that is declared: the error is about something else;
      // a name that is declared elsewhere: that place.)
      if (whole && best == 0)
        return "";
      return closest.empty() ? not_modelled : suggestion(closest);
    }


    /**
     * "; did you mean 'VALUE'?" for a value that a Selection pattern refuses:
     * @p message holds the value between @p before and @p after and the
     * pattern "[Selection a|b|c ]"; the choices closest to the value (at most a
     * third of its length apart, at least 2; case and blanks, '-' and '_'
     * not counted), else "".
     */
    std::string
    closest_choice(const std::string &message,
                   const std::string &before,
                   const std::string &after)
    {
      const std::string choices = text_between(message, "[Selection ", "]");
      if (choices.empty() || message.find(before) == std::string::npos)
        return "";
      const auto normal = [](const std::string &text) {
        std::string result;
        for (const char c : text)
          if (std::isalnum(static_cast<unsigned char>(c)))
            result +=
              static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return result;
      };
      const std::string value = normal(text_between(message, before, after));
      std::size_t       best  = std::max<std::size_t>(2, value.size() / 3) + 1;
      std::vector<std::string> closest;
      for (const auto &choice : Utilities::split_string_list(choices, '|'))
        {
          const std::size_t d = edit_distance(value, normal(choice));
          if (d < best)
            best = d, closest.clear();
          if (d == best)
            closest.push_back(choice);
        }
      return suggestion(closest);
    }


    /**
     * The one-line message of @p e, an error of ParameterHandler reading a
     * file, with did_you_mean() for a name it does not know.
     */
    std::string
    with_suggestion(const ParameterHandler &prm, const ExceptionBase &e)
    {
      std::string message = one_line_message(e);
      if (!message.empty() && message.back() == '.')
        message.pop_back();
      const std::string entry =
        text_between(message, "No entry with name <", ">");
      if (!entry.empty())
        return message + did_you_mean(prm, entry, false);
      const std::string marker = "no such subsection to be entered: ";
      const auto        at     = message.find(marker);
      if (at != std::string::npos)
        {
          // (deal.II's text of this error leaves the file name's '<' open.)
          const std::string closest =
            did_you_mean(prm,
                         Utilities::trim(message.substr(at + marker.size())),
                         true);
          const auto file = message.find(" of file <");
          const auto end  = message.find(": There is", file);
          if (file != std::string::npos && end != std::string::npos &&
              message.find('>', file) > end)
            message.insert(end, ">");
          return message + closest;
        }
      return message +
             closest_choice(message, "The entry value ", " for the entry");
    }
  } // namespace


  Scene
  read_scene(ParameterHandler               &prm,
             const std::string              &filename,
             const std::vector<std::string> &overrides,
             const bool                      allow_gmsh_commands)
  {
    std::vector<std::string> chain, files;
    check_parameter_file(filename, chain, files);
    const auto    base = std::filesystem::path(filename).parent_path();
    std::string   gmsh_file;
    BoundaryParts parts = boundary_parts(
      [&](ParameterHandler &first) {
        first.parse_input(filename, "", true, false);
      },
      overrides,
      base,
      gmsh_file,
      allow_gmsh_commands);
    Scene::declare_parameters(prm, parts);
    try
      {
        prm.parse_input(filename, "", false, true);
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false, ExcMessage(with_suggestion(prm, e)));
      }

    // "Section/Subsection/Entry=value" from the command line; blanks around
    // the names and the value do not count.
    for (const auto &assignment : overrides)
      {
        const auto equal = assignment.find('=');
        AssertThrow(equal != std::string::npos,
                    ExcMessage("--set expects 'Section/Entry=value', got '" +
                               assignment + "'"));
        const auto path =
          Utilities::split_string_list(assignment.substr(0, equal), '/');
        AssertThrow(path.size() >= 2,
                    ExcMessage("--set expects 'Section/Entry=value', got '" +
                               assignment + "'"));
        unsigned int entered = 0;
        try
          {
            for (; entered + 1 < path.size(); ++entered)
              prm.enter_subsection(path[entered]);
            prm.set(path.back(), Utilities::trim(assignment.substr(equal + 1)));
          }
        catch (const ExceptionBase &e)
          {
            std::string joined;
            for (const auto &name : path)
              joined += (joined.empty() ? "" : "/") + name;
            std::string message = one_line_message(e);
            if (!message.empty() && message.back() == '.')
              message.pop_back();
            // (deal.II's text for a name that is not declared.)
            if (message.find("you have not yet declared") != std::string::npos)
              message = "no entry '" + joined + "' is declared";
            AssertThrow(false,
                        ExcMessage("--set " + assignment + ": " + message +
                                   did_you_mean(prm, joined, false) +
                                   closest_choice(message,
                                                  "The string <",
                                                  "> does not match")));
          }
        for (; entered > 0; --entered)
          prm.leave_subsection();
      }

    Scene scene;
    scene.parse_parameters(prm, parts);
    scene.name = std::filesystem::path(filename).stem().string();
    for (auto &file : scene.mesh.mesh_files)
      if (std::filesystem::path(file).is_relative())
        file = (base / file).string();
    scene.geometry.gmsh_file           = gmsh_file;
    scene.geometry.allow_gmsh_commands = allow_gmsh_commands;
    scene.input_files                  = files;
    return scene;
  }


  Scene
  scene_from_string(const std::string &text, const std::string &name)
  {
    std::string         gmsh_file;
    const BoundaryParts parts = boundary_parts(
      [&](ParameterHandler &first) {
        first.parse_input_from_string(text, "", true);
      },
      {},
      "",
      gmsh_file,
      false);
    ParameterHandler prm;
    Scene::declare_parameters(prm, parts);
    prm.parse_input_from_string(text);
    Scene scene;
    scene.parse_parameters(prm, parts);
    scene.geometry.gmsh_file = gmsh_file;
    scene.name               = name;
    return scene;
  }


  std::string
  one_line_message(const ExceptionBase &exception)
  {
    std::ostringstream info;
    exception.print_info(info);
    std::string collapsed;
    for (char c : info.str())
      {
        if (c == '\n' || c == '\t')
          c = ' ';
        if (!(c == ' ' && (collapsed.empty() || collapsed.back() == ' ')))
          collapsed += c;
      }
    while (!collapsed.empty() && collapsed.back() == ' ')
      collapsed.pop_back();
    return collapsed;
  }


  std::string
  applicable_entries(const std::string &short_prm, const Scene &scene)
  {
    if (scene.geometry.gmsh_file.empty())
      return short_prm;
    const std::set<std::string> unused = {
      "Geometry/Lower left corner",
      "Geometry/Upper right corner",
      "Geometry/Height of Sigma",
      "Geometry/Crack interval on Sigma",
      "Mesh/Cells along Sigma",
      "Mesh/Cells across each subdomain",
      "Mesh/Cells along Sigma on the plus side",
      "Mesh/Fit crack tips",
      "Mesh/Mesh files"};
    std::vector<std::string> sections;
    std::string              result;
    std::istringstream       in(short_prm);
    for (std::string line; std::getline(in, line);)
      {
        const std::string trimmed = Utilities::trim(line);
        if (trimmed.rfind("subsection ", 0) == 0)
          sections.push_back(Utilities::trim(trimmed.substr(11)));
        else if (trimmed == "end" && !sections.empty())
          sections.pop_back();
        else if (trimmed.rfind("set ", 0) == 0)
          {
            const auto  equal = trimmed.find('=');
            std::string path;
            for (const auto &section : sections)
              path += section + "/";
            path += Utilities::trim(trimmed.substr(4, equal - 4));
            if (unused.count(path) > 0)
              {
                result += line.substr(0, line.find_first_not_of(' ')) + "# " +
                          path +
                          ": not used by a Gmsh scene (Geometry/Gmsh file)\n";
                continue;
              }
          }
        result += line + "\n";
      }
    return result;
  }
} // namespace bilayer
