// A square (-1,1)^2 cut by a polygonal Sigma (four segments, corners at
// (-0.5,0.25), (0,0.1), (0.5,-0.2)) with the crack on the two middle
// segments (a crack node at the corner (0,0.1)). Transfinite
// quadrilaterals; used by tests/gmsh_scenes.cc (patch tests).
Mesh.MshFileVersion = 2.2;
lc = 1;
Point(1) = {-1, -1, 0, lc};
Point(2) = {1, -1, 0, lc};
Point(3) = {1, 1, 0, lc};
Point(4) = {-1, 1, 0, lc};
Point(5) = {-1, 0, 0, lc};
Point(6) = {-0.5, 0.25, 0, lc};
Point(7) = {0, 0.1, 0, lc};
Point(8) = {0.5, -0.2, 0, lc};
Point(9) = {1, 0, 0, lc};
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
Transfinite Curve{1, 2, 3, 4} = 3;
Transfinite Curve{5, 8} = 9;
Transfinite Curve{6, 7, 9, 10} = 4;
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
