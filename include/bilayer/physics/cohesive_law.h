#ifndef bilayer_cohesive_law_h
#define bilayer_cohesive_law_h

#include <memory>
#include <string>

/**
 * @file
 * The traction-separation laws of a cohesive zone (docs/cohesive.md): one
 * interface, CohesiveLaw, and one implementation per file
 * (bilinear_cohesive_law.cc, exponential_cohesive_law.cc), chosen by
 * Cohesive/Law (make_cohesive_law()).
 */
namespace bilayer
{
  /// Cohesive/Law.
  enum class CohesiveLawType
  {
    none,
    /// Bilinear: linear up to the strength, linear softening to zero
    /// (Camanho-Davila mixed mode).
    bilinear,
    /// Exponential (Xu-Needleman type): t = k0 delta exp(-delta / delta_c).
    exponential
  };

  /// Cohesive/Mixed-mode criterion.
  enum class CohesiveCriterion
  {
    /// G_c(B) = G_Ic + (G_IIc - G_Ic) B^eta.
    benzeggagh_kenane,
    /// ((1 - B) G / G_Ic)^a + (B G / G_IIc)^a = 1.
    power_law
  };

  /// The law of a cohesive zone and its constants (Cohesive/...).
  struct CohesiveProperties
  {
    CohesiveLawType   type            = CohesiveLawType::none;
    double            normal_strength = 1, shear_strength = 1;
    double            mode_i_toughness = 1, mode_ii_toughness = 1;
    CohesiveCriterion criterion = CohesiveCriterion::benzeggagh_kenane;
    double            exponent  = 2;
    /// Bilinear/Penalty stiffness.
    double penalty_stiffness = 1e4;
  };

  /**
   * A traction-separation law written as damage of an initial stiffness
   * k0: the traction is t = k0 (1 - d) delta on the separation delta =
   * (<delta_n>, delta_t) (the normal part in tension only; under pressure
   * the faces touch, exactly), with the damage d = d(delta_m, B) a function
   * of the largest equivalent separation delta_m = max over the history of
   * sqrt(<delta_n>^2 + delta_t^2) and of the mode mixity B = delta_t^2 /
   * delta^2 (the shear share of the energy, G_II / (G_I + G_II), for one
   * stiffness in both directions). Unloading runs along the secant to the
   * origin; d never decreases (the driver keeps the larger of the old and
   * new values). A point with d = 1 is a crack: contact and friction
   * (Contact) act there.
   */
  class CohesiveLaw
  {
  public:
    virtual ~CohesiveLaw() = default;

    /// The initial stiffness k0 [stress / length].
    virtual double
    initial_stiffness() const = 0;

    /// The damage at the largest equivalent separation @p delta_m and the
    /// mode mixity @p B, in [0, 1] (1: fully damaged, a crack).
    virtual double
    damage(const double delta_m, const double B) const = 0;

    /// The energy per area dissipated when the separation has grown to
    /// @p delta_m at the fixed mixity @p B (the area under the law up to
    /// delta_m less what unloading along the secant returns): 0 before the
    /// onset, the mixed-mode toughness G_c(B) at full damage.
    virtual double
    dissipated_energy(const double delta_m, const double B) const = 0;

    /// The mixed-mode toughness G_c(B) (Cohesive/Mixed-mode criterion).
    double
    toughness(const double B) const;

    /// The equivalent separation at which the traction peaks, at mixity B.
    virtual double
    onset_separation(const double B) const = 0;

    /// What the law's entries are (a line for the terminal).
    virtual std::string
    describe() const = 0;

  protected:
    explicit CohesiveLaw(const CohesiveProperties &properties)
      : properties(properties)
    {}

    /// The mixing factor of the criterion at mixity @p B: B^eta for
    /// Benzeggagh-Kenane, used by both laws.
    double
    mixing(const double B) const;

    const CohesiveProperties properties;
  };

  /// The law of Cohesive/Law (null for none).
  std::unique_ptr<CohesiveLaw>
  make_cohesive_law(const CohesiveProperties &properties);
} // namespace bilayer

#endif
