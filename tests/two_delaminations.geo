// The two delaminations of parameter_files/two_delaminations.prm as a Gmsh
// scene of three regions: the beam (0, 32) x (0, 3), Sigma at y = 1 with
// the crack (0, 8), interface 2 at y = 2 with the crack (0, 20); cells of
// size 1 (transfinite quadrilaterals, the rectangle scene's mesh of cycle
// 0), scaled by 1 / Mesh.MeshSizeFactor (tests/gmsh_interfaces.cc).
Mesh.MshFileVersion = 2.2;
f = Mesh.MeshSizeFactor;
n = Round(1 / f);
If (n < 1)
  n = 1;
EndIf

Point(1) = {0, 0, 0, 1};    Point(2) = {32, 0, 0, 1};
Point(3) = {32, 1, 0, 1};   Point(4) = {32, 2, 0, 1};
Point(5) = {32, 3, 0, 1};   Point(6) = {0, 3, 0, 1};
Point(7) = {0, 2, 0, 1};    Point(8) = {0, 1, 0, 1};
Point(9) = {8, 1, 0, 1};    Point(10) = {20, 2, 0, 1};

Line(1) = {1, 2};     // bottom
Line(2) = {2, 3};     // right
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};     // top
Line(6) = {6, 7};     // left
Line(7) = {7, 8};
Line(8) = {8, 1};
Line(9) = {8, 9};     // crack
Line(10) = {9, 3};    // Sigma
Line(11) = {7, 10};   // crack 2
Line(12) = {10, 4};   // Sigma 2

Curve Loop(1) = {1, 2, -10, -9, 8};
Plane Surface(1) = {1};
Curve Loop(2) = {9, 10, 3, -12, -11, 7};
Plane Surface(2) = {2};
Curve Loop(3) = {11, 12, 4, 5, 6};
Plane Surface(3) = {3};

Transfinite Curve{1, 5} = 32 * n + 1;
Transfinite Curve{9} = 8 * n + 1;
Transfinite Curve{10} = 24 * n + 1;
Transfinite Curve{11} = 20 * n + 1;
Transfinite Curve{12} = 12 * n + 1;
Transfinite Curve{2, 3, 4, 6, 7, 8} = n + 1;
Transfinite Surface{1} = {1, 2, 3, 8};
Transfinite Surface{2} = {8, 3, 4, 7};
Transfinite Surface{3} = {7, 4, 5, 6};
Recombine Surface{1, 2, 3};

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
Physical Surface("Region 3") = {3};
Physical Curve("Sigma") = {10};
Physical Curve("crack") = {9};
Physical Curve("Sigma 2") = {12};
Physical Curve("crack 2") = {11};
Physical Curve("bottom") = {1};
Physical Curve("top") = {5};
Physical Curve("left") = {6, 7, 8};
Physical Curve("right") = {2, 3, 4};
