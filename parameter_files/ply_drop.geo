// A ply drop: a laminate of two plies (0, 60) x (0, 2) with a third ply
// (20, 60) x (2, 3) on top, ending at x = 20; the right end clamped. The
// three plies are three regions: 'Omega-' (0 < y < 1), 'Omega+' (1 < y < 2)
// and 'Region 3' (the dropped ply); Sigma (y = 1) is glued everywhere, the
// interface 2 between Omega+ and Region 3 (y = 2, 20 < x < 60) has a
// delamination from the end of the ply, 'crack 2' from (20, 2) to (a, 2).
// Mesh: transfinite quadrilaterals of size 1 (scaled by 1 /
// Mesh.MeshSizeFactor); the tip at a = 35 (tests/gmsh_interfaces.cc writes
// copies with other a). parameter_files/ply_drop.prm states the scene.
Mesh.MshFileVersion = 2.2;
f = Mesh.MeshSizeFactor;
n = Round(1 / f);
If (n < 1)
  n = 1;
EndIf
If (!Exists(a))
  a = 35;
EndIf

Point(1) = {0, 0, 0, 1};    Point(2) = {60, 0, 0, 1};
Point(3) = {60, 1, 0, 1};   Point(4) = {60, 2, 0, 1};
Point(5) = {60, 3, 0, 1};   Point(6) = {20, 3, 0, 1};
Point(7) = {20, 2, 0, 1};   Point(8) = {0, 2, 0, 1};
Point(9) = {0, 1, 0, 1};    Point(10) = {a, 2, 0, 1};

Line(1) = {1, 2};     // bottom
Line(2) = {2, 3};     // right
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};     // top of the dropped ply
Line(6) = {6, 7};     // the end of the dropped ply
Line(7) = {7, 8};     // top of the two plies
Line(8) = {8, 9};     // left
Line(9) = {9, 1};
Line(10) = {9, 3};    // Sigma
Line(11) = {7, 10};   // crack 2
Line(12) = {10, 4};   // Sigma 2

Curve Loop(1) = {1, 2, -10, 9};
Plane Surface(1) = {1};
Curve Loop(2) = {10, 3, -12, -11, 7, 8};
Plane Surface(2) = {2};
Curve Loop(3) = {11, 12, 4, 5, 6};
Plane Surface(3) = {3};

Transfinite Curve{1, 10} = 60 * n + 1;
Transfinite Curve{7} = 20 * n + 1;
Transfinite Curve{11} = (a - 20) * n + 1;
Transfinite Curve{12} = (60 - a) * n + 1;
Transfinite Curve{5} = 40 * n + 1;
Transfinite Curve{2, 3, 4, 6, 8, 9} = n + 1;
Transfinite Surface{1} = {1, 2, 3, 9};
Transfinite Surface{2} = {9, 3, 4, 8};
Transfinite Surface{3} = {7, 4, 5, 6};
Recombine Surface{1, 2, 3};

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
Physical Surface("Region 3") = {3};
Physical Curve("Sigma") = {10};
Physical Curve("crack 2") = {11};
Physical Curve("Sigma 2") = {12};
Physical Curve("left") = {8, 9};
Physical Curve("right") = {2, 3, 4};
Physical Curve("free") = {1, 5, 6, 7};
