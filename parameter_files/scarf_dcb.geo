// A double cantilever beam whose upper arm is a scarf joint: a carbon/epoxy
// 0 ply on the left, an aluminium part on the right, joined along the
// oblique line from (21, 0) to (25, 4); the delamination (0, 20) on Sigma
// (y = 0) runs from the free left end to 1 before the foot of the scarf
// (parameter_files/scarf_dcb.prm; tests/gmsh_plies.cc).
//
//   the beam (0, 60) x (-4, 4); Omega- the lower arm (-4 < y < 0), Omega+
//   the upper arm (0 < y < 4) in two surfaces: "carbon" left of the scarf,
//   "aluminium" right of it (physical surfaces inside Omega+, the plies that
//   Materials/Layer 1/Ply groups names).
//
// Mesh: transfinite quadrilaterals, 8 rows per arm, cells of about 1 along
// x (2 between the tip and the scarf), scaled by 1 / Mesh.MeshSizeFactor.
//
// Physical groups: Surface "Omega-", "Omega+", "carbon", "aluminium";
// Curve "Sigma", "crack", "left", "right", "bottom", "top".

Mesh.MshFileVersion = 2.2;
f = Mesh.MeshSizeFactor;
n = Round(1 / f);
If (n < 1)
  n = 1;
EndIf

Point(1) = {0, -4, 0, 1};    Point(2) = {60, -4, 0, 1};
Point(3) = {60, 0, 0, 1};    Point(4) = {60, 4, 0, 1};
Point(5) = {25, 4, 0, 1};    Point(6) = {0, 4, 0, 1};
Point(7) = {0, 0, 0, 1};     Point(8) = {20, 0, 0, 1};   // the crack tip
Point(9) = {21, 0, 0, 1};    // the foot of the scarf

Line(1) = {1, 2};     // bottom
Line(2) = {2, 3};     // right, lower arm
Line(3) = {3, 4};     // right, upper arm
Line(4) = {4, 5};     // top, aluminium
Line(5) = {5, 6};     // top, carbon
Line(6) = {6, 7};     // left, upper arm
Line(7) = {7, 1};     // left, lower arm
Line(8) = {7, 8};     // crack
Line(9) = {8, 9};     // Sigma, tip to scarf
Line(10) = {9, 3};    // Sigma, scarf to the right end
Line(11) = {9, 5};    // the scarf

Curve Loop(1) = {1, 2, -10, -9, -8, 7};
Plane Surface(1) = {1};
Curve Loop(2) = {8, 9, 11, 5, 6};
Plane Surface(2) = {2};
Curve Loop(3) = {10, 3, 4, -11};
Plane Surface(3) = {3};

Transfinite Curve{1} = 60 * n + 1;
Transfinite Curve{8} = 20 * n + 1;
Transfinite Curve{9} = 2 * n + 1;
Transfinite Curve{10, 4} = 38 * n + 1;
Transfinite Curve{5} = 22 * n + 1;
Transfinite Curve{2, 3, 6, 7, 11} = 8 * n + 1;
Transfinite Surface{1} = {1, 2, 3, 7};
Transfinite Surface{2} = {7, 9, 5, 6};
Transfinite Surface{3} = {9, 3, 4, 5};
Recombine Surface{1, 2, 3};

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2, 3};
Physical Surface("carbon") = {2};
Physical Surface("aluminium") = {3};
Physical Curve("Sigma") = {9, 10};
Physical Curve("crack") = {8};
Physical Curve("bottom") = {1};
Physical Curve("top") = {4, 5};
Physical Curve("left") = {6, 7};
Physical Curve("right") = {2, 3};
