#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/fracture_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

#include <cmath>

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
    prm.leave_subsection();
  }


  void
  FractureParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fracture");
    energy_release_rate = prm.get_bool("Energy release rate");
    support_radius      = get_double(prm, "Fracture", "Support radius");
    AssertThrow(std::isfinite(support_radius) && support_radius >= 0,
                ExcMessage("Fracture/Support radius must be >= 0 (0: "
                           "automatic), got " +
                           prm.get("Support radius")));
    mode_split_length = get_double(prm, "Fracture", "Mode split length");
    AssertThrow(std::isfinite(mode_split_length) && mode_split_length >= 0,
                ExcMessage("Fracture/Mode split length must be >= 0 (0: "
                           "automatic), got " +
                           prm.get("Mode split length")));
    prm.leave_subsection();
  }
} // namespace bilayer
