// Scale invariance of the error estimator and of adaptive refinement.
//
// The problem is linear in the loads and its constraints are positively
// homogeneous (non-penetration, gluing): loads times c > 0 give the
// solution times c, the energy times c^2 and the error indicators times c.
// For c a power of two every floating point operation of the solve scales
// exactly (no rounding changes), so the adaptive meshes must be the same
// cell for cell, eta must scale by exactly c and Pi by exactly c^2, at any
// magnitude that double precision represents: here c = 2^-60, 1 and 2^80
// on Example 1 (the multiplier bound p scaled along, being a traction).
// Single precision indicators overflowed (eta = inf) or lost the ordering
// of small cells at such loads.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  struct Run
  {
    bool                      accepted = false;
    std::vector<unsigned int> cells, dofs;
    std::vector<double>       eta, energy;
  };

  Run
  run(const int exponent)
  {
    const double       c = std::ldexp(1., exponent);
    std::ostringstream s;
    s << std::setprecision(17)
      << "subsection Mesh\n set Cells along Sigma = 8\n"
         " set Refinement = adaptive\n set Number of cycles = 5\nend\n"
         "subsection Loads\n set Constants = c = 1e-3*mu1*"
      << c
      << "\n subsection Layer 1\n"
         "  set Traction on bottom side = 0; c*x\n"
         "  set Traction on top side = 0; -c*x\n end\nend\n"
         "subsection Contact\n set Multiplier bound p = "
      << 1e7 * c
      << "\nend\n"
         "subsection Solver\n set Method = active set\n"
         " set Tolerance = 1e-10\nend\n"
         "subsection Output\n set Output directory = results\n"
         " set Write VTU = false\n set Write interface CSV = false\n"
         " set Terminal output = checks\nend\n";
    std::ostringstream sink;
    Study study(scene_from_string(s.str(), "scale_invariance"), sink);
    Run   r;
    r.accepted = study.run();
    for (const auto &record : study.records())
      {
        r.cells.push_back(record.minus.cells + record.plus.cells);
        r.dofs.push_back(record.dofs);
        r.eta.push_back(record.eta);
        r.energy.push_back(record.energy);
      }
    return r;
  }

} // namespace


int
main()
{
  const Run one = run(0);
  std::cout << "load factor 1: accepted, 5 cycles, the meshes refined: "
            << yes(one.accepted && one.cells.size() == 5 &&
                   one.cells.back() > one.cells.front())
            << std::endl;
  for (const int exponent : {-60, 80})
    {
      const Run    r      = run(exponent);
      const double c      = std::ldexp(1., exponent);
      bool         finite = true, eta_exact = true, energy_exact = true;
      for (unsigned int k = 0; k < r.eta.size() && k < one.eta.size(); ++k)
        {
          finite       = finite && std::isfinite(r.eta[k]) && r.eta[k] > 0;
          eta_exact    = eta_exact && r.eta[k] == c * one.eta[k];
          energy_exact = energy_exact && r.energy[k] == c * c * one.energy[k];
        }
      std::cout << "load factor 2^" << exponent
                << ": accepted: " << yes(r.accepted) << std::endl
                << "load factor 2^" << exponent
                << ": the same cells and dofs at every cycle: "
                << yes(r.cells == one.cells && r.dofs == one.dofs) << std::endl
                << "load factor 2^" << exponent << ": eta finite and exactly 2^"
                << exponent
                << " times that of load factor 1: " << yes(finite && eta_exact)
                << std::endl
                << "load factor 2^" << exponent << ": Pi exactly 2^"
                << 2 * exponent
                << " times that of load factor 1: " << yes(energy_exact)
                << std::endl;
    }
}
