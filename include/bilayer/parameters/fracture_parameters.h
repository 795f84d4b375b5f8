#ifndef bilayer_fracture_parameters_h
#define bilayer_fracture_parameters_h

#include <deal.II/base/parameter_handler.h>

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
  struct FractureParameters
  {
    /// Compute G at every crack tip of every cycle.
    bool energy_release_rate = true;
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

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace bilayer

#endif
