// The divergence test of the accelerated method on a converging iteration
// whose increments grow (tests/active_set_cycling.prm: contrast 2e7, a
// nearly singular dual operator). With theta = auto the step is below
// 1/lambda_max, so the accelerated projected gradient iteration converges
// (its dual objective at the rate 1/k^2); along the flat directions the
// multipliers drift with growing momentum, and their increments grow by
// more than the growth factor 1000 over the smallest one, while the KKT
// residual keeps falling. Such a run must not be reported as divergent:
// after 30 000 iterations it stops at the iteration limit, not diverged,
// with a KKT residual below half of that after 3 000 iterations.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "verdict.h"

using namespace bilayer;

namespace
{
  SolverResult
  run(const unsigned int iterations)
  {
    std::ifstream      in(std::string(SOURCE_DIR) + "/active_set_cycling.prm");
    std::ostringstream text;
    text << in.rdbuf()
         << "subsection Solver\n set Method = accelerated\n"
            " set Uzawa step theta = auto\n set Maximum iterations = "
         << iterations << "\nend\n";
    std::ostringstream quiet;
    Study              study(scene_from_string(text.str(), "drift"), quiet);
    study.run();
    return study.records().back().result;
  }
} // namespace


int
main()
{
  const SolverResult shorter = run(3000);
  const SolverResult longer  = run(30000);
  std::cout << "not diverged: " << yes(!shorter.diverged && !longer.diverged)
            << std::endl
            << "stopped at the iteration limit: "
            << yes(!longer.converged && longer.iterations >= 30000) << std::endl
            << "KKT residual after 30000 iterations below half of that after "
               "3000: "
            << yes(longer.stopping_value < 0.5 * shorter.stopping_value)
            << std::endl;
}
