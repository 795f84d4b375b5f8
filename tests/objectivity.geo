// The scene of tests/objectivity.cc in its own frame (rotation 0): the
// rectangle (-2, 2) x (-1, 1), Sigma the line y = 0, two cracks (-1.4, -0.6)
// and (0.3, 1.2) on it (four tips, geometry points), unstructured triangles
// (no symmetry of the mesh), cells of about 0.2, 0.06 at the tips. The
// test reads the .msh and writes it rotated: the meshes are congruent.
//
// Physical groups (read by name by bilayer):
//   Surface "Omega-", "Omega+"
//   Curve   "Sigma" (three pieces), "crack" (two pieces)
//   Curve   "left" (x = -2, two segments), "right" (x = 2, two segments),
//           "bottom" (y = -1), "top" (y = 1)
//
//   gmsh -2 -format msh2 objectivity.geo -o objectivity.msh

Mesh.MshFileVersion = 2.2;

L = 2;  H = 1;  c = 0.2;  ct = 0.06;

Point(1) = {-L, -H, 0, c};
Point(2) = {L, -H, 0, c};
Point(3) = {L, H, 0, c};
Point(4) = {-L, H, 0, c};
XS[] = {-2, -1.4, -0.6, 0.3, 1.2, 2};   // Sigma: ends and crack tips
For i In {0 : 5}
  Point(11 + i) = {XS[i], 0, 0, (i == 0 || i == 5) ? c : ct};
EndFor

Line(1) = {1, 2};     // bottom
Line(2) = {2, 16};    // right, Omega-
Line(3) = {16, 3};    // right, Omega+
Line(4) = {3, 4};     // top
Line(5) = {4, 11};    // left, Omega+
Line(6) = {11, 1};    // left, Omega-
Line(11) = {11, 12};  // Sigma
Line(12) = {12, 13};  // crack
Line(13) = {13, 14};  // Sigma
Line(14) = {14, 15};  // crack
Line(15) = {15, 16};  // Sigma

Curve Loop(1) = {1, 2, -15, -14, -13, -12, -11, 6};   // Omega-
Plane Surface(1) = {1};
Curve Loop(2) = {11, 12, 13, 14, 15, 3, 4, 5};        // Omega+
Plane Surface(2) = {2};

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
Physical Curve("Sigma") = {11, 13, 15};
Physical Curve("crack") = {12, 14};
Physical Curve("bottom") = {1};
Physical Curve("top") = {4};
Physical Curve("left") = {5, 6};
Physical Curve("right") = {2, 3};
