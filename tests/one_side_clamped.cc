// An end of Sigma clamped on one side only (tests/one_side_clamped.geo: the
// left side split at Sigma into left_below, a part of Omega-, and
// left_above, a part of Omega+; bottom and top clamped, matching Q1 traces
// of the straight Sigma, no crack).
//
// An end of Sigma lies on Gamma_D only where its jump is fixed by the
// Dirichlet data on both sides. Clamped on one side, the other side's end
// node is free and the gluing constraint there must be kept: its row
// couples the free dof to the prescribed value of the clamped side
// (non-zero here: both layers prescribed to the constant (0.5 c, 0.25 c) on
// Gamma_D, so the jump includes it). The free part next to the end is
// pulled away from Sigma (traction (0, c) on left_above, (0, -c) on
// left_below), which opens the end if it is not glued; the right parts
// (free) are pulled likewise in every case.
//
// On matching Q1 traces the glued discrete space is conforming and the
// spaces of nested uniform refinements are nested, so
// - the energy (the minimum of the discrete problem) does not increase
//   from one cycle to the next: the sign of each difference is asserted;
// - the constraint violation (12) vanishes to round-off on every cycle
//   (relative value below 1e-9), and so does the normal opening at the
//   end node relative to the displacement scale;
// - the gluing multiplier at the end node is a free multiplier and carries
//   the traction of the pulled part: it is non-zero;
// - each cycle is accepted.
// Cases: the left end clamped below only, above only, on both sides (its
// gluing multiplier is then dropped: the jump is fixed by the data) and on
// neither side.

#include <bilayer/drivers/study.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace bilayer;

namespace
{
  std::ostringstream quiet;

  void
  check(const std::string &name,
        const std::string &clamped,
        const std::string &tractions,
        const bool         end_dropped)
  {
    const std::string text =
      "subsection Geometry\n set Gmsh file = " + std::string(SOURCE_DIR) +
      "/one_side_clamped.geo\n set Clamped sides = " + clamped +
      "\nend\n"
      "subsection Mesh\n set Number of cycles = 4\n"
      " set Refinement = global\nend\n"
      "subsection Loads\n set Constants = c = 1e-3*mu1\n"
      " subsection Layer 1\n" +
      tractions +
      "  set Traction on right_above = 0; c\n"
      "  set Traction on right_below = 0; -c\n"
      "  set Prescribed displacement = 0.5*c; 0.25*c\n end\n"
      " subsection Layer 2\n"
      "  set Prescribed displacement = 0.5*c; 0.25*c\n end\nend\n"
      "subsection Solver\n set Method = active set\n"
      " set Stopping rule = kkt\n set Tolerance = 1e-12\nend\n"
      "subsection Output\n set Output directory = results\n"
      " set Write VTU = false\n set Write interface CSV = false\n"
      " set Terminal output = checks\nend\n";
    Study study(scene_from_string(text, "scene"), quiet);

    bool   decreasing = true, accepted = true, glued = true, carried = true;
    double previous = 0, worst_violation = 0, worst_opening = 0;
    for (unsigned int cycle = 0; cycle < 4; ++cycle)
      {
        const CycleRecord &record = study.run_cycle(cycle);
        accepted                  = accepted && record.accepted();
        if (cycle > 0)
          decreasing = decreasing && record.energy - previous <= 0;
        previous        = record.energy;
        worst_violation = std::max(worst_violation,
                                   record.report.relative_constraint_violation);

        // The end node of mu_1 at the left end (x = -1).
        const MultiplierSpace &space = study.interface().space();
        const unsigned int     n     = space.n_nodes(Layout::across_sigma);
        const auto &mu = study.multipliers().block(Layout::across_sigma);
        const std::vector<double> opening =
          normal_opening(study.interface(), study.solutions());
        for (const unsigned int end : {0u, n - 1})
          {
            if (study.interface().curve().point(
                  space.node_position(end, Layout::across_sigma))[0] > 0)
              continue;
            const unsigned int t = Layout::entry(end, Layout::tangential),
                               m = Layout::entry(end, Layout::normal);
            const double scale   = record.report.displacement_scale;
            worst_opening =
              std::max(worst_opening, std::abs(opening[end]) / scale);
            if (end_dropped)
              carried = carried && !space.free(t) && !space.free(m);
            else
              {
                glued   = glued && space.free(t) && space.free(m);
                carried = carried && std::abs(mu(m)) > 1e-6 * mu.linfty_norm();
              }
          }
      }
    std::cout << name << ": accepted: " << (accepted ? "yes" : "NO")
              << "; energy non-increasing: " << (decreasing ? "yes" : "NO")
              << "; relative violation (12) below 1e-9: "
              << (worst_violation < 1e-9 ? "yes" : "NO")
              << "; opening at the left end below 1e-9: "
              << (worst_opening < 1e-9 ? "yes" : "NO") << "; left end "
              << (end_dropped ? "on Gamma_D (no multiplier): " :
                                "glued, multiplier non-zero: ")
              << (glued && carried ? "yes" : "NO") << std::endl;
  }
} // namespace


int
main()
{
  const std::string pull_above = "  set Traction on left_above = 0; c\n";
  const std::string pull_below = "  set Traction on left_below = 0; -c\n";
  check("clamped below only", "bottom, top, left_below", pull_above, false);
  check("clamped above only", "bottom, top, left_above", pull_below, false);
  check("clamped on both sides",
        "bottom, top, left_below, left_above",
        "",
        true);
  check("clamped on neither side",
        "bottom, top",
        pull_above + pull_below,
        false);
}
