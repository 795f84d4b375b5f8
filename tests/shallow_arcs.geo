// Two layers meeting along a shallow circular arc (radius 26, chord 3),
// rotated by rot degrees about the centre of the circle (the origin):
//
//   Omega-: radii 25.8 .. 26 (inner ring),  Omega+: radii 26 .. 26.2
//   Sigma:  the arc of radius 26 between the angles 90 + rot -+ a
//           (2 a = the angle of chord 3), three arcs: the crack the middle
//           third, its two tips at the junctions of two arcs of one circle.
//   corner = 1: the crack is the straight segment between the same points
//           instead, meeting the arcs at an angle a / 3 (corners of Sigma).
//
// Mesh: transfinite quadrilaterals, 16 cells along each third, 4 across each
// layer. Physical groups as in parameter_files/curved_interface.geo.
//
//   gmsh -2 -format msh2 shallow_arcs.geo -o shallow_arcs.msh

Mesh.MshFileVersion = 2.2;

rot    = 0;
corner = 0;
n = 16;
m = 4;

r0 = 25.8;  r1 = 26;  r2 = 26.2;
a  = Asin(1.5 / 26);
c  = (90 + rot) * Pi / 180;
a0 = c + a;  a1 = c + a / 3;  a2 = c - a / 3;  a3 = c - a;
lc = 0.05;

Point(1) = {0, 0, 0, lc};
Point(2) = {r0 * Cos(a0), r0 * Sin(a0), 0, lc};
Point(3) = {r0 * Cos(a3), r0 * Sin(a3), 0, lc};
Point(4) = {r1 * Cos(a0), r1 * Sin(a0), 0, lc};
Point(5) = {r1 * Cos(a1), r1 * Sin(a1), 0, lc};   // crack tip
Point(6) = {r1 * Cos(a2), r1 * Sin(a2), 0, lc};   // crack tip
Point(7) = {r1 * Cos(a3), r1 * Sin(a3), 0, lc};
Point(8) = {r2 * Cos(a0), r2 * Sin(a0), 0, lc};
Point(9) = {r2 * Cos(a3), r2 * Sin(a3), 0, lc};

Circle(1) = {2, 1, 3};   // inner arc
Circle(2) = {4, 1, 5};   // Sigma
If (corner == 0)
  Circle(3) = {5, 1, 6}; // crack, on the circle of Sigma
Else
  Line(3) = {5, 6};      // crack, the chord: corners at the tips
EndIf
Circle(4) = {6, 1, 7};   // Sigma
Circle(5) = {8, 1, 9};   // outer arc
Line(6) = {2, 4};
Line(7) = {4, 8};
Line(8) = {3, 7};
Line(9) = {7, 9};

Curve Loop(1) = {6, 2, 3, 4, -8, -1};    // Omega-
Plane Surface(1) = {1};
Curve Loop(2) = {7, 5, -9, -4, -3, -2};   // Omega+
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
Physical Curve("right") = {8, 9};
Physical Curve("left") = {6, 7};
