#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/expressions.h>
#include <bilayer/parameters/fracture_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

#include <cmath>
#include <sstream>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


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
    prm.declare_entry(
      "Mode split length",
      "0",
      Patterns::Double(0),
      "Length Delta [length] of the crack-closure integrals that split G "
      "into its opening and sliding parts G = G_I + G_II at every tip "
      "(docs/fracture.md, section 7): the ratio of the closure works of "
      "the traction ahead of the tip against the opening and the sliding "
      "of layer 1 behind it, over Delta, applied to G. 0 chooses 8 times "
      "the size of the cells at the tip, at most half the distance to the "
      "nearest obstacle; with 0 the split is not reported (NaN) at a tip "
      "between different materials on the two sides of Sigma, where it "
      "depends on the length: a given Delta reports it at that reference "
      "length. A given Delta must not exceed the distance to the nearest "
      "obstacle of the tip (else NaN there).");
    prm.declare_entry(
      "Goal-oriented estimate",
      "false",
      Patterns::Bool(),
      "Whether to compute the dual-weighted residual estimates of G at "
      "every tip and of the energy (docs/fracture.md, section 11): one dual "
      "problem per tip, solved with the factorisations of the state (its "
      "active set held), weighted by a patchwise reconstruction of degree "
      "p + 1. dG then is the larger of the DWR estimate and the estimate "
      "from the cycles and the support radius. On by itself with a "
      "Mesh/Refinement goal other than estimator.");
    prm.declare_entry(
      "Stress intensity factors",
      "true",
      Patterns::Bool(),
      "Whether to compute the stress intensity factors K_I, K_II of every "
      "tip where G is computed, by the interaction integral with the "
      "near-tip field of the materials at the tip (docs/fracture.md, "
      "section 10): at tips on straight interfaces between isotropic "
      "layers (one Poisson's ratio per side) without friction; elsewhere "
      "a note says why not. Its cost is that of a second domain integral "
      "per tip.");
    prm.declare_entry(
      "Reference length",
      "0",
      Patterns::Double(0),
      "Reference length L [length] of the stress intensity factors K_I, "
      "K_II and their phase angle at a tip between different materials "
      "(docs/fracture.md, section 10): the complex K of the oscillating "
      "field is reported as K L^(i eps) = K_I + i K_II, whose phase "
      "atan2(K_II, K_I) moves by eps ln(L2 / L1) from L1 to L2. 0: not set; "
      "then K_I, K_II and the phase angle are NaN at such a tip (|K|, eps "
      "and G from K are reported). A tip between equal materials (eps = 0) "
      "has one K for every L.");
    prm.declare_entry(
      "Crack growth",
      "none",
      Patterns::Selection("none|sweep|quasi-static"),
      "none: the mesh cycles of the study. quasi-static: Griffith growth "
      "along Sigma on the meshes of the last cycle (Mesh/Refinement = global) "
      "under the load factors of Loads/Load factor: at each load the tips "
      "whose criterion (Mixed-mode law) reaches 1 advance by Growth "
      "increment vertices of Sigma, irreversibly, and the state is solved "
      "again, until every criterion is below 1; growth at a fixed load "
      "beyond the first step is reported as unstable. sweep: the tips "
      "advance step by step at the (single) load factor whatever their "
      "criterion, until they stop: G, its mode split and the critical load "
      "of every crack length. The subproblems are factorised once; each "
      "step rebuilds only the interface (docs/fracture.md, section 9).");
    prm.declare_entry("Toughness",
                      "1",
                      Patterns::Anything(),
                      "G_c [energy / area]: the critical energy release "
                      "rate, a number or an expression of x, y and s (the "
                      "parameter along Sigma), > 0 on Sigma; the mode I "
                      "toughness G_Ic of the mode-dependent laws.");
    prm.declare_entry("Mode II toughness",
                      "",
                      Patterns::Anything(),
                      "G_IIc [energy / area] of Mixed-mode law = power law "
                      "or Benzeggagh-Kenane: a number or an expression of x, "
                      "y and s, > 0 on Sigma; empty: equal to Toughness.");
    prm.declare_entry(
      "Mixed-mode law",
      "mode independent",
      Patterns::Selection("mode independent|power law|Benzeggagh-Kenane"),
      "When a tip grows: mode independent G >= G_c; power law (G_I / "
      "G_Ic)^a + (G_II / G_IIc)^a >= 1; Benzeggagh-Kenane G >= G_Ic + "
      "(G_IIc - G_Ic) (G_II / G)^eta; a and eta = Mixed-mode exponent. The "
      "mode-dependent laws need the mode split at the tip.");
    prm.declare_entry(
      "Mode mix",
      "closure",
      Patterns::Selection("closure|stress intensity factors"),
      "The G_I, G_II the mode-dependent laws read: closure (the "
      "crack-closure split over Mode split length, docs/fracture.md §7) or "
      "stress intensity factors (G_I = G cos^2 psi, G_II = G sin^2 psi, "
      "psi = atan2(K_II, K_I) at Reference length: the phase angle of "
      "interface fracture; needs Stress intensity factors = true, and a "
      "Reference length at a tip between different materials).");
    prm.declare_entry("Mixed-mode exponent",
                      "1",
                      Patterns::Double(0),
                      "The exponent a of the power law or eta of the "
                      "Benzeggagh-Kenane law [-], > 0.");
    prm.declare_entry("Growth increment",
                      "1",
                      Patterns::Integer(1, 1000000),
                      "The vertices of Sigma (of both meshes) a growing tip "
                      "advances per growth step, 1 to 1000000 [-].");
    prm.declare_entry("Growing tips",
                      "all",
                      Patterns::Anything(),
                      "all, or a ','-separated list of the numbers 1, 2, ... "
                      "of the tips that may grow (the crack's tips at the "
                      "start, ordered by s); the others stay.");
    prm.declare_entry(
      "Exact onsets",
      "true",
      Patterns::Bool(),
      "true: under proportional loading (no temperature change or "
      "eigenstrain, frictionless faces) G(lambda) = lambda^2 G(1), and the "
      "critical load of each crack is inserted as a load step between the "
      "load factors, so that growth starts at its exact onset; false, or a "
      "preload: the load factors alone (the onsets are bracketed by them).");
    prm.declare_entry("Maximum growth steps",
                      "1000",
                      Patterns::Integer(1, 1000000),
                      "The most states (load and growth steps) of a "
                      "growing crack, 1 to 1000000; the run fails when the "
                      "crack still grows after that many.");
    prm.leave_subsection();
  }


  void
  FractureParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fracture");
    energy_release_rate = prm.get_bool("Energy release rate");
    stress_intensity    = prm.get_bool("Stress intensity factors");
    goal_oriented       = prm.get_bool("Goal-oriented estimate");
    support_radius      = get_double(prm, "Fracture", "Support radius");
    AssertThrow(std::isfinite(support_radius) && support_radius >= 0,
                ExcMessage("Fracture/Support radius must be >= 0 (0: "
                           "automatic), got " +
                           prm.get("Support radius")));
    reference_length = get_double(prm, "Fracture", "Reference length");
    AssertThrow(std::isfinite(reference_length) && reference_length >= 0,
                ExcMessage("Fracture/Reference length must be >= 0 (0: not "
                           "set), got " +
                           prm.get("Reference length")));
    mode_split_length = get_double(prm, "Fracture", "Mode split length");
    AssertThrow(std::isfinite(mode_split_length) && mode_split_length >= 0,
                ExcMessage("Fracture/Mode split length must be >= 0 (0: "
                           "automatic), got " +
                           prm.get("Mode split length")));
    const std::string mode = prm.get("Crack growth");
    growth                 = mode == "sweep"        ? CrackGrowth::sweep :
                             mode == "quasi-static" ? CrackGrowth::quasi_static :
                                                      CrackGrowth::none;
    toughness              = prm.get("Toughness");
    mode_ii_toughness      = prm.get("Mode II toughness");
    const std::string law  = prm.get("Mixed-mode law");
    mixed_mode_law         = law == "power law" ? MixedModeLaw::power_law :
                             law == "Benzeggagh-Kenane" ?
                                                  MixedModeLaw::benzeggagh_kenane :
                                                  MixedModeLaw::mode_independent;
    mixed_mode_exponent    = get_double(prm, "Fracture", "Mixed-mode exponent");
    mode_mix_from_k        = prm.get("Mode mix") == "stress intensity factors";
    AssertThrow(!mode_mix_from_k || stress_intensity,
                ExcMessage("Fracture/Mode mix = stress intensity factors "
                           "needs Fracture/Stress intensity factors = true"));
    AssertThrow(std::isfinite(mixed_mode_exponent) && mixed_mode_exponent > 0,
                ExcMessage("Fracture/Mixed-mode exponent must be > 0, got " +
                           prm.get("Mixed-mode exponent")));
    growth_increment     = prm.get_integer("Growth increment");
    exact_onsets         = prm.get_bool("Exact onsets");
    maximum_growth_steps = prm.get_integer("Maximum growth steps");
    growing_tips.clear();
    const std::string tips = Utilities::trim(prm.get("Growing tips"));
    if (tips != "all")
      for (const std::string &item : Utilities::split_string_list(tips, ','))
        {
          const std::string t = Utilities::trim(item);
          const bool number = !t.empty() && t.find_first_not_of("0123456789") ==
                                              std::string::npos;
          AssertThrow(number && t.size() < 9 && std::stoul(t) >= 1,
                      ExcMessage("Fracture/Growing tips must be all or a "
                                 "','-separated list of tip numbers >= 1, "
                                 "got " +
                                 tips));
          growing_tips.push_back(std::stoul(t));
        }
    toughness_function.reset();
    mode_ii_function.reset();
    if (growth != CrackGrowth::none)
      {
        toughness_function =
          expressions::curve_function(toughness, {}, "Fracture/Toughness");
        if (!Utilities::trim(mode_ii_toughness).empty())
          mode_ii_function =
            expressions::curve_function(mode_ii_toughness,
                                        {},
                                        "Fracture/Mode II toughness");
      }
    prm.leave_subsection();
  }


  namespace
  {
    double
    positive_toughness(const FunctionParser<3> &f,
                       const Point<2>          &p,
                       const double             s,
                       const std::string       &entry)
    {
      const double g = f.value(Point<3>(p[0], p[1], s));
      if (!(std::isfinite(g) && g > 0))
        {
          std::ostringstream msg;
          msg << "Fracture/" << entry
              << " must be finite and > 0 on Sigma, got " << g
              << " at (x, y) = (" << p[0] << ", " << p[1] << ")";
          AssertThrow(false, ExcMessage(msg.str()));
        }
      return g;
    }
  } // namespace


  double
  FractureParameters::toughness_at(const Point<2> &p, const double s) const
  {
    AssertThrow(toughness_function,
                ExcMessage("Fracture/Toughness is read with Crack growth"));
    return positive_toughness(*toughness_function, p, s, "Toughness");
  }


  double
  FractureParameters::mode_ii_toughness_at(const Point<2> &p,
                                           const double    s) const
  {
    if (!mode_ii_function)
      return toughness_at(p, s);
    return positive_toughness(*mode_ii_function, p, s, "Mode II toughness");
  }
} // namespace bilayer
