// Sliding contact over a corner of a polygonal Sigma inside the crack.
//
// tests/corner_contact.geo: a roof-shaped Sigma of four segments whose
// middle two form the crack and meet at the corner (0, 0), Sigma turning
// there by 20, 45 or 90 degrees (tests/corner_contact_TURN.msh, matching
// Q1 traces, 8 cells along Sigma, refined globally 3 times; twice for the
// opening load). Omega- is clamped at the bottom, both subdomains on the
// left; the top of Omega+ is pressed and sheared (traction (q/2, -q)): the
// crack closes and its faces slide over the corner; pulled up (traction (q/2,
// q)) it opens.
//
// At a corner of Sigma the constraint [u].nu >= 0 holds against the
// normals of both pieces that meet there. With the multiplier in the cone
// spanned by those two normals the discrete constraint set is
// K_h = {w in V_h: [w].nu >= 0 on gamma_c} exactly (the jump of a Q1 trace
// is linear on each straight segment and the normal is constant there), so
// under uniform refinement the sets are nested and the energy cannot grow:
// each difference Pi_{k+1} - Pi_k must be <= 0. The penetration at the
// corner point, the jump of the displacement at the corner node measured
// against each adjacent face (the piece normals from the geometry), and the
// largest interpenetration of the diagnostics vanish up to round-off; a
// single constraint along the mean normal of the two faces lets the node
// slide through the other face by |slip| sin(turn / 2), which does not fall
// with h. Asserted: penetration at round-off (1e-10 of the displacement
// scale) or falling at an observed rate >= 0.9 between cycles; the
// relative constraint violation (12) at round-off or falling from cycle to
// cycle; every cycle is accepted (mu_c >= 0, complementarity). The values
// per cycle are written to corner_contact.txt.

#include <bilayer/drivers/study.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  struct Cycle
  {
    double energy, violation, corner_penetration, max_penetration, h;
    bool   accepted;
  };

  std::vector<Cycle>
  run(const int turn, const std::string &traction, const unsigned int n_cycles)
  {
    std::ostringstream scene, sink;
    scene << "subsection Geometry\n set Gmsh file = " << SOURCE_DIR
          << "/corner_contact_" << turn << ".msh\n"
          << " set Clamped sides = bottom, left\nend\n"
          << "subsection Mesh\n set Number of cycles = " << n_cycles
          << "\nend\n"
          << "subsection Loads\n set Constants = q = 1e-3*mu1\n"
          << " subsection Layer 1\n  set Traction on top = " << traction
          << "\n end\nend\n"
          << "subsection Solver\n set Method = active set\n"
          << " set Stopping rule = kkt\n set Tolerance = 1e-12\nend\n"
          << "subsection Output\n set Output directory = results\n"
          << " set Write VTU = false\n set Write interface CSV = false\n"
          << " set Terminal output = checks\nend\n";
    Study study(scene_from_string(scene.str(), "corner_contact"), sink);
    // The normals of the two crack segments at the corner (into Omega+).
    const double       a = turn * M_PI / 360;
    const Tensor<1, 2> before({-std::sin(a), std::cos(a)}),
      after({std::sin(a), std::cos(a)});
    std::vector<Cycle> cycles;
    for (unsigned int k = 0; k < n_cycles; ++k)
      {
        const CycleRecord &record      = study.run_cycle(k);
        const auto         nodes       = interface_nodes(study.interface(),
                                           study.solutions(),
                                           study.multipliers(),
                                           1e-10);
        double             penetration = -1, h = 0;
        for (unsigned int i = 0; i < nodes.size(); ++i)
          if (nodes[i].point.norm() < 1e-12)
            {
              const auto        &t = nodes[i].trace;
              const Tensor<1, 2> d = t[Layout::u_plus] - t[Layout::u_minus];
              const Tensor<1, 2> jump =
                d[0] * tangent_of(nodes[i].normal) + d[1] * nodes[i].normal;
              penetration =
                std::max(0., -std::min(jump * before, jump * after));
            }
        for (unsigned int i = 0; i + 1 < nodes.size(); ++i)
          h = std::max(h, (nodes[i + 1].point - nodes[i].point).norm());
        const double scale = record.report.displacement_scale;
        cycles.push_back({record.energy,
                          record.report.relative_constraint_violation,
                          penetration / scale,
                          record.report.max_penetration / scale,
                          h,
                          record.accepted() && penetration >= 0});
      }
    return cycles;
  }

  /// Round-off (1e-10), or falling like h^0.9 at least, from each cycle to
  /// the next.
  bool
  falls_like_h(const std::vector<Cycle> &c, double Cycle::*value)
  {
    bool ok = true;
    for (unsigned int k = 1; k < c.size(); ++k)
      ok =
        ok && (c[k].*value <= 1e-10 || std::log(c[k - 1].*value / c[k].*value) /
                                           std::log(c[k - 1].h / c[k].h) >=
                                         0.9);
    return ok;
  }
} // namespace


int
main()
{
  // The measured values, cycle by cycle (docs/multipliers.md).
  std::ofstream table("corner_contact.txt");
  table << std::setprecision(3);
  for (const int turn : {20, 45, 90})
    for (const auto &[name, traction] :
         {std::pair<std::string, std::string>("pressed and sheared",
                                              "0.5*q; -q"),
          std::pair<std::string, std::string>("opening", "0.5*q; q")})
      {
        // Opening: no contact, three meshes suffice.
        const std::vector<Cycle> c =
          run(turn, traction, name == "opening" ? 3 : 4);
        bool accepted = true, monotone = true, violation = true;
        for (unsigned int k = 0; k < c.size(); ++k)
          {
            accepted = accepted && c[k].accepted;
            if (k > 0)
              {
                monotone  = monotone && c[k].energy - c[k - 1].energy <= 0;
                violation = violation && (c[k].violation <= 1e-10 ||
                                          c[k].violation < c[k - 1].violation);
              }
          }
        const std::string what =
          "turn " + std::to_string(turn) + " degrees, " + name + ": ";
        std::cout
          << what << "every cycle accepted: " << yes(accepted) << std::endl
          << what << "energy non-increasing under refinement: " << yes(monotone)
          << std::endl
          << what
          << "relative constraint violation at round-off or falling with h: "
          << yes(violation) << std::endl
          << what
          << "penetration at the corner against both faces at "
             "round-off or falling like h: "
          << yes(falls_like_h(c, &Cycle::corner_penetration)) << std::endl
          << what
          << "largest interpenetration at round-off or falling like "
             "h: "
          << yes(falls_like_h(c, &Cycle::max_penetration)) << std::endl;
        for (const Cycle &x : c)
          table << what << "h " << x.h << " energy " << x.energy
                << " relative violation " << x.violation
                << " corner penetration " << x.corner_penetration
                << " largest interpenetration " << x.max_penetration << '\n';
      }
}
