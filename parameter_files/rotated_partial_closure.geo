// Example 1 of the paper (docs/problem.md §5, parameter_files/partial_closure.prm)
// rotated by 30 degrees counter-clockwise about the origin.
//
// Specimen: the square (-1,1)^2 (lengths in the unit of the geometry),
// Sigma the segment y = 0, the crack (-0.5, 0.5) on it, all in the body's
// own coordinates (xb, yb); every point is mapped by the rotation
//   x = cos30 xb - sin30 yb,   y = sin30 xb + cos30 yb.
// Omega- is the image of yb < 0, Omega+ of yb > 0 (the normal of Sigma is
// the rotated e_y, pointing into Omega+).
//
// Mesh: the rotated structured mesh of the original: transfinite
// quadrilaterals, 16 cells along Sigma (4 + 8 + 4: Sigma (-1,-0.5), crack
// (-0.5,0.5), Sigma (0.5,1); the crack tips are geometry points), 8 cells
// across each subdomain, uniform (2 x 16 x 8 = 256 cells).
// The cell counts scale with 1/Mesh.MeshSizeFactor (gmsh -clscale F, the
// bilayer entry Mesh/Gmsh mesh size factor): F = 0.5 gives 32 cells along
// Sigma, and the crack tips stay vertices.
//
// Physical groups (read by name by bilayer):
//   Surface "Omega-", "Omega+"
//   Curve   "Sigma" (glued, two pieces), "crack" (one piece)
//   Curve   "bottom" (image of yb = -1), "top" (yb = 1),
//           "left" (xb = -1, two curves), "right" (xb = 1, two curves)
//
//   gmsh -2 -format msh2 rotated_partial_closure.geo -o rotated_partial_closure.msh

Mesh.MshFileVersion = 2.2;

f = Mesh.MeshSizeFactor;
n = Round(4 / f);       // cells per half unit of length (4 at F = 1)
If (n < 1)
  n = 1;
EndIf

alpha = Pi / 6;          // 30 degrees
cs = Cos(alpha);
sn = Sin(alpha);

// Points in body coordinates, then rotated.
//   1 (-1,-1)   2 (1,-1)   3 (1,1)   4 (-1,1)
//   5 (-1,0)    6 (-0.5,0) 7 (0.5,0) 8 (1,0)
XB[] = {-1, 1, 1, -1, -1, -0.5, 0.5, 1};
YB[] = {-1, -1, 1, 1, 0, 0, 0, 0};
For i In {0 : 7}
  Point(i + 1) = {cs * XB[i] - sn * YB[i], sn * XB[i] + cs * YB[i], 0, 0.125};
EndFor

Line(1) = {1, 2};   // bottom
Line(2) = {2, 8};   // right, Omega-
Line(3) = {8, 3};   // right, Omega+
Line(4) = {3, 4};   // top
Line(5) = {4, 5};   // left, Omega+
Line(6) = {5, 1};   // left, Omega-
Line(7) = {5, 6};   // Sigma (left piece)
Line(8) = {6, 7};   // crack
Line(9) = {7, 8};   // Sigma (right piece)

Curve Loop(1) = {1, 2, -9, -8, -7, 6};   // Omega-
Plane Surface(1) = {1};
Curve Loop(2) = {7, 8, 9, 3, 4, 5};      // Omega+
Plane Surface(2) = {2};

Transfinite Curve{1, 4} = 4 * n + 1;
Transfinite Curve{8} = 2 * n + 1;
Transfinite Curve{7, 9} = n + 1;
Transfinite Curve{2, 3, 5, 6} = 2 * n + 1;
Transfinite Surface{1} = {1, 2, 8, 5};
Transfinite Surface{2} = {5, 8, 3, 4};
Recombine Surface{1, 2};

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
Physical Curve("Sigma") = {7, 9};
Physical Curve("crack") = {8};
Physical Curve("bottom") = {1};
Physical Curve("top") = {4};
Physical Curve("left") = {5, 6};
Physical Curve("right") = {2, 3};
