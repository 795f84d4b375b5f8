// The accelerated solver (FISTA momentum with gradient restart on the same
// projected dual step) solves the same discrete problem as the paper's
// Uzawa iteration: both converge to the unique saddle point, so with a
// tight relative tolerance their solutions, energies and multipliers agree
// up to the iteration error, and the acceleration needs fewer subdomain
// solves. Example 1 on 8 quadrilaterals along Sigma and on the paper's
// mesh1 (P1 triangles), theta = auto for both.

#include <bilayer/parameters.h>
#include <bilayer/study.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

int
main()
{
  const std::string meshes[] = {" set Cells along Sigma = 8\n",
                                " set Mesh files = " + std::string(SOURCE_DIR) +
                                  "/../meshes/table1_P12_M32_{side}.msh\n"};
  for (const auto &mesh : meshes)
    {
      std::array<std::unique_ptr<Study>, 2> studies;
      const char        *methods[] = {"uzawa", "accelerated"};
      std::ostringstream quiet;
      for (unsigned int m = 0; m < 2; ++m)
        {
          studies[m] = std::make_unique<Study>(
            scene_from_string(
              "subsection Mesh\n" + mesh +
                "end\n"
                "subsection Loads\n set Constants = c = 1e-3*mu1\n"
                " subsection Layer 1\n"
                "  set Traction on bottom side = 0; c*x\n"
                "  set Traction on top side = 0; -c*x\n end\nend\n"
                "subsection Solver\n set Method = " +
                methods[m] +
                "\n set Uzawa step theta = auto\n"
                " set Stopping rule = relative\n set Tolerance = 1e-11\nend\n"
                "subsection Output\n set Output directory = results\n"
                " set Write VTU = false\n set Write interface CSV = false\n"
                " set Terminal output = checks\nend\n",
              methods[m]),
            quiet);
          studies[m]->run_cycle(0);
        }
      const auto &a          = studies[0]->records().back();
      const auto &b          = studies[1]->records().back();
      double      difference = 0, size = 0;
      for (unsigned int s = 0; s < 4; ++s)
        {
          Vector<double> d = studies[1]->solutions()[s];
          d -= studies[0]->solutions()[s];
          difference = std::max(difference, d.linfty_norm());
          size       = std::max(size, studies[0]->solutions()[s].linfty_norm());
        }
      BlockVector<double> dmu = studies[1]->multipliers();
      dmu -= studies[0]->multipliers();
      std::cout << (mesh.find("msh") != std::string::npos ? "mesh1" : "quads")
                << ": both accepted: " << yes(a.accepted() && b.accepted())
                << ", displacements agree to 1e-7: "
                << yes(difference <= 1e-7 * size)
                << ", multipliers agree to 1e-6: "
                << yes(dmu.linfty_norm() <=
                       1e-6 * studies[0]->multipliers().linfty_norm())
                << ", energies agree to 1e-9: "
                << yes(std::abs(a.energy - b.energy) <=
                       1e-9 * std::abs(a.energy))
                << ", fewer subdomain solves: "
                << yes(b.result.subdomain_solves < a.result.subdomain_solves)
                << std::endl;
    }
}
