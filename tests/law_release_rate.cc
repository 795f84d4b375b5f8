// The energy release rate with the laws of issue 32 against the
// fourth-order central difference of the program's own energy in the crack
// length (docs/fracture.md, "Interface cracks" and the verification of
// section 5): materials that differ across Sigma, and an orthotropic layer
// at 30 degrees. (A body force alone: tests/volume_load_release_rate.cc,
// case (a), by the same method.)
//
// The method of tests/volume_load_release_rate.cc: the rectangle (-1, 1)^2,
// Sigma y = 0, the crack (-0.5, 0.5); its tip at x_t = 0.5 grows towards
// +x; Fracture/Support radius R = 0.3. Q2 on uniform cells of h = 1/32,
// written as Mesh/Mesh files; Pi(t) is the energy of the scene whose mesh
// nodes move by x -> x + t psi(|x - x_t|) e_x (psi the cut-off of
// docs/fracture.md §1 with this R) and whose crack ends at x_t + t. Each
// subdomain keeps its material under the motion (the nodes move along
// Sigma, not across it). G of the unmoved mesh against FD4 = -(8 (Pi(d) -
// Pi(-d)) - (Pi(2d) - Pi(-2d))) / 12d, d = R/50, within 1e-3 relative and
// within 3 |FD4 - FD2| + (h/R)^2 G / 4 (FD2 = -(Pi(2d) - Pi(-2d)) / 4d;
// the nodal motion is the vertex interpolant of theta).
//
// (a) Per-side materials, two layers, clamped left and right: layer 1
//     isotropic E = 200, nu = 0.28 on Omega- and E = 70, nu = 0.35 on
//     Omega+ (an interface crack between dissimilar materials); layer 2
//     isotropic E = 112, nu = 0.32 on Omega- and orthotropic (E_1 = 140,
//     E_2 = 10, E_3 = 12, nu_12 = 0.3, nu_13 = 0.28, nu_23 = 0.45,
//     G_12 = 5) at 60 degrees on Omega+; all plane strain. Tractions on
//     layer 1: top (0.05, 0.1), bottom (0, -0.1): the crack opens, in mixed
//     mode.
// (b) One orthotropic layer at 30 degrees, plane stress (the constants of
//     (a)'s orthotropic side), clamped left and right, tractions top
//     (0, 0.1) and bottom (0, -0.1): the material axes turned against the
//     crack give a mixed-mode opening.
// The numbers go to measured.txt in the test's directory.

#include <string>

#include "release_rate_difference.h"

namespace
{
  const std::string orthotropic_constants =
    "set E_1 = 140\n set E_2 = 10\n set E_3 = 12\n set nu_12 = 0.3\n"
    " set nu_13 = 0.28\n set nu_23 = 0.45\n set G_12 = 5\n";
} // namespace


int
main()
{
  release_rate_difference::start_measured();
  const release_rate_difference::Difference fd{
    "law_release_rate", " set Clamped sides = left, right\n"};
  fd.compare("materials per side, two layers",
             "subsection Materials\n subsection Layer 1\n"
             "  subsection Omega-\n   set Young's modulus = 200\n"
             "   set Poisson's ratio = 0.28\n  end\n"
             "  subsection Omega+\n   set Young's modulus = 70\n"
             "   set Poisson's ratio = 0.35\n  end\n end\n"
             " subsection Layer 2\n"
             "  subsection Omega-\n   set Young's modulus = 112\n"
             "   set Poisson's ratio = 0.32\n  end\n"
             "  subsection Omega+\n   set Law = orthotropic\n " +
               orthotropic_constants +
               "   set Orientation angle = 60\n  end\n end\nend\n"
               "subsection Loads\n subsection Layer 1\n"
               "  set Traction on top side = 0.05; 0.1\n"
               "  set Traction on bottom side = 0; -0.1\n end\nend\n");
  fd.compare("orthotropic layer at 30 degrees, plane stress",
             "subsection Materials\n set Number of layers = 1\n"
             " subsection Layer 1\n  set Law = orthotropic\n"
             "  set Plane state = plane stress\n " +
               orthotropic_constants +
               "  set Orientation angle = 30\n end\nend\n"
               "subsection Loads\n subsection Layer 1\n"
               "  set Traction on top side = 0; 0.1\n"
               "  set Traction on bottom side = 0; -0.1\n end\nend\n");
}
