// The [0/90/0] cross-ply double cantilever beam of parameter_files/
// cross_ply_dcb.prm as a Gmsh scene whose plies are physical surfaces
// (Materials/Layer k/Ply groups; tests/gmsh_plies.cc).
//
//   the beam (0, 60) x (-1, 2), each ply of thickness 1: the lower 0 ply
//   -1 < y < 0 (Omega-), the 90 ply 0 < y < 1 and the upper 0 ply
//   1 < y < 2 (Omega+, two surfaces); Sigma the lower 0/90 interface y = 0,
//   the crack (0, 20) from the free left end.
//
// Mesh: transfinite quadrilaterals, cells of size 1 along x, 2 rows per ply
// (scaled by 1 / Mesh.MeshSizeFactor).
//
// Physical groups: Surface "Omega-" = lower ply, "Omega+" = the 90 and the
// upper 0 ply; "ninety" = the 90 ply, "zero" = both 0 plies (one in each
// region); Curve "Sigma", "crack", "left", "right", "bottom", "top".

Mesh.MshFileVersion = 2.2;
f = Mesh.MeshSizeFactor;
n = Round(1 / f);
If (n < 1)
  n = 1;
EndIf

Point(1) = {0, -1, 0, 1};   Point(2) = {60, -1, 0, 1};
Point(3) = {60, 0, 0, 1};   Point(4) = {60, 1, 0, 1};
Point(5) = {60, 2, 0, 1};   Point(6) = {0, 2, 0, 1};
Point(7) = {0, 1, 0, 1};    Point(8) = {0, 0, 0, 1};
Point(9) = {20, 0, 0, 1};   // the crack tip

Line(1) = {1, 2};     // bottom
Line(2) = {2, 3};     // right, lower ply
Line(3) = {3, 4};     // right, 90 ply
Line(4) = {4, 5};     // right, upper ply
Line(5) = {5, 6};     // top
Line(6) = {6, 7};     // left, upper ply
Line(7) = {7, 8};     // left, 90 ply
Line(8) = {8, 1};     // left, lower ply
Line(9) = {8, 9};     // crack
Line(10) = {9, 3};    // Sigma
Line(11) = {7, 4};    // the 0/90 ply boundary y = 1

Curve Loop(1) = {1, 2, -10, -9, 8};
Plane Surface(1) = {1};
Curve Loop(2) = {9, 10, 3, -11, 7};
Plane Surface(2) = {2};
Curve Loop(3) = {11, 4, 5, 6};
Plane Surface(3) = {3};

Transfinite Curve{1, 11, 5} = 60 * n + 1;
Transfinite Curve{9} = 20 * n + 1;
Transfinite Curve{10} = 40 * n + 1;
Transfinite Curve{2, 3, 4, 6, 7, 8} = 2 * n + 1;
Transfinite Surface{1} = {1, 2, 3, 8};
Transfinite Surface{2} = {8, 3, 4, 7};
Transfinite Surface{3} = {7, 4, 5, 6};
Recombine Surface{1, 2, 3};

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2, 3};
Physical Surface("ninety") = {2};
Physical Surface("zero") = {1, 3};
Physical Curve("Sigma") = {10};
Physical Curve("crack") = {9};
Physical Curve("bottom") = {1};
Physical Curve("top") = {5};
Physical Curve("left") = {6, 7, 8};
Physical Curve("right") = {2, 3, 4};
