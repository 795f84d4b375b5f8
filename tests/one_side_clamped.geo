// The square (-1,1)^2 cut by the straight Sigma y = 0 (no crack), the
// left and right sides each split at Sigma into a part of Omega- and a
// part of Omega+, so that an end of Sigma can be clamped on one side
// only. Transfinite quadrilaterals, matching traces on Sigma; used by
// tests/one_side_clamped.cc.
Mesh.MshFileVersion = 2.2;
lc = 1;
Point(1) = {-1, -1, 0, lc};
Point(2) = {1, -1, 0, lc};
Point(3) = {1, 1, 0, lc};
Point(4) = {-1, 1, 0, lc};
Point(5) = {-1, 0, 0, lc};
Point(6) = {1, 0, 0, lc};
Line(1) = {5, 6};   // Sigma
Line(2) = {1, 2};   // bottom
Line(3) = {2, 6};   // right, Omega-
Line(4) = {6, 3};   // right, Omega+
Line(5) = {3, 4};   // top
Line(6) = {4, 5};   // left, Omega+
Line(7) = {5, 1};   // left, Omega-
Curve Loop(1) = {2, 3, -1, 7};
Plane Surface(1) = {1};
Curve Loop(2) = {1, 4, 5, 6};
Plane Surface(2) = {2};
Transfinite Curve{1, 2, 5} = 5;
Transfinite Curve{3, 4, 6, 7} = 3;
Transfinite Surface{1} = {1, 2, 6, 5};
Transfinite Surface{2} = {5, 6, 3, 4};
Recombine Surface{1, 2};
Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
Physical Curve("Sigma") = {1};
Physical Curve("bottom") = {2};
Physical Curve("right_below") = {3};
Physical Curve("right_above") = {4};
Physical Curve("top") = {5};
Physical Curve("left_above") = {6};
Physical Curve("left_below") = {7};
