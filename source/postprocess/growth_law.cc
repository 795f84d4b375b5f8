#include <bilayer/postprocess/growth_law.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bilayer
{
  GrowthCriterion
  growth_criterion(const MixedModeLaw       law,
                   const double             exponent,
                   const EnergyReleaseRate &g,
                   const double             G_c,
                   const double             G_IIc)
  {
    GrowthCriterion f;
    const double    G = std::max(g.G, 0.);
    if (law == MixedModeLaw::mode_independent)
      {
        f.value = G / G_c;
        return f;
      }
    if (G == 0)
      return f;
    if (!(std::isfinite(g.G_I) && std::isfinite(g.G_II)))
      {
        f.undefined =
          "the mode split is not defined at the tip" +
          (g.mode_split_note.empty() ? std::string() :
                                       " (" + g.mode_split_note + ")");
        return f;
      }
    const double G_I = std::max(g.G_I, 0.), G_II = std::max(g.G_II, 0.);
    if (law == MixedModeLaw::power_law)
      {
        f.value =
          std::pow(G_I / G_c, exponent) + std::pow(G_II / G_IIc, exponent);
        f.degree = 2 * exponent;
        return f;
      }
    // Benzeggagh-Kenane: the toughness of the mode mix G_II / G.
    const double mix = std::min(G_II / G, 1.);
    f.value          = G / (G_c + (G_IIc - G_c) * std::pow(mix, exponent));
    return f;
  }


  double
  critical_load_factor(const GrowthCriterion &f, const double lambda)
  {
    if (!(f.value > 0))
      return std::numeric_limits<double>::infinity();
    return lambda * std::pow(f.value, -1. / f.degree);
  }
} // namespace bilayer
