// The energy release rate with Tresca friction on the crack faces against
// the fourth-order central difference in the crack length of the program's
// own J = Pi + int_{gamma_c} g |[u].tau| ds (docs/fracture.md §6: with
// friction G is -dJ/dl, the energy that flows into the tip, not -dPi/dl).
//
// The method of tests/law_release_rate.cc (tests/release_rate_difference.h):
// the rectangle (-1, 1)^2, Sigma y = 0, the crack (-0.5, 0.5) whose tip at
// x_t = 0.5 grows towards +x, Fracture/Support radius R = 0.3, Q2 on
// uniform cells of h = 1/32; J(t) of the scene whose mesh nodes move by
// x -> x + t psi(|x - x_t|) e_x and whose crack ends at x_t + t. G of the
// unmoved mesh against FD4 within 1e-3 relative and within
// 3 |FD4 - FD2| + (h/R)^2 G / 4.
//
// One layer (E = 1, nu = 0.3, plane strain) clamped left and right,
// tractions (0.1, -0.05) on the top and (-0.1, 0.05) on the bottom side: a
// shear that slides the faces, pressed together, against a constant Tresca
// bound g = 0.003 (on 64 cells 28 crack nodes slip, 35 stick; G is 0.14 of
// the frictionless one). Where
// the bound did not enter J, or the friction term not G, the two would
// differ by the rate of the frictional dissipation.
// The numbers go to measured.txt in the test's directory.

#include <string>

#include "release_rate_difference.h"


int
main()
{
  release_rate_difference::start_measured();
  const release_rate_difference::Difference fd{
    "friction_release_rate", " set Clamped sides = left, right\n"};
  fd.compare("Tresca g = 0.003, sheared closed crack",
             "subsection Materials\n set Number of layers = 1\n"
             " subsection Layer 1\n  set Young's modulus = 1\n"
             "  set Poisson's ratio = 0.3\n end\nend\n"
             "subsection Loads\n subsection Layer 1\n"
             "  set Traction on top side = 0.1; -0.05\n"
             "  set Traction on bottom side = -0.1; 0.05\n end\nend\n"
             "subsection Contact\n set Friction = tresca\n"
             " set Friction bound = 0.003\nend\n");
}
