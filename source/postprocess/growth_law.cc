#include <bilayer/postprocess/growth_law.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bilayer
{
  namespace
  {
    constexpr double minus_infinity = -std::numeric_limits<double>::infinity();

    /// ln(e^a + e^b) without overflow (either may be -infinity).
    double
    log_sum_exp(const double a, const double b)
    {
      const double high = std::max(a, b), low = std::min(a, b);
      if (high == minus_infinity)
        return minus_infinity;
      return high + std::log1p(std::exp(low - high));
    }

    /// ln(x), -infinity at 0.
    double
    log_of(const double x)
    {
      return x > 0 ? std::log(x) : minus_infinity;
    }

    /// f from ln f: the largest double where it overflows.
    GrowthCriterion
    from_log(const double log_value, const double degree)
    {
      GrowthCriterion f;
      f.log_value = log_value;
      f.value =
        std::min(std::exp(log_value), std::numeric_limits<double>::max());
      f.degree = degree;
      return f;
    }
  } // namespace


  GrowthCriterion
  growth_criterion(const MixedModeLaw       law,
                   const double             exponent,
                   const EnergyReleaseRate &g,
                   const double             G_c,
                   const double             G_IIc,
                   const double             resolution)
  {
    GrowthCriterion f;
    const double    G = std::max(g.G, 0.);
    if (law == MixedModeLaw::mode_independent)
      return from_log(log_of(G) - std::log(G_c), 2);
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
    // A mode's part at or below the resolution of the split is round-off:
    // zero for the criterion (a small exponent would make it count).
    const auto resolved = [&](const double part) {
      return part > resolution * G ? part : 0.;
    };
    const double G_I  = resolved(std::max(g.G_I, 0.)),
                 G_II = resolved(std::max(g.G_II, 0.));
    if (law == MixedModeLaw::power_law)
      {
        // ln f = ln((G_I / G_Ic)^a + (G_II / G_IIc)^a), in logs: no
        // overflow for a large a, no 0^a issue for a small one.
        const double t_I =
          G_I > 0 ? exponent * (std::log(G_I) - std::log(G_c)) : minus_infinity;
        const double t_II = G_II > 0 ?
                              exponent * (std::log(G_II) - std::log(G_IIc)) :
                              minus_infinity;
        return from_log(log_sum_exp(t_I, t_II), 2 * exponent);
      }
    // Benzeggagh-Kenane: the toughness of the mode mix G_II / G (at most
    // 1: no overflow).
    const double mix       = std::min(G_II / G, 1.);
    const double toughness = G_c + (G_IIc - G_c) * std::pow(mix, exponent);
    return from_log(std::log(G) - std::log(toughness), 2);
  }


  double
  critical_load_factor(const GrowthCriterion &f, const double lambda)
  {
    if (f.log_value == minus_infinity || std::isnan(f.log_value))
      return std::numeric_limits<double>::infinity();
    return lambda * std::exp(-f.log_value / f.degree);
  }


  bool
  is_critical(const GrowthCriterion &f)
  {
    // lambda / lambda_c = f^(1 / degree) >= 1 - tolerance.
    return f.log_value / f.degree >= std::log1p(-growth_criterion_tolerance);
  }


  double
  split_resolution(const double acceptance_tolerance)
  {
    return std::max(acceptance_tolerance, 1e-12);
  }
} // namespace bilayer
