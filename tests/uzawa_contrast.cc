// Uzawa with theta = auto under strong material contrast.
//
// With layer 2 softer than layer 1 by 1e5, the dual operator S = D^-1 C
// A^-1 C^T has eigenvalues of the order of the compliance of layer 2 on the
// gluing multipliers lambda- and lambda+ and of the order of the compliance
// of layer 1 on mu_1: its condition number grows with the contrast, and the
// constant step 0.9 * 2 / lambda_max needs of the order of the condition
// number iterations (more than 200000 here). The adaptive steps of theta =
// auto (Barzilai-Borwein with a non-monotone line search) must reach the
// KKT tolerance 1e-9 within 20000 iterations and agree with the active-set
// solution: the saddle point is unique, so the energies agree up to the
// iteration error (1e-8 relative).
//
// Example 1 (16 quadrilaterals along Sigma), Young's modulus of layer 2
// 2e-3 against 200.

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
  run(const std::string &solver)
  {
    std::ostringstream quiet;
    Study              study(scene_from_string(
                  std::string(example1_loads) +
                    "subsection Mesh\n set Cells along Sigma = 16\nend\n"
                                 "subsection Materials\n subsection Layer 1\n"
                                 "  set Young's modulus = 200\n end\n"
                                 " subsection Layer 2\n  set Young's modulus = 2e-3\n end\n"
                                 "end\n"
                                 "subsection Solver\n" +
                    solver +
                    " set Stopping rule = kkt\n set Tolerance = 1e-9\n"
                                 " set Maximum iterations = 20000\nend\n"
                                 "subsection Output\n set Output directory = results\n"
                                 " set Write VTU = false\n set Write interface CSV = false\n"
                                 " set Terminal output = checks\nend\n",
                  "contrast"),
                quiet);
    return study.run_cycle(0);
  }
} // namespace

int
main()
{
  const CycleRecord uzawa =
    run(" set Method = uzawa\n set Uzawa step theta = auto\n");
  const CycleRecord active_set = run(" set Method = active set\n");
  const double      difference =
    std::abs(uzawa.energy - active_set.energy) / std::abs(active_set.energy);
  if (getenv("BILAYER_TEST_DIAGNOSTICS"))
    std::cerr << "uzawa: " << uzawa.result.iterations << " iterations, "
              << uzawa.result.message << "; energy difference " << difference
              << std::endl;
  std::cout << "uzawa, theta = auto, converges within 20000 iterations: "
            << yes(uzawa.result.converged && !uzawa.result.diverged)
            << std::endl
            << "active set converges: " << yes(active_set.result.converged)
            << std::endl
            << "energies agree to 1e-8: " << yes(difference < 1e-8)
            << std::endl;
}
