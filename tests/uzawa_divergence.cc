// The Uzawa step above the stability threshold is recognised as divergence.
//
// The iteration matrix of the multipliers is I - theta S with
// S = D^-1 C A^-1 C^T symmetric positive semidefinite in the D inner
// product; for theta > 2 / lambda_max(S) the error along the top eigenvector
// grows geometrically. theta = 1000 is far above the threshold (about 70
// for these moduli), so the solver must stop with diverged = true long
// before the iteration limit, and report that the run did not converge.

#include <bilayer/parameters.h>
#include <bilayer/study.h>

#include <iostream>

using namespace dealii;
using namespace bilayer;

int
main()
{
  Study       study(scene_from_string(
                "subsection Mesh\n set Cells along Sigma = 8\nend\n"
                      "subsection Loads\n set Constants = c = 1e-3*mu1\n"
                      " subsection Layer 1\n"
                      "  set Traction on bottom side = 0; c*x\n"
                      "  set Traction on top side = 0; -c*x\n end\nend\n"
                      "subsection Solver\n set Uzawa step theta = 1000\n"
                      " set Maximum iterations = 100000\nend\n"
                      "subsection Output\n set Output directory = results\n"
                      " set Write VTU = false\n set Write interface CSV = false\n"
                      " set Terminal output = checks\nend\n",
                "divergence"),
              std::cout);
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
}
