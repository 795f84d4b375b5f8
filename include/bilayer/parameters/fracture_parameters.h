#ifndef bilayer_fracture_parameters_h
#define bilayer_fracture_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <memory>
#include <string>
#include <vector>

/**
 * The subsection Fracture: the energy release rate at the crack tips.
 */
namespace bilayer
{
  /**
   * The energy release rate at the crack tips (docs/fracture.md): the
   * domain integral of the shape derivative of the energy under a velocity
   * field theta that moves one tip along Sigma.
   */
  /// Fracture/Crack growth: what the growth driver does.
  enum class CrackGrowth
  {
    /// No growth: the mesh cycles of the study.
    none,
    /// The tips advance step by step at the first load factor whatever
    /// their criterion (G and the critical load of every crack length).
    sweep,
    /// Quasi-static Griffith growth under the load factors of
    /// Loads/Load factor.
    quasi_static
  };

  /// Fracture/Mixed-mode law: when a tip grows.
  enum class MixedModeLaw
  {
    /// G >= G_c.
    mode_independent,
    /// (G_I / G_Ic)^a + (G_II / G_IIc)^a >= 1.
    power_law,
    /// G >= G_Ic + (G_IIc - G_Ic) (G_II / G)^eta (Benzeggagh-Kenane).
    benzeggagh_kenane
  };

  struct FractureParameters
  {
    /// Compute G at every crack tip of every cycle.
    bool energy_release_rate = true;
    /// Whether to compute K_I, K_II at the tips (docs/fracture.md §10).
    bool stress_intensity = true;
    /// Fracture/Goal-oriented estimate (also on with a Mesh/Refinement
    /// goal other than estimator).
    bool goal_oriented = false;
    /**
     * Outer radius R of the support of theta [length]; theta = its
     * direction for r <= R/2 and falls smoothly to 0 at r = R. 0: half the
     * distance from the tip to the nearest other tip, corner of Sigma or
     * point of the outer boundary.
     */
    double support_radius = 0;
    /**
     * The length Delta of the crack-closure integrals of the mode split
     * G = G_I + G_II [length] (docs/fracture.md §7). 0: mode_split_cells
     * times the size of the cells at the tip, at most half the free
     * distance (then no split at a tip between different materials, whose
     * split depends on the length).
     */
    double mode_split_length = 0;
    /**
     * The reference length L of K_I + i K_II = K L^(i eps) at a tip
     * between different materials [length] (docs/fracture.md §10); 0: not
     * set (K_I, K_II and the phase angle NaN at such tips).
     */
    double reference_length = 0;

    CrackGrowth growth = CrackGrowth::none;
    /// G_c (mode I toughness of the mode-dependent laws) and G_IIc as
    /// expressions of (x, y, s) [energy / area]; G_IIc empty: G_c.
    std::string  toughness           = "1";
    std::string  mode_ii_toughness   = "";
    MixedModeLaw mixed_mode_law      = MixedModeLaw::mode_independent;
    double       mixed_mode_exponent = 1;
    /// The mode mix the mode-dependent laws read: the crack-closure split
    /// G_I, G_II (false) or that of the stress intensity factors,
    /// G_I = G cos^2 psi, G_II = G sin^2 psi with psi their phase angle at
    /// the reference length (true).
    bool mode_mix_from_k = false;
    /// Vertices of Sigma a growing tip advances per growth step.
    unsigned int growth_increment = 1;
    /// The tips that may grow (numbers 1, 2, ... of the initial tips ordered
    /// by s); empty: all.
    std::vector<unsigned int> growing_tips;
    /// Under proportional loading: step exactly to the critical load of
    /// each crack (G(lambda) = lambda^2 G(1)) between the load factors.
    bool exact_onsets = true;
    /// The most growth steps (states) of one run.
    unsigned int maximum_growth_steps = 1000;

    /// G_c and G_IIc at the point @p p, parameter @p s of Sigma.
    double
    toughness_at(const dealii::Point<2> &p, const double s) const;
    double
    mode_ii_toughness_at(const dealii::Point<2> &p, const double s) const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

  private:
    std::shared_ptr<const dealii::FunctionParser<3>> toughness_function,
      mode_ii_function;
  };
} // namespace bilayer

#endif
