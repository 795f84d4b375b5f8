#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/cohesive_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


  void
  CohesiveParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cohesive");
    prm.declare_entry(
      "Law",
      "none",
      Patterns::Selection("none|bilinear|exponential"),
      "The traction-separation law on the pieces Zone of the interface "
      "Interface (docs/cohesive.md): none (glue and crack only); bilinear "
      "(Penalty stiffness up to the strength, linear softening to zero); "
      "exponential (t = k0 delta exp(-delta / delta_c), k0 = e^2 "
      "sigma_max^2 / G_Ic). A run with a law traces the softening curve "
      "step by step (Control) on the meshes of the last cycle.");
    prm.declare_entry("Interface",
                      "1",
                      Patterns::Integer(1),
                      "The interface whose pieces carry the law (1 is "
                      "Sigma).");
    prm.declare_entry(
      "Zone",
      "",
      Patterns::Anything(),
      "The pieces of the interface that carry the law: 's_start, s_end' "
      "intervals of the coordinate along it, separated by ';', ending at "
      "mesh vertices; they join the crack (their nodes start intact), so "
      "they must obey the rules of crack pieces (a piece may not reach a "
      "clamped side).");
    prm.declare_entry("Normal strength",
                      "1",
                      Patterns::Double(0),
                      "sigma_max > 0 [stress]: the peak of the normal "
                      "traction in pure mode I.");
    prm.declare_entry("Shear strength",
                      "",
                      Patterns::Anything(),
                      "tau_max > 0 [stress]: the peak of the shear traction "
                      "in pure mode II (bilinear law); empty: Normal "
                      "strength. The exponential law's follows from k0 and "
                      "Mode II toughness.");
    prm.declare_entry("Mode I toughness",
                      "1",
                      Patterns::Double(0),
                      "G_Ic > 0 [energy / area]: the area under the law in "
                      "pure mode I.");
    prm.declare_entry("Mode II toughness",
                      "",
                      Patterns::Anything(),
                      "G_IIc > 0 [energy / area]; empty: Mode I toughness.");
    prm.declare_entry(
      "Mixed-mode criterion",
      "Benzeggagh-Kenane",
      Patterns::Selection("Benzeggagh-Kenane|power law"),
      "G_c at the mode mixity B = G_II / G: Benzeggagh-Kenane G_Ic + "
      "(G_IIc - G_Ic) B^eta (with its onset sqrt(d_n0^2 + (d_t0^2 - "
      "d_n0^2) B^eta)); power law ((1 - B) G / G_Ic)^a + (B G / G_IIc)^a "
      "= 1 (with the quadratic onset criterion).");
    prm.declare_entry("Mixed-mode exponent",
                      "2",
                      Patterns::Double(0),
                      "eta of Benzeggagh-Kenane or a of the power law, > 0.");
    prm.declare_entry("Control",
                      "load factor",
                      Patterns::Selection("load factor|separation|dissipation"),
                      "What each step prescribes: load factor (the factors "
                      "of Loads/Load factor: load or displacement control; "
                      "stops with a message at a limit point); dissipation "
                      "(path following: the zone's dissipated energy grows "
                      "by Dissipation increment per step; passes limit "
                      "points and snap-back, node by node); separation "
                      "(path following: the largest growth of an equivalent "
                      "separation in the zone beyond its past maximum is "
                      "Separation increment; passes the turning points of "
                      "the load, not a node's own). The path-following "
                      "controls need proportional loads; their first step "
                      "ends at the elastic limit.");
    prm.declare_entry("Separation increment",
                      "0",
                      Patterns::Double(0),
                      "Control = separation: the growth of the largest "
                      "separation per step [length], > 0.");
    prm.declare_entry("Dissipation increment",
                      "0",
                      Patterns::Double(0),
                      "Control = dissipation: the growth of the dissipated "
                      "energy per step [energy / area x length: per unit "
                      "width], > 0; G_Ic times the crack advance wanted per "
                      "step.");
    prm.declare_entry("Steps",
                      "100",
                      Patterns::Integer(1),
                      "Control = separation or dissipation: the number of "
                      "steps (the run "
                      "ends earlier when the whole zone is a crack).");
    prm.declare_entry("Damage tolerance",
                      "1e-6",
                      Patterns::Double(0),
                      "The secant iteration of a step ends when no damage "
                      "changes by more than this, in (0, 0.1].");
    prm.declare_entry("Maximum iterations",
                      "200",
                      Patterns::Integer(1),
                      "Secant iterations per step before the step fails.");
    prm.declare_entry(
      "Method",
      "newton",
      Patterns::Selection("newton|secant"),
      "How a step's state is found. newton: a semismooth Newton method on "
      "the interface alone (the jumps are affine in the multipliers and "
      "the load factor: a dense matrix built once from the subproblems' "
      "factorisations, one solve per multiplier component) gives the "
      "first iterate, which the secant iteration checks with the outer "
      "solver and carries on from where it is not the solution; secant: "
      "the secant iteration alone (docs/cohesive.md). Friction on the "
      "interfaces, or more than 6000 multiplier components, take the "
      "secant iteration.");
    prm.enter_subsection("Bilinear");
    prm.declare_entry("Penalty stiffness",
                      "1e4",
                      Patterns::Double(0),
                      "k0 > 0 [stress / length]: the initial stiffness of "
                      "the bilinear law (docs/cohesive.md: large against "
                      "E / h, 1e2 to 1e4 E / h).");
    prm.leave_subsection();
    prm.leave_subsection();
  }


  namespace
  {
    [[noreturn]] void
    refuse(const std::string &entry, const std::string &range)
    {
      AssertThrow(false, ExcMessage("Cohesive/" + entry + " must be " + range));
      std::abort();
    }


    double
    positive(const ParameterHandler &prm,
             const std::string      &name,
             const std::string      &text)
    {
      const double x = to_double(text, "Cohesive/" + name);
      if (!(x > 0) || !std::isfinite(x))
        refuse(name, "a number > 0, got '" + text + "'");
      (void)prm;
      return x;
    }
  } // namespace


  void
  CohesiveParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cohesive");
    const std::string l = prm.get("Law");
    law.type            = l == "bilinear"    ? CohesiveLawType::bilinear :
                          l == "exponential" ? CohesiveLawType::exponential :
                                               CohesiveLawType::none;
    interface           = prm.get_integer("Interface") - 1;
    zone.clear();
    for (const std::string &piece :
         Utilities::split_string_list(prm.get("Zone"), ';'))
      {
        const auto ends = Utilities::split_string_list(piece, ',');
        if (ends.size() != 2)
          refuse("Zone",
                 "'s_start, s_end' pieces separated by ';', got '" + piece +
                   "'");
        const double a = to_double(ends[0], "Cohesive/Zone"),
                     b = to_double(ends[1], "Cohesive/Zone");
        if (!(a < b))
          refuse("Zone", "pieces with s_start < s_end, got '" + piece + "'");
        if (!zone.empty() && !(a >= zone.back()[1]))
          refuse("Zone",
                 "pieces ordered by s that do not overlap, got '" + piece +
                   "' after '" + number(zone.back()[0]) + ", " +
                   number(zone.back()[1]) + "'");
        zone.push_back({{a, b}});
      }
    law.normal_strength =
      positive(prm, "Normal strength", prm.get("Normal strength"));
    const std::string shear = prm.get("Shear strength");
    law.shear_strength      = shear.empty() ? law.normal_strength :
                                              positive(prm, "Shear strength", shear);
    law.mode_i_toughness =
      positive(prm, "Mode I toughness", prm.get("Mode I toughness"));
    const std::string g2  = prm.get("Mode II toughness");
    law.mode_ii_toughness = g2.empty() ? law.mode_i_toughness :
                                         positive(prm, "Mode II toughness", g2);
    law.criterion         = prm.get("Mixed-mode criterion") == "power law" ?
                              CohesiveCriterion::power_law :
                              CohesiveCriterion::benzeggagh_kenane;
    law.exponent =
      positive(prm, "Mixed-mode exponent", prm.get("Mixed-mode exponent"));
    const std::string c = prm.get("Control");
    control             = c == "separation"  ? CohesiveControl::separation :
                          c == "dissipation" ? CohesiveControl::dissipation :
                                               CohesiveControl::load_factor;
    dissipation_increment =
      get_double(prm, "Cohesive", "Dissipation increment");
    separation_increment = get_double(prm, "Cohesive", "Separation increment");
    steps                = prm.get_integer("Steps");
    damage_tolerance     = get_double(prm, "Cohesive", "Damage tolerance");
    if (!(damage_tolerance > 0 && damage_tolerance <= 0.1))
      refuse("Damage tolerance",
             "in (0, 0.1], got " + number(damage_tolerance));
    maximum_iterations = prm.get_integer("Maximum iterations");
    newton             = prm.get("Method") == "newton";
    prm.enter_subsection("Bilinear");
    law.penalty_stiffness =
      positive(prm, "Bilinear/Penalty stiffness", prm.get("Penalty stiffness"));
    prm.leave_subsection();
    prm.leave_subsection();
    if (active() && zone.empty())
      refuse("Zone",
             "at least one piece 's_start, s_end' with Cohesive/Law = " + l);
    if (active() && control == CohesiveControl::separation &&
        !(separation_increment > 0))
      refuse("Separation increment",
             "> 0 with Cohesive/Control = separation, got " +
               number(separation_increment));
    if (active() && control == CohesiveControl::dissipation &&
        !(dissipation_increment > 0))
      refuse("Dissipation increment",
             "> 0 with Cohesive/Control = dissipation, got " +
               number(dissipation_increment));
    if (law.type == CohesiveLawType::bilinear &&
        !(law.normal_strength / law.penalty_stiffness > 0))
      refuse("Bilinear/Penalty stiffness",
             "small enough for a positive onset separation");
  }
} // namespace bilayer
