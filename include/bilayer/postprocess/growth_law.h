#ifndef bilayer_growth_law_h
#define bilayer_growth_law_h

#include <bilayer/parameters/fracture_parameters.h>
#include <bilayer/postprocess/fracture.h>

#include <limits>
#include <string>

/**
 * @file
 * When a crack tip grows (docs/fracture.md, section 9): the criterion of
 * Fracture/Mixed-mode law at a tip, and the load factor at which it
 * reaches 1 under proportional loading.
 */
namespace bilayer
{
  /// The growth criterion at one tip.
  struct GrowthCriterion
  {
    /// f: the tip grows where f >= 1 (the largest double where f
    /// overflows; is_critical() decides from log_value).
    double value = 0;
    /// ln f (-infinity where f = 0), exact where f overflows.
    double log_value = -std::numeric_limits<double>::infinity();
    /**
     * The degree of f in the load factor under proportional loading (G,
     * G_I, G_II ~ lambda^2): 2 for the mode-independent and the
     * Benzeggagh-Kenane laws, 2 a for the power law. f(lambda) = (lambda /
     * lambda_0)^degree f(lambda_0).
     */
    double degree = 2;
    /// Why f is not available (the mode split is not defined for a law
    /// that needs it); empty where it is.
    std::string undefined;
  };

  /**
   * The criterion of @p law with @p exponent at a tip with @p g (its G and
   * mode split), toughness @p G_c (mode I for the mode-dependent laws)
   * and @p G_IIc. Nothing released (G <= 0) gives f = 0. A part G_I or
   * G_II of the mode split at or below @p resolution G is round-off and
   * counts as 0 (split_resolution()). f is evaluated in logarithms: no
   * overflow for a large exponent.
   */
  GrowthCriterion
  growth_criterion(const MixedModeLaw       law,
                   const double             exponent,
                   const EnergyReleaseRate &g,
                   const double             G_c,
                   const double             G_IIc,
                   const double             resolution = 0);

  /**
   * The resolution of the mode split relative to G: the crack-closure
   * works are products of the multipliers and the jumps, each accurate to
   * the relative constraint violation a run accepts (Solver/Acceptance
   * tolerance), so a share G_II / G (or G_I / G) at or below
   * max(Solver/Acceptance tolerance, 1e-12) is not resolved.
   */
  double
  split_resolution(const double acceptance_tolerance);

  /**
   * Whether the tip of @p f is critical: its load factor is at least
   * 1 - growth_criterion_tolerance times its critical load
   * (f^(1/degree) >= 1 - tolerance: the tolerance applies to the load, not
   * to f).
   */
  bool
  is_critical(const GrowthCriterion &f);

  /**
   * The load factor at which the criterion @p f, computed at the load
   * factor @p lambda, reaches 1 under proportional loading: lambda
   * f^(-1/degree); infinite where f = 0.
   */
  double
  critical_load_factor(const GrowthCriterion &f, const double lambda);

  /// A tip grows where its load factor is at least 1 - this times its
  /// critical load (round-off of G at an exactly critical load).
  constexpr double growth_criterion_tolerance = 1e-9;
} // namespace bilayer

#endif
