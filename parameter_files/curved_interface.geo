// Two layers meeting along a circular arc: an arch, the annular sector
// between the angles 30 and 150 degrees centred at the origin (lengths in the
// unit of the geometry).
//
//   Omega-: radii 0.8 .. 1.0 (inner ring),  Omega+: radii 1.0 .. 1.2 (outer)
//   Sigma:  the arc of radius 1 (its normal e_r points into Omega+),
//   crack:  on that arc between the angles 70 and 110 degrees
//           (tips at (cos70, sin70) and (cos110, sin110), geometry points).
//
// Mesh: transfinite quadrilaterals, 24 cells along the arcs (5 degrees each:
// 8 + 8 + 8 on Sigma, the crack in the middle), 4 cells across each layer
// (2 x 24 x 4 = 192 cells). The cell counts scale with 1/Mesh.MeshSizeFactor
// (gmsh -clscale F, bilayer's Mesh/Gmsh mesh size factor); the crack tips
// stay vertices. All arcs are Gmsh Circle curves centred at the origin
// (bilayer attaches a polar manifold to them).
//
// Physical groups (read by name by bilayer):
//   Surface "Omega-", "Omega+"
//   Curve   "Sigma" (two arcs), "crack" (one arc)
//   Curve   "inner" (r = 0.8), "outer" (r = 1.2),
//           "right" (the radial end at 30 degrees, two segments),
//           "left"  (the radial end at 150 degrees, two segments)
//
//   gmsh -2 -format msh2 curved_interface.geo -o curved_interface.msh

Mesh.MshFileVersion = 2.2;

f = Mesh.MeshSizeFactor;
n = Round(8 / f);        // cells per 40 degrees of arc (8 at F = 1)
If (n < 1)
  n = 1;
EndIf
m = Round(4 / f);        // cells across each layer (4 at F = 1)
If (m < 1)
  m = 1;
EndIf

r0 = 0.8;  r1 = 1.0;  r2 = 1.2;
a0 = 30 * Pi / 180;  a1 = 70 * Pi / 180;  a2 = 110 * Pi / 180;
a3 = 150 * Pi / 180;
lc = 0.05;

Point(1) = {0, 0, 0, lc};                               // centre
Point(2) = {r0 * Cos(a0), r0 * Sin(a0), 0, lc};         // inner, 30 deg
Point(3) = {r0 * Cos(a3), r0 * Sin(a3), 0, lc};         // inner, 150 deg
Point(4) = {r1 * Cos(a0), r1 * Sin(a0), 0, lc};         // Sigma, 30 deg
Point(5) = {r1 * Cos(a1), r1 * Sin(a1), 0, lc};         // crack tip, 70 deg
Point(6) = {r1 * Cos(a2), r1 * Sin(a2), 0, lc};         // crack tip, 110 deg
Point(7) = {r1 * Cos(a3), r1 * Sin(a3), 0, lc};         // Sigma, 150 deg
Point(8) = {r2 * Cos(a0), r2 * Sin(a0), 0, lc};         // outer, 30 deg
Point(9) = {r2 * Cos(a3), r2 * Sin(a3), 0, lc};         // outer, 150 deg

Circle(1) = {2, 1, 3};   // inner arc (120 degrees)
Circle(2) = {4, 1, 5};   // Sigma, 30 .. 70
Circle(3) = {5, 1, 6};   // crack, 70 .. 110
Circle(4) = {6, 1, 7};   // Sigma, 110 .. 150
Circle(5) = {8, 1, 9};   // outer arc
Line(6) = {2, 4};        // right end, Omega-
Line(7) = {4, 8};        // right end, Omega+
Line(8) = {3, 7};        // left end, Omega-
Line(9) = {7, 9};        // left end, Omega+

Curve Loop(1) = {6, 2, 3, 4, -8, -1};    // Omega-
Plane Surface(1) = {1};
Curve Loop(2) = {7, 5, -9, -4, -3, -2};  // Omega+
Plane Surface(2) = {2};

Transfinite Curve{1, 5} = 3 * n + 1;
Transfinite Curve{2, 3, 4} = n + 1;
Transfinite Curve{6, 7, 8, 9} = m + 1;
Transfinite Surface{1} = {2, 4, 7, 3};
Transfinite Surface{2} = {4, 8, 9, 7};
Recombine Surface{1, 2};

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
Physical Curve("Sigma") = {2, 4};
Physical Curve("crack") = {3};
Physical Curve("inner") = {1};
Physical Curve("outer") = {5};
Physical Curve("right") = {6, 7};
Physical Curve("left") = {8, 9};
