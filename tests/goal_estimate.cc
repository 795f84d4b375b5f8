// The goal-oriented (dual-weighted residual) estimates of G and the energy
// (goal_oriented_estimates(), docs/fracture.md §11) and the refinement for
// a goal (Mesh/Refinement goal), on the double cantilever beam of
// parameter_files/dcb.prm (crack (0, 10), tractions P at the arms' ends,
// the other end clamped: tractions only, zero prescribed displacement).
// Asserted:
// 1. the dual problem: J'(w)[w] = 2 G for the quadratic domain integral,
//    and the dual solution z of the problem with the active set held
//    satisfies (F, z) = J'(w)[w] (the operator is symmetric, the
//    multipliers of the state and of the dual are complementary on the
//    held set), so (F, z) = 2 G on every cycle, to 1e-6 (the dual's
//    conjugate gradients stop at 1e-10 of the largest |z0|);
// 2. the estimate is reported (finite) on every cycle with G and dG is at
//    least |G_dwr| (dG is widened to the goal-oriented estimate);
// 3. Mesh/Refinement goal = G and = G at tip 1 and = energy: accepted
//    runs whose energies do not rise from cycle to cycle (nested meshes)
//    and whose last G is within 2 % of the beam theory's
//    12 P^2 (a + chi h)^2 / (E' h^3);
// 4. a tip number 0 or beyond the tips, and an unknown goal, are refused
//    naming Mesh/Refinement goal.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "verdict.h"

using namespace bilayer;

namespace
{
  constexpr double E = 1, nu = 0.3, h = 1, P = 1e-3, a = 10;

  std::string
  scene(const std::string &goal, const unsigned int cycles)
  {
    std::ifstream in(std::string(SOURCE_DIR) + "/../parameter_files/dcb.prm");
    std::ostringstream text;
    text << in.rdbuf() << "subsection Mesh\n set Number of cycles = " << cycles
         << "\n set Refinement goal = " << goal << "\nend\n"
         << "subsection Fracture\n set Goal-oriented estimate = true\nend\n"
         << "subsection Output\n set Output directory = results\n"
            " set Write VTU = false\n set Write interface CSV = false\n"
            " set Progress interval = 0\n set Terminal output = checks\nend\n";
    return text.str();
  }

  /// 12 P^2 (a + chi h)^2 / (E' h^3), chi = 6^(-1/4) (as
  /// tests/beam_specimens.h).
  double
  beam_G()
  {
    const double E_prime = E / (1 - nu * nu);
    const double l       = a + std::pow(6., -0.25) * h;
    return 12 * P * P * l * l / (E_prime * h * h * h);
  }
} // namespace


int
main()
{
  {
    std::ostringstream sink;
    Study      study(scene_from_string(scene("estimator", 8), "goal"), sink);
    const bool accepted = study.run();
    std::cout << "dcb: run accepted: " << yes(accepted) << std::endl;
    double       worst    = 0;
    bool         reported = true, widened = true;
    unsigned int n = 0;
    for (const CycleRecord &r : study.records())
      for (const EnergyReleaseRate &g : r.release)
        if (std::isfinite(g.G))
          {
            ++n;
            worst    = std::max(worst, std::abs(g.dual_work / (2 * g.G) - 1));
            reported = reported && std::isfinite(g.G_dwr) &&
                       std::isfinite(g.G_dwr_absolute) &&
                       std::abs(g.G_dwr) <= g.G_dwr_absolute * (1 + 1e-12);
            widened = widened && g.error >= std::abs(g.G_dwr);
          }
    std::cout << "dcb: (F, z) = 2 G on every cycle with G, to 1e-6: "
              << yes(n >= 6 && worst <= 1e-6) << std::endl;
    std::cout << "dcb: G_dwr reported, |G_dwr| <= sum |cell terms|: "
              << yes(n >= 6 && reported) << std::endl;
    std::cout << "dcb: dG >= |G_dwr|: " << yes(n >= 6 && widened) << std::endl;
    std::ofstream("measured.txt")
      << "largest |(F, z) / (2 G) - 1| = " << worst << "\n";
  }
  for (const std::string goal : {"G", "G at tip 1", "energy"})
    {
      std::ostringstream sink;
      Study              study(scene_from_string(scene(goal, 8), "goal"), sink);
      const bool         accepted = study.run();
      bool               falling  = true;
      for (std::size_t k = 1; k < study.records().size(); ++k)
        falling = falling && study.records()[k].energy <=
                               study.records()[k - 1].energy * (1 - 1e-12);
      const auto  &last = study.records().back().release;
      const double G    = last.size() == 1 ? last[0].G : std::nan("");
      std::cout << "Refinement goal = " << goal
                << ": accepted, energies falling: " << yes(accepted && falling)
                << std::endl;
      std::cout << "Refinement goal = " << goal
                << ": G within 2 % of beam theory: "
                << yes(std::abs(G / beam_G() - 1) <= 0.02) << std::endl;
    }
  for (const std::string goal : {"G at tip 0", "G at tip 2", "tips"})
    {
      bool named = false;
      try
        {
          std::ostringstream sink;
          Study study(scene_from_string(scene(goal, 2), "goal"), sink);
          named = !study.run();
        }
      catch (const std::exception &e)
        {
          named = std::string(e.what()).find("Mesh/Refinement goal") !=
                  std::string::npos;
        }
      std::cout << "refused: Refinement goal = " << goal << ": " << yes(named)
                << std::endl;
    }
}
