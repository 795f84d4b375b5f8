// The growth criteria of Fracture/Mixed-mode law (growth_criterion(),
// docs/fracture.md section 9) against their formulas, and the critical load
// factor: under proportional loading G, G_I and G_II scale with lambda^2,
// so f at the critical load lambda_c = lambda f^(-1/d) (computed from the
// state at lambda) is 1, with d = 2 for the mode-independent and the
// Benzeggagh-Kenane laws and d = 2 a for the power law.

#include <bilayer/postprocess/growth_law.h>

#include <cmath>
#include <iostream>
#include <limits>

#include "verdict.h"

using namespace bilayer;

namespace
{
  EnergyReleaseRate
  release(const double G_I, const double G_II)
  {
    EnergyReleaseRate g;
    g.G    = G_I + G_II;
    g.G_I  = G_I;
    g.G_II = G_II;
    return g;
  }

  /// The same tip at load factor lambda' = s lambda (every part times s^2).
  EnergyReleaseRate
  scaled(const EnergyReleaseRate &g, const double s)
  {
    return release(g.G_I * s * s, g.G_II * s * s);
  }

  bool
  near(const double a, const double b)
  {
    return std::abs(a - b) <= 1e-13 * std::max(1., std::abs(b));
  }

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << yes(ok) << std::endl;
  }
} // namespace

int
main()
{
  const double            G_Ic = 0.3, G_IIc = 1.2, lambda = 0.7;
  const auto              mi = MixedModeLaw::mode_independent;
  const auto              pl = MixedModeLaw::power_law;
  const auto              bk = MixedModeLaw::benzeggagh_kenane;
  const EnergyReleaseRate g  = release(0.05, 0.11);

  // The formulas.
  check("mode independent: f = G / G_c",
        near(growth_criterion(mi, 1, g, G_Ic, G_IIc).value, 0.16 / G_Ic));
  for (const double a : {1., 2., 0.5})
    check("power law a = " + std::to_string(a) +
            ": f = (G_I/G_Ic)^a + (G_II/G_IIc)^a",
          near(growth_criterion(pl, a, g, G_Ic, G_IIc).value,
               std::pow(0.05 / G_Ic, a) + std::pow(0.11 / G_IIc, a)));
  for (const double eta : {1., 2.3})
    check("Benzeggagh-Kenane eta = " + std::to_string(eta) +
            ": f = G / (G_Ic + (G_IIc - G_Ic) (G_II/G)^eta)",
          near(growth_criterion(bk, eta, g, G_Ic, G_IIc).value,
               0.16 / (G_Ic + (G_IIc - G_Ic) * std::pow(0.11 / 0.16, eta))));
  check("BK and the power law a = 1 in pure mode I: G / G_Ic",
        near(growth_criterion(bk, 2, release(0.2, 0), G_Ic, G_IIc).value,
             0.2 / G_Ic) &&
          near(growth_criterion(pl, 1, release(0.2, 0), G_Ic, G_IIc).value,
               0.2 / G_Ic));
  check("BK and the power law a = 1 in pure mode II: G / G_IIc",
        near(growth_criterion(bk, 2, release(0, 0.2), G_Ic, G_IIc).value,
             0.2 / G_IIc) &&
          near(growth_criterion(pl, 1, release(0, 0.2), G_Ic, G_IIc).value,
               0.2 / G_IIc));
  check("equal toughnesses: every law is G / G_c (power law a = 1)",
        near(growth_criterion(bk, 1.7, g, G_Ic, G_Ic).value, 0.16 / G_Ic) &&
          near(growth_criterion(pl, 1, g, G_Ic, G_Ic).value, 0.16 / G_Ic));

  // The critical load: f = 1 at lambda_c, from any state.
  bool degree = true, one = true;
  for (const auto law : {mi, pl, bk})
    for (const double exponent : {0.5, 1., 2., 3.})
      {
        const GrowthCriterion f =
          growth_criterion(law, exponent, g, G_Ic, G_IIc);
        degree = degree && near(f.degree, law == pl ? 2 * exponent : 2.);
        const double          lambda_c = critical_load_factor(f, lambda);
        const GrowthCriterion at_c     = growth_criterion(
          law, exponent, scaled(g, lambda_c / lambda), G_Ic, G_IIc);
        one = one && std::abs(at_c.value - 1) < 1e-13;
        // The same lambda_c from a state at another load.
        const GrowthCriterion other =
          growth_criterion(law, exponent, scaled(g, 3.1), G_Ic, G_IIc);
        one = one && near(critical_load_factor(other, 3.1 * lambda), lambda_c);
      }
  check("degree of f in lambda: 2, or 2 a for the power law", degree);
  check("f = 1 at lambda_c = lambda f^(-1/d), from any load", one);

  // Nothing released; the split not defined.
  const GrowthCriterion closed =
    growth_criterion(pl, 2, release(-1e-16, 0), G_Ic, G_IIc);
  check("G <= 0: f = 0 and no critical load",
        closed.value == 0 && std::isinf(critical_load_factor(closed, lambda)));
  EnergyReleaseRate nan = release(0.05, 0.11);
  nan.G_I = nan.G_II  = std::numeric_limits<double>::quiet_NaN();
  nan.mode_split_note = "a bimaterial tip";
  check("split not defined: the mode-dependent laws say why",
        !growth_criterion(pl, 1, nan, G_Ic, G_IIc).undefined.empty() &&
          !growth_criterion(bk, 1, nan, G_Ic, G_IIc).undefined.empty());
  check("split not defined: the mode-independent law needs none",
        growth_criterion(mi, 1, nan, G_Ic, G_IIc).undefined.empty() &&
          near(growth_criterion(mi, 1, nan, G_Ic, G_IIc).value, 0.16 / G_Ic));
}
