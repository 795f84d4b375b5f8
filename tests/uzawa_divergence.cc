// The Uzawa step above the stability threshold is recognised as divergence.
//
// The iteration matrix of the multipliers is I - theta S with
// S = D^-1 C A^-1 C^T symmetric positive semidefinite in the D inner
// product; for theta > 2 / lambda_max(S) the error along the top eigenvector
// grows geometrically. theta = 1000 is far above the threshold (about 70
// for these moduli), so the solver must stop with diverged = true long
// before the iteration limit, and report that the run did not converge.
// Its message suggests a safe step (0.9 * 2 / lambda_max from a power
// iteration): a run with that step converges.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <iostream>
#include <sstream>
#include <string>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  std::string
  scene(const std::string &theta)
  {
    return "subsection Mesh\n set Cells along Sigma = 8\nend\n" +
           std::string(example1_loads) +
           "subsection Solver\n set Uzawa step theta = " + theta +
           "\n"
           " set Maximum iterations = 100000\nend\n"
           "subsection Output\n set Output directory = results\n"
           " set Write VTU = false\n set Write interface CSV = false\n"
           " set Terminal output = checks\nend\n";
  }
} // namespace

int
main()
{
  std::ostringstream quiet;
  Study       study(scene_from_string(scene("1000"), "divergence"), quiet);
  const bool  ok = study.run();
  const auto &r  = study.records().back().result;
  std::cout << "run reported as failed: " << (!ok ? "yes" : "NO") << std::endl
            << "diverged: " << (r.diverged ? "yes" : "NO") << std::endl
            << "stopped within 200 iterations: "
            << (r.iterations < 200 ? "yes" : "NO") << std::endl
            << "message names the step parameter: "
            << (r.message.find("Solver/Uzawa step theta") != std::string::npos ?
                  "yes" :
                  "NO")
            << std::endl;
  const std::string key = "estimated safe step: theta <= ";
  const auto        at  = r.message.find(key);
  const double      safe =
    at == std::string::npos ? 0. : std::stod(r.message.substr(at + key.size()));
  std::cout << "message gives a safe step below the divergent one: "
            << (safe > 0 && safe < 1000 ? "yes" : "NO") << std::endl;
  if (safe > 0)
    {
      std::ostringstream text;
      text << safe;
      Study second(scene_from_string(scene(text.str()), "safe"), quiet);
      std::cout << "a run with the safe step converges and passes its checks: "
                << (second.run() ? "yes" : "NO") << std::endl;
    }
}
