// Crack growth on an interface other than Sigma (docs/laminates.md): the two
// delaminations of parameter_files/two_delaminations.prm (a homogeneous beam
// (0, 32) x (0, 3) of three sublaminates of height 1, the delaminations
// (0, 8) on Sigma (y = 1) and (0, 20) on interface 2 (y = 2), pure bending
// moments on the cracked end's arms) on a uniform Q2 mesh of 64 cells along
// the interfaces, quasi-static growth under the load factors 1, 1.5 with the
// toughness G_c = 1e-5 for x < 21 (1 beyond: the tips stop there).
//
// Pure bending of the sublaminates is a steady state: G at either tip does
// not depend on its crack's length (the energy per unit length of the
// cracked and the uncracked parts of the beam), G ~ lambda^2. So:
// - tip 2 (on interface 2, the larger G) starts at the load factor
//   sqrt(G_c / G_2(1)) (the driver's exact onset, 1e-9) and runs at that
//   load (unstable growth) to the tough part at x = 21; tip 1 on Sigma stays
//   at x = 8, below critical;
// - over the growth of tip 2, its G stays the same (steady state; 1e-6
//   relative; the uniform mesh is invariant under the step of a vertex);
// - the state after growth is the equilibrium of the moved crack: a static
//   run with the crack (0, 21) on interface 2 at the load factor 1 gives
//   G_2 / lambda^2 of the grown state (1e-8: the solvers' tolerance).

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "quiet_output.h"
#include "verdict.h"

using namespace bilayer;

namespace
{
  std::string
  scene_text()
  {
    std::ifstream      in(std::string(SOURCE_DIR) +
                     "/../parameter_files/two_delaminations.prm");
    std::ostringstream text;
    text << in.rdbuf()
         << "subsection Mesh\n set Refinement = global\n"
            " set Number of cycles = 1\n set Cells along Sigma = 64\nend\n";
    return text.str();
  }
} // namespace


int
main()
{
  const std::string  base = scene_text();
  std::ostringstream sink;
  Study              growth(scene_from_string(
                 base +
                   "subsection Fracture\n set Crack growth = quasi-static\n"
                                " set Toughness = x < 21 ? 1e-5 : 1\nend\n"
                                "subsection Loads\n set Load factor = 1, 1.5\nend\n" +
                   quiet_output(),
                 "interface_growth"),
               sink);
  const bool         accepted = growth.run_growth();
  std::cout << "growth on interface 2 accepted: " << yes(accepted) << std::endl;
  const auto &steps = growth.growth();
  if (steps.empty())
    return 0;
  const double G2_at_1 = steps[0].tips[1].G;
  const double onset   = std::sqrt(1e-5 / G2_at_1);
  bool         started = false, sigma_still = true, steady = true;
  double       G_grown = 0, lambda_grown = 0;
  for (const GrowthStep &step : steps)
    {
      const GrowthTip &t1 = step.tips[0], &t2 = step.tips[1];
      sigma_still =
        sigma_still && t1.s == 8 && t1.point[1] == 1 && !t1.critical;
      if (step.kind == "growth")
        {
          started = started || std::abs(step.load_factor / onset - 1) < 1e-9;
          steady =
            steady &&
            std::abs(t2.G / (step.load_factor * step.load_factor * G2_at_1) -
                     1) < 1e-6;
          if (t2.s == 21)
            G_grown = t2.G, lambda_grown = step.load_factor;
        }
    }
  std::cout << "tip 2 (interface 2) grows from the exact onset "
               "sqrt(G_c / G_2(1)): "
            << yes(started) << std::endl;
  std::cout << "tip 2 reaches the tough part at x = 21 and stays on its "
               "interface: "
            << yes(steps.back().tips[1].s == 21 &&
                   steps.back().tips[1].point[1] == 2)
            << std::endl;
  std::cout << "tip 1 on Sigma stays at x = 8, below critical: "
            << yes(sigma_still) << std::endl;
  std::cout << "G of tip 2 independent of its crack's length (steady state, "
               "1e-6): "
            << yes(steady) << std::endl;

  // The grown state against the static scene with the moved crack.
  Study static_run(
    scene_from_string(base +
                        "subsection Geometry\n"
                        " set Interfaces above Sigma = 2: 0, 21\nend\n"
                        "subsection Fracture\n set Energy release rate = true\n"
                        "end\n" +
                        quiet_output(),
                      "interface_growth"),
    sink);
  const bool   solved = static_run.run();
  const auto  &tips   = static_run.records().back().release;
  const double G2_static =
    solved && tips.size() == 2 ? tips[1].G : std::nan("");
  std::cout << "the grown state is the static equilibrium of the moved crack "
               "(G_2 / lambda^2, 1e-8): "
            << yes(lambda_grown > 0 &&
                   std::abs(
                     G_grown / (lambda_grown * lambda_grown) / G2_static - 1) <
                     1e-8)
            << std::endl;
}
