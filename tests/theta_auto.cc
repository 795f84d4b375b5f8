// theta = auto and the predicted stability threshold of the Uzawa step.
//
// For theta < 2 / lambda_max(S), S = D^-1 C A^-1 C^T symmetric positive
// semidefinite in the D inner product, the projected step is
// non-expansive, so the paper's iteration converges: the predicted
// threshold 2 / lambda_max(S) (power iteration) is a lower bound of the
// observed divergence threshold, and theta = auto (0.9 of it) converges
// without tuning. Near the solution the projection holds the open crack
// nodes at mu_c = 0, so the final phase is governed by S restricted to the
// free multipliers; its threshold must be close (within 10 %) to the
// observed one. The observed threshold is located by bisection to +-0.5 on
// the paper's mesh1 (P/M = 12/32).

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  CycleRecord
  run(const std::string &theta)
  {
    std::ostringstream quiet;
    Study              study(scene_from_string(
                  "subsection Mesh\n set Mesh files = " +
                    std::string(SOURCE_DIR) +
                    "/../meshes/table1_P12_M32_{side}.msh\nend\n" +
                    std::string(example1_loads) +
                    "subsection Solver\n set Uzawa step theta = " + theta +
                    "\nend\n"
                                 "subsection Output\n set Output directory = results\n"
                                 " set Write VTU = false\n set Write interface CSV = false\n"
                                 " set Terminal output = checks\nend\n",
                  "auto"),
                quiet);
    return study.run_cycle(0);
  }
} // namespace

int
main()
{
  const CycleRecord automatic   = run("auto");
  const double      predicted   = automatic.result.predicted_threshold;
  const double      at_solution = automatic.result.threshold_at_solution;
  std::cout << "theta = auto converges: " << yes(automatic.accepted())
            << std::endl
            << "theta = 0.9 * predicted threshold: "
            << yes(std::abs(automatic.theta - 0.9 * predicted) <
                   1e-12 * predicted)
            << std::endl;

  double     lo = automatic.theta, hi = 2 * predicted;
  const bool diverges_at_hi = run(std::to_string(hi)).result.diverged;
  std::cout << "theta = 2 * predicted threshold diverges: "
            << yes(diverges_at_hi) << std::endl;
  while (hi - lo > 1.0)
    {
      const double mid                                      = 0.5 * (lo + hi);
      (run(std::to_string(mid)).result.converged ? lo : hi) = mid;
    }
  const double observed = 0.5 * (lo + hi);
  if (getenv("BILAYER_TEST_DIAGNOSTICS"))
    std::cerr << "predicted " << predicted << ", at solution " << at_solution
              << ", observed " << observed << std::endl;
  std::cout << "predicted threshold <= observed threshold + 0.5: "
            << yes(predicted <= observed + 0.5) << std::endl
            << "threshold at the solution within 10 % of the observed: "
            << yes(std::abs(at_solution - observed) <= 0.1 * observed)
            << std::endl;
}
