#ifndef bilayer_mode_split_h
#define bilayer_mode_split_h

#include <deal.II/lac/block_vector.h>

#include <bilayer/core/layout.h>
#include <bilayer/interface/interface.h>
#include <bilayer/postprocess/fracture.h>
#include <bilayer/subproblem/subproblem.h>

#include <array>
#include <string>
#include <vector>

/**
 * @file
 * The mode split G = G_I + G_II at the crack tips (docs/fracture.md §7):
 * the ratio of Irwin's crack-closure integrals over a length Delta at the
 * tip, applied to the domain-integral G, so that the two parts add up to G
 * exactly.
 */
namespace bilayer
{
  /// The automatic closure length Delta (Fracture/Mode split length = 0)
  /// is this many times the size of the cells at the tip (support_cells()),
  /// at most half the free distance of the tip.
  constexpr double mode_split_cells = 8;

  /**
   * Irwin's crack-closure integrals over the length @p length at @p tip,
   *
   *   c_I  = 1 / (2 Delta) int_0^Delta t_n(s_tip + d r) d_n(s_tip - d
   *          (Delta - r)) dr,
   *   c_II = the same with t_t and d_t,
   *
   * d = the direction of growth along s (CrackTip::sign), t = sigma nu =
   * -mu the traction that Omega- exerts on Omega+ ahead of the tip (the
   * multiplier mu_1 across Sigma, which carries all the force between
   * Omega- and Omega+: layer 2's halves couple only to layer 1 of their own
   * side), d = [u] = u+ - u- the jump of layer 1 behind it, both in the
   * node frames (tangential, normal). The traction enters as the nodal
   * forces the discrete problem transmits, t ds -> -D_a mu_a at the nodes a
   * of mu_1 ahead (0 <= r_a < Delta; D the lumped multiplier mass), each
   * against the jump at the point Delta - r_a behind, interpolated from the
   * nodes (the opening of a crack node in contact, mu_c > 0, is 0; a
   * penetration counts as 0; the jumps at glued nodes are 0): the
   * distributed form of the virtual crack-closure technique, exact for the
   * nodal forces where the interpolated traction misses the r^(-1/2) peak
   * at the tip (docs/fracture.md §7). Not clipped: c_I, c_II may be
   * negative (round-off, or faces that close behind the tip). The third
   * entry is the scale Delta max|mu_a|^2 over those nodes [stress^2 x
   * length]: divided by a stiffness, a release rate.
   */
  std::array<double, 3>
  crack_closure_integrals(const Interface                   &interface,
                          const Solutions                   &w,
                          const dealii::BlockVector<double> &mu,
                          const CrackTip                    &tip,
                          const double                       length);

  /**
   * Whether the materials of every present layer agree across interface
   * @p i of @p topology (Sigma: 0) at the crack tip @p tip: the tangents C
   * of the laws of the plies next to the tip on either side, in every
   * layer, equal to 1e-12 of their largest entry. Then the field at a tip
   * splits into the parts symmetric and antisymmetric about the crack line
   * and the closure ratio tends to the mode ratio as Delta -> 0; otherwise
   * (an interface crack between different materials) the near-tip field
   * oscillates and the split depends on the length.
   */
  bool
  materials_agree_across(
    const PerSubproblem<const ElasticSubproblem *> &subproblems,
    const Topology                                 &topology,
    const unsigned int                              i,
    const dealii::Point<2>                         &tip);

  /**
   * Fill G_I, G_II, phase_angle, mode_split_length and mode_split_note of
   * every entry of @p release (G already computed) from the closure
   * integrals: G_I = G c_I / (c_I + c_II), G_II = G c_II / (c_I + c_II),
   * c_I and c_II clipped at 0, phase angle atan(sqrt(c_II / c_I)) in
   * degrees (= atan(sqrt(G_II / G_I)) where G > 0, and defined for a G of
   * either sign). @p length: Fracture/Mode split length (0: automatic,
   * mode_split_cells times @p tip_cell_sizes[t], at most half the free
   * distance). NaN with a note where G is NaN, where the automatic length
   * meets a tip between different materials, where the given length
   * reaches past the free distance of the tip, and where c_I + c_II = 0
   * while |G| is more than round-off (1e-6 of Delta max|t|^2 / the
   * stiffness of layer 1); G_I = G_II = 0 where it is round-off.
   */
  void
  mode_split(const PerSubproblem<const ElasticSubproblem *> &subproblems,
             const Interface                                &interface,
             const Solutions                                &w,
             const dealii::BlockVector<double>              &mu,
             const std::vector<double>                      &tip_cell_sizes,
             const double                                    length,
             std::vector<EnergyReleaseRate>                 &release);
} // namespace bilayer

#endif
