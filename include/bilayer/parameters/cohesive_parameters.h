#ifndef bilayer_cohesive_parameters_h
#define bilayer_cohesive_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <bilayer/physics/cohesive_law.h>

#include <array>
#include <limits>
#include <vector>

/**
 * The subsection Cohesive: a traction-separation law on pieces of an
 * interface and the driver that traces its softening curve
 * (docs/cohesive.md).
 */
namespace bilayer
{
  /// Cohesive/Control: what the steps prescribe.
  enum class CohesiveControl
  {
    /// The load factors of Loads/Load factor, one per step.
    load_factor,
    /// The largest growth of an equivalent separation in the zone beyond
    /// its history, Separation increment per step (path following).
    separation,
    /// The growth of the zone's dissipated energy, Dissipation increment
    /// per step (path following; the dissipation never decreases along
    /// the curve, whatever its turns).
    dissipation
  };

  struct CohesiveParameters
  {
    /// The law and its constants.
    CohesiveProperties law;
    /// The interface (0-based) whose pieces carry the law.
    unsigned int interface = 0;
    /// The pieces of the zone, intervals of the coordinate s along it.
    std::vector<std::array<double, 2>> zone;
    CohesiveControl                    control = CohesiveControl::load_factor;
    double       separation_increment = 0, dissipation_increment = 0;
    unsigned int steps              = 100;
    double       damage_tolerance   = 1e-6;
    unsigned int maximum_iterations = 200;
    /// Whether a step starts from the Newton method on the interface
    /// (Cohesive/Method = newton) or the secant iteration runs alone
    /// (secant).
    bool newton = true;

    bool
    active() const
    {
      return law.type != CohesiveLawType::none;
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace bilayer

#endif
