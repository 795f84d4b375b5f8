// A corner of a polygonal Sigma inside the crack, the turn of Sigma there
// `turn` degrees (a roof: Sigma rises from the left boundary to the corner
// at the origin and falls to the right boundary, each arm at turn/2 to the
// horizontal):
//
//   Omega-: below Sigma, down to y = -2;  Omega+: above Sigma, up to y = 1
//   Sigma:  (-1, -t) - (-0.5, -t/2) - (0, 0) - (0.5, -t/2) - (1, -t),
//           t = tan(turn/2), four segments; the crack the two middle ones
//           (a crack node at the corner (0, 0); their outer ends are
//           collinear junctions, no corners).
//
// Mesh: transfinite quadrilaterals, n cells along each segment of Sigma
// (matching traces), n cells across each subdomain. The meshes
// tests/corner_contact_TURN.msh are built from it by
//
//   gmsh -2 -format msh2 -setnumber turn TURN corner_contact.geo \
//        -o corner_contact_TURN.msh
//
// for TURN = 20, 45, 90.

Mesh.MshFileVersion = 2.2;

If (!Exists(turn))
  turn = 45;
EndIf
n  = 2;
t  = Tan(turn * Pi / 360);
lc = 1;

Point(1) = {-1, -2, 0, lc};
Point(2) = {1, -2, 0, lc};
Point(3) = {1, 1, 0, lc};
Point(4) = {-1, 1, 0, lc};
Point(5) = {-1, -t, 0, lc};
Point(6) = {-0.5, -t / 2, 0, lc};
Point(7) = {0, 0, 0, lc};
Point(8) = {0.5, -t / 2, 0, lc};
Point(9) = {1, -t, 0, lc};
Line(1) = {5, 6};   // Sigma
Line(2) = {6, 7};   // crack
Line(3) = {7, 8};   // crack
Line(4) = {8, 9};   // Sigma
Line(5) = {1, 2};   // bottom
Line(6) = {2, 9};   // right, Omega-
Line(7) = {9, 3};   // right, Omega+
Line(8) = {3, 4};   // top
Line(9) = {4, 5};   // left, Omega+
Line(10) = {5, 1};  // left, Omega-
Curve Loop(1) = {5, 6, -4, -3, -2, -1, 10};
Plane Surface(1) = {1};
Curve Loop(2) = {1, 2, 3, 4, 7, 8, 9};
Plane Surface(2) = {2};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Curve{5, 8} = 4 * n + 1;
Transfinite Curve{6, 7, 9, 10} = n + 1;
Transfinite Surface{1} = {1, 2, 9, 5};
Transfinite Surface{2} = {5, 9, 3, 4};
Recombine Surface{1, 2};
Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
Physical Curve("Sigma") = {1, 4};
Physical Curve("crack") = {2, 3};
Physical Curve("bottom") = {5};
Physical Curve("right") = {6, 7};
Physical Curve("top") = {8};
Physical Curve("left") = {9, 10};
