#ifndef bilayer_growth_law_h
#define bilayer_growth_law_h

#include <bilayer/parameters/fracture_parameters.h>
#include <bilayer/postprocess/fracture.h>

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
    /// f: the tip grows where f >= 1.
    double value = 0;
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
   * and @p G_IIc. Nothing released (G <= 0) gives f = 0.
   */
  GrowthCriterion
  growth_criterion(const MixedModeLaw       law,
                   const double             exponent,
                   const EnergyReleaseRate &g,
                   const double             G_c,
                   const double             G_IIc);

  /**
   * The load factor at which the criterion @p f, computed at the load
   * factor @p lambda, reaches 1 under proportional loading: lambda
   * f^(-1/degree); infinite where f = 0.
   */
  double
  critical_load_factor(const GrowthCriterion &f, const double lambda);

  /// A tip grows where its criterion is at least 1 - this (round-off of G
  /// at an exactly critical load).
  constexpr double growth_criterion_tolerance = 1e-9;
} // namespace bilayer

#endif
