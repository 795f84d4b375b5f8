// G at crack tips between two shallow arcs of one circle, at any rotation.
//
// tests/shallow_arcs.geo: Sigma the arc of radius 26 and chord 3 in three
// arcs, the crack the middle one, rotated by 0, 17, 61, 137 degrees; the
// meshes tests/shallow_arcs_ROT.msh are built from it by gmsh with the node
// coordinates written to 11 digits, as other mesh generators do. The
// circle fitted to the nodes of one such arc (chord 1) has its centre
// determined only to about (node error) R^2 / chord^2, far more than the
// geometric tolerance, while tangents and curvatures at the junction agree
// closely: the tips are smooth points of Sigma and G is defined. The scene
// and its loads (radial tractions on the layers' outer arcs, the radial ends
// clamped) are invariant under the rotation, so G is the same at every
// rotation and at both tips (mirror symmetry). With the crack the chord
// (shallow_arcs_c17.msh, corner = 1), the crack meets Sigma at an angle
// a / 3 = 0.019 at each tip: G is not defined there.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "verdict.h"

using namespace bilayer;

namespace
{

  std::vector<EnergyReleaseRate>
  release(const std::string &mesh, bool &accepted)
  {
    std::ostringstream scene, sink;
    scene << "subsection Geometry\n set Gmsh file = " << SOURCE_DIR << "/"
          << mesh << "\n set Clamped sides = left, right\nend\n"
          << "subsection Mesh\n set Polynomial degree of layer 1 = 2\n"
          << " set Polynomial degree of layer 2 = 2\nend\n"
          << "subsection Loads\n set Constants = q = 1e-3*mu1\n"
          << " subsection Layer 1\n"
          << "  set Traction on inner = -q*x/sqrt(x*x + y*y); "
             "-q*y/sqrt(x*x + y*y)\n"
          << "  set Traction on outer = q*x/sqrt(x*x + y*y); "
             "q*y/sqrt(x*x + y*y)\n"
          << " end\nend\n"
          << "subsection Solver\n set Method = active set\n"
          << " set Tolerance = 1e-10\nend\n"
          << "subsection Output\n set Output directory = results\n"
          << " set Write VTU = false\n set Write interface CSV = false\n"
          << " set Terminal output = checks\nend\n";
    Study study(scene_from_string(scene.str(), "shallow_arcs"), sink);
    accepted = study.run();
    return study.records().back().release;
  }
} // namespace

int
main()
{
  std::vector<double> G;
  bool                all_defined = true, all_accepted = true;
  for (const int rot : {0, 17, 61, 137})
    {
      bool       accepted = false;
      const auto tips =
        release("shallow_arcs_" + std::to_string(rot) + ".msh", accepted);
      all_accepted = all_accepted && accepted && tips.size() == 2;
      for (const auto &tip : tips)
        {
          all_defined = all_defined && tip.tip.defined() &&
                        tip.unresolved.empty() && std::isfinite(tip.G);
          G.push_back(tip.G);
        }
    }
  double spread = 0;
  for (const double g : G)
    spread = std::max(spread, std::abs(g - G[0]));
  std::cout << "two arcs of one circle: runs accepted, two tips: "
            << yes(all_accepted) << std::endl
            << "two arcs of one circle: G defined at both tips at every "
               "rotation: "
            << yes(all_defined) << std::endl
            << "two arcs of one circle: G > 0 and equal to 1e-6 relative at "
               "every rotation and tip: "
            << yes(!G.empty() && G[0] > 0 && spread <= 1e-6 * G[0])
            << std::endl;
  bool       accepted = false;
  const auto tips     = release("shallow_arcs_c17.msh", accepted);
  bool       corners  = tips.size() == 2;
  for (const auto &tip : tips)
    corners = corners && !tip.tip.defined() && std::isnan(tip.G);
  std::cout << "arcs and a chord meeting at an angle: G not defined at both "
               "tips: "
            << yes(corners) << std::endl;
}
