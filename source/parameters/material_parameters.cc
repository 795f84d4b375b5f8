#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/material_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


  namespace
  {
    /// The entries of one layer that an orthotropic law uses.
    void
    declare_orthotropic(ParameterHandler &prm, const LayerMaterial &defaults)
    {
      const OrthotropicConstants &o = defaults.orthotropic;
      const auto                  modulus =
        [&](const std::string &name, const double value, const char *what) {
          prm.declare_entry(name,
                            Patterns::Tools::to_string(value),
                            Patterns::Double(0),
                            std::string("Law = orthotropic: ") + what +
                              " [stress, the unit of Young's modulus].");
        };
      modulus("E_1", o.E_1, "Young's modulus along the material axis 1");
      modulus("E_2",
              o.E_2,
              "Young's modulus along the material axis 2 (in the plane, "
              "perpendicular to axis 1)");
      modulus("E_3",
              o.E_3,
              "Young's modulus along the material axis 3 = z (plane strain "
              "only)");
      const auto ratio =
        [&](const std::string &name, const double value, const char *what) {
          prm.declare_entry(name,
                            Patterns::Tools::to_string(value),
                            Patterns::Double(),
                            std::string("Law = orthotropic: ") + what +
                              " [-]; nu_ji = nu_ij E_j / E_i. The constants "
                              "must make the compliance positive definite.");
        };
      ratio("nu_12",
            o.nu_12,
            "Poisson's ratio nu_12, the contraction along axis 2 of a "
            "tension along axis 1");
      ratio("nu_13", o.nu_13, "Poisson's ratio nu_13 (plane strain only)");
      ratio("nu_23", o.nu_23, "Poisson's ratio nu_23 (plane strain only)");
      modulus("G_12", o.G_12, "the in-plane shear modulus G_12");
      prm.declare_entry("Orientation angle",
                        Patterns::Tools::to_string(defaults.orientation_angle),
                        Patterns::Double(-360, 360),
                        "Law = orthotropic: the angle from the x-axis to the "
                        "material axis 1, counter-clockwise [degrees].");
    }


    /// The three numbers of an orthotropic refusal, as text.
    std::string
    numbers3(const double a, const double b, const double c)
    {
      return number(a) + ", " + number(b) + ", " + number(c);
    }


    /**
     * Refuse orthotropic constants that do not make the compliance of
     * @p state positive definite, naming the entries of @p where.
     */
    void
    check_orthotropic(const OrthotropicConstants &o,
                      const PlaneState            state,
                      const std::string          &where)
    {
      const bool strain = state == PlaneState::plane_strain;
      AssertThrow(
        o.E_1 > 0 && o.E_2 > 0 && o.G_12 > 0 && (!strain || o.E_3 > 0),
        ExcMessage(where + (strain ? "E_1, E_2, E_3 and " : "E_1, E_2 and ") +
                   "G_12 must be > 0, got E_1, E_2, E_3, G_12 = " +
                   numbers3(o.E_1, o.E_2, o.E_3) + ", " + number(o.G_12)));
      // The leading minors of the compliance: |nu_ij| < sqrt(E_i / E_j)
      // for each pair, and in plane strain the determinant.
      const auto pair = [&](const double       nu,
                            const double       Ei,
                            const double       Ej,
                            const std::string &ij) {
        const double bound = std::sqrt(Ei / Ej);
        AssertThrow(std::abs(nu) < bound,
                    ExcMessage(where + "nu_" + ij + " must satisfy |nu_" + ij +
                               "| < sqrt(E_" + ij.substr(0, 1) + "/E_" +
                               ij.substr(1, 1) + ") = " + number(bound) +
                               " (a positive definite compliance), got " +
                               number(nu)));
      };
      pair(o.nu_12, o.E_1, o.E_2, "12");
      if (!strain)
        return;
      pair(o.nu_13, o.E_1, o.E_3, "13");
      pair(o.nu_23, o.E_2, o.E_3, "23");
      const double nu_21 = o.nu_12 * o.E_2 / o.E_1;
      const double nu_31 = o.nu_13 * o.E_3 / o.E_1;
      const double nu_32 = o.nu_23 * o.E_3 / o.E_2;
      const double delta = 1 - o.nu_12 * nu_21 - o.nu_23 * nu_32 -
                           o.nu_13 * nu_31 - 2 * nu_21 * nu_32 * o.nu_13;
      AssertThrow(delta > 0,
                  ExcMessage(where +
                             "nu_12, nu_13, nu_23 with E_1, E_2, E_3 must make "
                             "the 3-D compliance positive definite: 1 - "
                             "nu_12 nu_21 - nu_23 nu_32 - nu_13 nu_31 - 2 "
                             "nu_21 nu_32 nu_13 > 0 (nu_ji = nu_ij E_j/E_i), "
                             "got " +
                             number(delta) + " for nu_12, nu_13, nu_23 = " +
                             numbers3(o.nu_12, o.nu_13, o.nu_23)));
    }


    /**
     * The entry @p entry (a Stiffness) of the text @p text; @p check: refused
     * unless positive definite.
     */
    std::array<double, 6>
    parse_stiffness(const std::string &text,
                    const std::string &entry,
                    const bool         check)
    {
      const auto parts = Utilities::split_string_list(text, ',');
      AssertThrow(parts.size() == 6,
                  ExcMessage(entry +
                             " must be six numbers 'C11, C12, C16, C22, C26, "
                             "C66', got '" +
                             text + "'"));
      std::array<double, 6> c;
      for (unsigned int i = 0; i < 6; ++i)
        c[i] = to_double(parts[i], entry);
      if (!check)
        return c;
      // Sylvester's criterion on the leading minors of
      // [[C11, C12, C16], [C12, C22, C26], [C16, C26, C66]].
      const double minor2 = c[0] * c[3] - c[1] * c[1];
      const double det    = c[0] * (c[3] * c[5] - c[4] * c[4]) -
                         c[1] * (c[1] * c[5] - c[4] * c[2]) +
                         c[2] * (c[1] * c[4] - c[3] * c[2]);
      AssertThrow(c[0] > 0 && minor2 > 0 && det > 0,
                  ExcMessage(entry +
                             " must be symmetric positive definite (C11 > 0, "
                             "C11 C22 - C12^2 > 0 and det [[C11, C12, C16], "
                             "[C12, C22, C26], [C16, C26, C66]] > 0), got '" +
                             text + "'"));
      return c;
    }


    /**
     * The entry @p entry (a Thermal expansion) of the text @p text for the
     * law @p law: one number alpha (every law: isotropic alpha I;
     * orthotropic alpha_1 = alpha_2 = alpha_3; anisotropic alpha_11 =
     * alpha_22, alpha_12 = 0) or, for orthotropic and anisotropic laws,
     * three.
     */
    std::array<double, 3>
    parse_thermal_expansion(const std::string &text,
                            const std::string &entry,
                            const MaterialLaw  law)
    {
      const auto parts = Utilities::split_string_list(text, ',');
      const bool three = law != MaterialLaw::isotropic;
      AssertThrow(parts.size() == 1 || (three && parts.size() == 3),
                  ExcMessage(
                    entry + " must be " +
                    (law == MaterialLaw::isotropic ?
                       "one number alpha [1/K] (Law = isotropic)" :
                     law == MaterialLaw::orthotropic ?
                       "one number alpha or three 'alpha_1, alpha_2, "
                       "alpha_3' in the material axes [1/K] (Law = "
                       "orthotropic)" :
                       "one number alpha or three 'alpha_11, alpha_22, "
                       "alpha_12' in the x-y frame [1/K] (Law = "
                       "anisotropic)") +
                    ", finite, got '" + text + "'"));
      std::array<double, 3> a;
      for (unsigned int i = 0; i < parts.size(); ++i)
        a[i] = to_double(parts[i], entry);
      if (parts.size() == 1)
        a = {{a[0], a[0], law == MaterialLaw::anisotropic ? 0. : a[0]}};
      return a;
    }


    const std::vector<std::string> &law_entries =
      MaterialParameters::law_entry_names();


    /// The pattern of the law entry @p name of a layer.
    std::unique_ptr<Patterns::PatternBase>
    law_pattern(const std::string &name)
    {
      if (name == "Law")
        return std::make_unique<Patterns::Selection>(
          "isotropic|orthotropic|anisotropic");
      if (name == "Poisson's ratio")
        return std::make_unique<Patterns::Double>(-1, 0.5);
      if (name == "Orientation angle")
        return std::make_unique<Patterns::Double>(-360, 360);
      if (name == "Stiffness")
        return std::make_unique<Patterns::List>(Patterns::Double(), 6, 6, ",");
      if (name == "Thermal expansion")
        return std::make_unique<Patterns::List>(Patterns::Double(), 1, 3, ",");
      if (name.substr(0, 3) == "nu_")
        return std::make_unique<Patterns::Double>();
      return std::make_unique<Patterns::Double>(0);
    }


    /// The text of an entry and its full path, by the entry's name.
    using EntryText = std::function<std::string(const std::string &)>;


    /**
     * Read the law entries of @p m from @p text and refuse inadmissible
     * constants: @p entry names an entry in the messages, @p where (a
     * subsection and '/') the messages on several entries. The plane state
     * of @p m is given.
     */
    void
    read_law(LayerMaterial     &m,
             const EntryText   &text,
             const EntryText   &entry,
             const std::string &where)
    {
      const std::string law = text("Law");
      m.law                 = law == "orthotropic" ? MaterialLaw::orthotropic :
                              law == "anisotropic" ? MaterialLaw::anisotropic :
                                                     MaterialLaw::isotropic;
      const auto value      = [&](const std::string &name) {
        return to_double(text(name), entry(name));
      };
      m.youngs_modulus        = value("Young's modulus");
      m.poisson_ratio         = value("Poisson's ratio");
      OrthotropicConstants &o = m.orthotropic;
      o.E_1                   = value("E_1");
      o.E_2                   = value("E_2");
      o.E_3                   = value("E_3");
      o.nu_12                 = value("nu_12");
      o.nu_13                 = value("nu_13");
      o.nu_23                 = value("nu_23");
      o.G_12                  = value("G_12");
      m.orientation_angle     = value("Orientation angle");
      m.stiffness             = parse_stiffness(text("Stiffness"),
                                    entry("Stiffness"),
                                    m.law == MaterialLaw::anisotropic);
      m.thermal_expansion = parse_thermal_expansion(text("Thermal expansion"),
                                                    entry("Thermal expansion"),
                                                    m.law);
      if (m.law == MaterialLaw::orthotropic)
        check_orthotropic(o, m.plane_state, where);
      if (m.law == MaterialLaw::isotropic)
        {
          const bool stress = m.plane_state == PlaneState::plane_stress;
          AssertThrow(m.youngs_modulus > 0,
                      ExcMessage(entry("Young's modulus") +
                                 " must be > 0, got " +
                                 text("Young's modulus")));
          AssertThrow(
            m.poisson_ratio > -1 &&
              (m.poisson_ratio < 0.5 || (stress && m.poisson_ratio == 0.5)),
            ExcMessage(entry("Poisson's ratio") + " must lie in " +
                       (stress ? "(-1, 0.5] (plane stress)" : "(-1, 0.5)") +
                       ", got " + text("Poisson's ratio")));
        }
    }


    /// The subsections of the sides of a layer.
    const std::array<std::string, 2> side_subsections = {{"Omega-", "Omega+"}};


    /// The law entries that the subsection @p section (entered) gives, by
    /// name, each checked against the pattern of @p layer_section's entry.
    std::map<std::string, std::string>
    given_entries(const ParameterHandler &prm,
                  const std::string      &section,
                  const std::string      &layer_section)
    {
      std::map<std::string, std::string> given;
      for (const std::string &name : law_entries)
        {
          const std::string value = Utilities::trim(prm.get(name));
          if (value.empty())
            continue;
          const auto pattern = law_pattern(name);
          AssertThrow(pattern->match(value),
                      ExcMessage(section + "/" + name + ": '" + value +
                                 "' does not match the pattern " +
                                 pattern->description() + " of " +
                                 layer_section + "/" + name +
                                 " (empty: as the layer)"));
          given[name] = value;
        }
      return given;
    }


    /// Entries given by a subsection, with the subsection's path.
    struct GivenEntries
    {
      std::string                        section;
      std::map<std::string, std::string> values;
    };


    /**
     * The material @p layer with the entries of @p overrides, the last
     * first (a ply's over its side's), checked; none if they give none.
     * @p layer_text and @p layer_section: the layer's entries.
     */
    std::optional<LayerMaterial>
    overridden(const LayerMaterial             &layer,
               const EntryText                 &layer_text,
               const std::string               &layer_section,
               const std::vector<GivenEntries> &overrides)
    {
      const GivenEntries *innermost = nullptr;
      for (const GivenEntries &o : overrides)
        if (!o.values.empty())
          innermost = &o;
      if (innermost == nullptr)
        return {};
      const auto source = [&](const std::string &name) -> const GivenEntries * {
        for (auto o = overrides.rbegin(); o != overrides.rend(); ++o)
          if (o->values.count(name))
            return &*o;
        return nullptr;
      };
      LayerMaterial m = layer;
      read_law(
        m,
        [&](const std::string &name) {
          const GivenEntries *o = source(name);
          return o ? o->values.at(name) : layer_text(name);
        },
        [&](const std::string &name) {
          const GivenEntries *o = source(name);
          return (o ? o->section : layer_section) + "/" + name;
        },
        innermost->section + "/");
      return m;
    }


    /// The subsection @p name of law entries that override the layer's
    /// (a side or a ply) in @p where (entered).
    void
    declare_overrides(ParameterHandler  &prm,
                      const std::string &layer,
                      const std::string &name,
                      const std::string &where)
    {
      prm.enter_subsection(name);
      for (const std::string &entry : law_entries)
        prm.declare_entry(entry,
                          "",
                          Patterns::Anything(),
                          "The layer's material on " + where +
                            ": empty (the default) as " + layer + "/" + entry +
                            ", else a value of that entry for this part "
                            "alone. The plane state is the layer's.");
      prm.leave_subsection();
    }


    /// The subsections Omega-, Omega+ and Ply 1 ... Ply @p n_plies of the
    /// layer @p l (entered).
    void
    declare_parts(ParameterHandler  &prm,
                  const unsigned int l,
                  const unsigned int n_plies)
    {
      const std::string layer = "Materials/" + layer_subsection(l);
      declare_overrides(prm,
                        layer,
                        side_subsections[0],
                        "Omega- (below Sigma; a Gmsh scene's group Omega-)");
      declare_overrides(prm,
                        layer,
                        side_subsections[1],
                        "Omega+ (above Sigma; a Gmsh scene's group Omega+)");
      // (One ply is the layer itself: no subsection Ply 1.)
      for (unsigned int j = 0; n_plies > 1 && j < n_plies; ++j)
        declare_overrides(
          prm,
          layer,
          "Ply " + std::to_string(j + 1),
          "ply " + std::to_string(j + 1) +
            " (with Ply heights the band of the plane between the ply "
            "heights " +
            std::to_string(j) + " and " + std::to_string(j + 1) +
            ", counted from the bottom; with Ply groups the cells of group " +
            std::to_string(j + 1) +
            (j + 1 == n_plies ? ", the last: the cells in none of the groups" :
                                "") +
            "; its entries win over a side's)");
    }


  } // namespace


  void
  MaterialParameters::declare_parameters(ParameterHandler &prm,
                                         const PlyCounts  &n_plies)
  {
    prm.enter_subsection("Materials");
    const MaterialParameters defaults;
    prm.declare_entry("Number of layers",
                      "2",
                      Patterns::Integer(1, max_layers),
                      "2: the two glued layers of the paper; 1: layer 2 is "
                      "absent, a single elastic body with a through crack "
                      "(only the layer-1 subproblems and the crack and "
                      "gluing multipliers are built; Materials/Layer 2 and "
                      "Loads/Layer 2 are not used); N > 2: N layers stacked "
                      "through the thickness, each glued along Sigma to the "
                      "one below it on both sides (layer 1 carries the "
                      "crack's contact; the subsections Layer 3 ... Layer N "
                      "of Materials and Loads appear, with layer 2's "
                      "defaults) [-].");
    for (unsigned int l = 0; l < n_plies.size(); ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        prm.declare_entry(
          "Law",
          "isotropic",
          Patterns::Selection("isotropic|orthotropic|anisotropic"),
          "Hooke's law of the layer: isotropic (Young's modulus, Poisson's "
          "ratio), orthotropic (E_1, E_2, E_3, nu_12, nu_13, nu_23, G_12 in "
          "the material axes, turned by the orientation angle) or anisotropic "
          "(the in-plane stiffness as given) [-].");
        prm.declare_entry(
          "Plane state",
          "plane strain",
          Patterns::Selection("plane strain|plane stress"),
          "The out-of-plane assumption of isotropic and orthotropic layers: "
          "plane strain (eps_zz = 0) or plane stress (sigma_zz = 0) [-]. An "
          "anisotropic layer ignores it: its stiffness is the plane law itself "
          "(sigma_zz not defined).");
        prm.declare_entry("Young's modulus",
                          Patterns::Tools::to_string(
                            defaults.layer[std::min(l, 1u)].youngs_modulus),
                          Patterns::Double(0),
                          "Law = isotropic: Young's modulus E of the layer "
                          "[stress, e.g. GPa; tractions use the same unit].");
        prm.declare_entry("Poisson's ratio",
                          Patterns::Tools::to_string(
                            defaults.layer[std::min(l, 1u)].poisson_ratio),
                          Patterns::Double(-1, 0.5),
                          "Law = isotropic: Poisson's ratio nu of the layer "
                          "[-], in (-1, 0.5) in plane strain, (-1, 0.5] in "
                          "plane stress.");
        declare_orthotropic(prm, defaults.layer[std::min(l, 1u)]);
        prm.declare_entry(
          "Stiffness",
          "250, 100, 0, 250, 0, 75",
          Patterns::List(Patterns::Double(), 6, 6, ","),
          "Law = anisotropic: C11, C12, C16, C22, C26, C66, the symmetric "
          "positive definite matrix of (s11, s22, s12) against (e11, e22, "
          "2 e12) in the x-y frame [stress, the unit of Young's modulus]; "
          "the default is isotropic (lambda = 100, mu = 75).");
        prm.declare_entry(
          "Thermal expansion",
          "0",
          Patterns::Anything(),
          "The coefficient of thermal expansion alpha [1/K], the thermal "
          "strain alpha dT under Loads/Temperature change: one number "
          "(isotropic; for the other laws alpha I as well), or for Law = "
          "orthotropic 'alpha_1, alpha_2, alpha_3' in the material axes "
          "(turned by the orientation angle; alpha_3 along z), for Law = "
          "anisotropic 'alpha_11, alpha_22, alpha_12', the plane eigenstrain "
          "per kelvin in the x-y frame as it enters the plane law (sigma_zz "
          "not defined).");
        prm.declare_entry(
          "Ply heights",
          "",
          Patterns::Anything(),
          "The plies of the layer: the heights y_1 < y_2 < ... [length] at "
          "which its material changes, a comma-separated list (empty, the "
          "default: one ply, the layer itself). Ply j (from the bottom) is "
          "the band y_(j-1) < y < y_j of the plane in every region it "
          "crosses; with n heights the layer has the subsections Ply 1 ... "
          "Ply n+1, which take the law entries of the layer (empty: as the "
          "side) and override the layer's and the side's. The "
          "rectangle scenes fit a row of mesh vertices to each height inside "
          "Omega; Gmsh scenes and mesh files are refused.");
        prm.declare_entry(
          "Ply groups",
          "",
          Patterns::Anything(),
          "The plies of the layer in a Gmsh scene: the names of physical "
          "surfaces of Geometry/Gmsh file, a comma-separated list (empty, "
          "the default: one ply, the layer itself). Each surface of a group "
          "also lies in Omega- or Omega+, and a cell in one group at most; "
          "with n groups the layer has the subsections Ply 1 ... Ply n (the "
          "groups in this order) and Ply n+1 (the cells in none of them), "
          "which take the law entries of the layer (empty: as the side) and "
          "override the layer's and the side's. Not with Ply heights.");
        declare_parts(prm, l, n_plies[l]);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    n_layers                   = prm.get_integer("Number of layers");
    const unsigned int n_slots = Layout::n_slots(n_layers);
    layer.resize(n_slots, layer.back());
    side.resize(n_slots);
    ply_heights.resize(n_slots);
    ply_groups.resize(n_slots);
    ply.resize(n_slots);
    for (unsigned int l = 0; l < n_slots; ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        const std::string where = "Materials/" + layer_subsection(l) + "/";
        LayerMaterial    &m     = layer[l];
        m.plane_state           = prm.get("Plane state") == "plane stress" ?
                                    PlaneState::plane_stress :
                                    PlaneState::plane_strain;
        std::map<std::string, std::string> texts;
        for (const std::string &name : law_entries)
          texts[name] = prm.get(name);
        const EntryText text = [&](const std::string &name) {
          return texts.at(name);
        };
        read_law(
          m,
          text,
          [&](const std::string &name) { return where + name; },
          where);
        const std::string layer_section = "Materials/" + layer_subsection(l);
        ply_heights[l] =
          MaterialParameters::parse_ply_heights(prm.get("Ply heights"),
                                                where + "Ply heights");
        ply_groups[l] =
          MaterialParameters::parse_ply_groups(prm.get("Ply groups"),
                                               where + "Ply groups");
        AssertThrow(ply_heights[l].empty() || ply_groups[l].empty(),
                    ExcMessage(where + "Ply heights and " + where +
                               "Ply groups: give one of them (bands of the "
                               "rectangle scene, or Gmsh physical surfaces), "
                               "not both"));
        const unsigned int n_layer_plies =
          std::max(ply_heights[l].size(), ply_groups[l].size()) + 1;
        std::vector<GivenEntries> plies;
        for (unsigned int j = 0; n_layer_plies > 1 && j < n_layer_plies; ++j)
          {
            const std::string name = "Ply " + std::to_string(j + 1);
            prm.enter_subsection(name);
            plies.push_back(
              {layer_section + "/" + name,
               given_entries(prm, layer_section + "/" + name, layer_section)});
            prm.leave_subsection();
          }
        for (unsigned int s = 0; s < 2; ++s)
          {
            prm.enter_subsection(side_subsections[s]);
            const GivenEntries on_side = {
              layer_section + "/" + side_subsections[s],
              given_entries(prm,
                            layer_section + "/" + side_subsections[s],
                            layer_section)};
            prm.leave_subsection();
            side[l][s] = overridden(m, text, layer_section, {on_side});
            ply[l][s].clear();
            for (const GivenEntries &p : plies)
              ply[l][s].push_back(
                p.values.empty() ?
                  std::nullopt :
                  overridden(m, text, layer_section, {on_side, p}));
          }
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  const std::vector<std::string> &
  MaterialParameters::law_entry_names()
  {
    static const std::vector<std::string> names = {"Law",
                                                   "Young's modulus",
                                                   "Poisson's ratio",
                                                   "E_1",
                                                   "E_2",
                                                   "E_3",
                                                   "nu_12",
                                                   "nu_13",
                                                   "nu_23",
                                                   "G_12",
                                                   "Orientation angle",
                                                   "Stiffness",
                                                   "Thermal expansion"};
    return names;
  }


  bool
  MaterialParameters::law_reads(const std::string &law,
                                const std::string &plane_state,
                                const std::string &name)
  {
    if (name == "Law" || name == "Thermal expansion")
      return true;
    if (law == "anisotropic")
      return name == "Stiffness";
    if (law == "orthotropic")
      return name == "E_1" || name == "E_2" || name == "nu_12" ||
             name == "G_12" || name == "Orientation angle" ||
             name == "Plane state" ||
             (plane_state != "plane stress" &&
              (name == "E_3" || name == "nu_13" || name == "nu_23"));
    return name == "Young's modulus" || name == "Poisson's ratio" ||
           name == "Plane state";
  }
} // namespace bilayer
