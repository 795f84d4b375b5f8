// The energy release rate with thermal loads (issue 32; docs/fracture.md,
// "Body forces and eigenstrains": a temperature change enters as the plane
// eigenstrain of the law, so G has the eigenstrain's volume terms) against
// finite differences of the energy, as tests/volume_load_release_rate.cc
// (whose scenes, motion and tolerances these are):
//
// The rectangle (-1, 1)^2, Sigma y = 0, the crack (-0.5, 0.5); its tip at
// x_t = 0.5 grows towards +x; Fracture/Support radius R = 0.3. Q2, uniform
// cells of h = 1/32, written as Mesh/Mesh files. Pi(t) is the energy of the
// scene whose mesh nodes are moved by x -> x + t psi(|x - x_t|) e_x and whose
// crack ends at x_t + t, the loads fixed in space. G is compared with the
// fourth-order central difference FD4 = -(8 (Pi(d) - Pi(-d)) - (Pi(2d) -
// Pi(-2d))) / 12d, d = R / 50, and FD2 = -(Pi(2d) - Pi(-2d)) / 4d:
// |FD4 - G| <= 3 |FD4 - FD2| + (h/R)^2 G / 4, and 1e-3 relative.
//
// (a) A thermal load alone: one layer (E = 200, nu = 0.28, alpha = 1e-5,
//     plane strain), all sides clamped (zero displacement), dT = -100 (2 +
//     x): a non-uniform cooling that the clamps resist, which opens the
//     crack; the plane eigenstrain (1 + nu) alpha dT I has the gradient
//     -(1 + nu) alpha 100 I e_x, so sigma : ((grad eps*) theta) enters G.
// (b) A thermally loaded bimaterial: one layer whose sides differ across
//     Sigma (Materials/Layer 1/Omega+: E = 70, nu = 0.33, alpha = 2.3e-5;
//     Omega-: E = 200, nu = 0.28, alpha = 1e-5), all sides clamped, a
//     uniform cooling dT = -150: each side pulls with its own (1 + nu)
//     alpha dT, the mismatch loads the interface crack.
// (c) As (b) in plane stress with the orthotropic Omega+ (E_1 = 140, E_2 =
//     10, nu_12 = 0.3, G_12 = 5, alpha_1 = -5e-7, alpha_2 = 3e-5, at 30
//     degrees): the rotated thermal strain of plane stress.

#include <string>

#include "release_rate_difference.h"


int
main()
{
  release_rate_difference::start_measured();
  const release_rate_difference::Difference fd{"thermal_release_rate"};
  const std::string                         clamped = "subsection Geometry\n"
                                                      " set Clamped sides = left, right, bottom, top\n"
                                                      "end\n";
  fd.compare(
    "thermal load alone, one layer",
    "subsection Materials\n set Number of layers = 1\n"
    " subsection Layer 1\n  set Thermal expansion = 1e-5\n end\nend\n" +
      clamped +
      "subsection Loads\n set Temperature change = -100*(2 + x)\nend\n");
  const std::string bimaterial =
    "subsection Materials\n set Number of layers = 1\n"
    " subsection Layer 1\n  set Young's modulus = 200\n"
    "  set Poisson's ratio = 0.28\n  set Thermal expansion = 1e-5\n";
  fd.compare("thermal bimaterial, plane strain",
             bimaterial +
               "  subsection Omega+\n   set Young's modulus = 70\n"
               "   set Poisson's ratio = 0.33\n   set Thermal expansion = "
               "2.3e-5\n  end\n end\nend\n" +
               clamped +
               "subsection Loads\n set Temperature change = -150\nend\n");
  fd.compare(
    "thermal bimaterial, plane stress, orthotropic Omega+ at 30 degrees",
    bimaterial +
      "  set Plane state = plane stress\n"
      "  subsection Omega+\n   set Law = orthotropic\n"
      "   set E_1 = 140\n   set E_2 = 10\n   set nu_12 = 0.3\n"
      "   set G_12 = 5\n   set Orientation angle = 30\n"
      "   set Thermal expansion = -5e-7, 3e-5, 3e-5\n  end\n end\nend\n" +
      clamped + "subsection Loads\n set Temperature change = -150\nend\n");
}
