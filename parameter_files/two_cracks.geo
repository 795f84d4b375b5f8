// A strip with two cracks on the interface: Example 1's load on a longer
// strip (lengths in the unit of the geometry).
//
//   Omega = (-2,2) x (-0.5,0.5), Sigma the line y = 0 (its normal e_y
//   points into Omega+), Omega- the lower half, Omega+ the upper half,
//   crack = two pieces (-1.5,-0.5) and (0.5,1.5) on Sigma, both in the
//   physical group "crack" (their four tips are geometry points).
//
// Mesh: transfinite quadrilaterals, 32 cells along Sigma (cell length 0.125:
// Sigma 4, crack 8, Sigma 8, crack 8, Sigma 4), 4 cells across each half
// (2 x 32 x 4 = 256 cells). The cell counts scale with 1/Mesh.MeshSizeFactor
// (gmsh -clscale F, bilayer's Mesh/Gmsh mesh size factor); the crack tips
// stay vertices.
//
// Physical groups (read by name by bilayer):
//   Surface "Omega-", "Omega+"
//   Curve   "Sigma" (three pieces), "crack" (two pieces)
//   Curve   "left" (x = -2, two segments), "right" (x = 2, two segments),
//           "bottom" (y = -0.5), "top" (y = 0.5)
//
//   gmsh -2 -format msh2 two_cracks.geo -o two_cracks.msh

Mesh.MshFileVersion = 2.2;

f = Mesh.MeshSizeFactor;
n = Round(4 / f);        // cells per half unit of length (4 at F = 1)
If (n < 1)
  n = 1;
EndIf

L = 2;  H = 0.5;

Point(1) = {-L, -H, 0, 0.125};
Point(2) = {L, -H, 0, 0.125};
Point(3) = {L, H, 0, 0.125};
Point(4) = {-L, H, 0, 0.125};
XS[] = {-2, -1.5, -0.5, 0.5, 1.5, 2};   // Sigma: ends and crack tips
For i In {0 : 5}
  Point(11 + i) = {XS[i], 0, 0, 0.125};
EndFor

Line(1) = {1, 2};     // bottom
Line(2) = {2, 16};    // right, Omega-
Line(3) = {16, 3};    // right, Omega+
Line(4) = {3, 4};     // top
Line(5) = {4, 11};    // left, Omega+
Line(6) = {11, 1};    // left, Omega-
Line(11) = {11, 12};  // Sigma, -2 .. -1.5
Line(12) = {12, 13};  // crack, -1.5 .. -0.5
Line(13) = {13, 14};  // Sigma, -0.5 .. 0.5
Line(14) = {14, 15};  // crack, 0.5 .. 1.5
Line(15) = {15, 16};  // Sigma, 1.5 .. 2

Curve Loop(1) = {1, 2, -15, -14, -13, -12, -11, 6};   // Omega-
Plane Surface(1) = {1};
Curve Loop(2) = {11, 12, 13, 14, 15, 3, 4, 5};        // Omega+
Plane Surface(2) = {2};

Transfinite Curve{1, 4} = 8 * n + 1;
Transfinite Curve{11, 15} = n + 1;
Transfinite Curve{12, 13, 14} = 2 * n + 1;
Transfinite Curve{2, 3, 5, 6} = n + 1;
Transfinite Surface{1} = {1, 2, 16, 11};
Transfinite Surface{2} = {11, 16, 3, 4};
Recombine Surface{1, 2};

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
Physical Curve("Sigma") = {11, 13, 15};
Physical Curve("crack") = {12, 14};
Physical Curve("bottom") = {1};
Physical Curve("top") = {4};
Physical Curve("left") = {5, 6};
Physical Curve("right") = {2, 3};
