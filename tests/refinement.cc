// Uniform refinement of Example 1 (three cycles, 8, 16, 32 cells along
// Sigma, Q1 and P1).
//
// The discrete spaces are nested, and for degree 1 so are the discrete
// constraint sets (a trace jump that is piecewise linear and >= 0 at the
// coarse nodes is >= 0 at the new midpoints), so the minimal energy Pi_h
// cannot increase under refinement; for the singular solution it decreases
// strictly, with decreasing decrements (Pi_h -> Pi). The mesh data of the
// table follow from the construction: h halves, P = 8 2^k + 1.
// The lines "energy Pi" and "largest crack opening" that Study prints are
// the numbers of tests/prm_references.cc (scenes "refinement, ..."), which
// checks that this .output holds them.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iostream>

using namespace dealii;
using namespace bilayer;

int
main()
{
  for (const std::string shape : {"quadrilaterals", "triangles"})
    {
      std::cout << shape << ":" << std::endl;
      Study study(scene_from_string(
                    "subsection Mesh\n set Element shape = " + shape +
                      "\n set Cells along Sigma = 8\n"
                      " set Number of cycles = 3\nend\n"
                      "subsection Loads\n set Constants = c = 1e-3*mu1\n"
                      " subsection Layer 1\n"
                      "  set Traction on bottom side = 0; c*x\n"
                      "  set Traction on top side = 0; -c*x\n end\nend\n"
                      "subsection Solver\n set Stopping rule = relative\n"
                      " set Tolerance = 1e-10\nend\n"
                      "subsection Output\n set Output directory = results\n"
                      " set Write VTU = false\n"
                      " set Terminal output = checks\nend\n",
                    "refinement"),
                  std::cout);
      study.run();
      const auto &r = study.records();
      std::cout << "energy decreases: "
                << (r[1].energy < r[0].energy && r[2].energy < r[1].energy ?
                      "yes" :
                      "NO")
                << std::endl
                << "energy decrements decrease: "
                << (r[1].energy - r[2].energy < r[0].energy - r[1].energy ?
                      "yes" :
                      "NO")
                << std::endl;
      for (const auto &c : r)
        std::cout << "cycle " << c.cycle << ": P = " << c.P
                  << ", h-max / h-max(0) = "
                  << std::round(1000 * c.minus.h_max / r[0].minus.h_max) / 1000
                  << std::endl;
    }
}
