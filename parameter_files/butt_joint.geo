// Two plies butted on a base ply, three regions meeting at a cross-point:
// the base 'Omega-' (0, 40) x (0, 1); on it 'Omega+' (0, 20) x (1, 3) and
// 'Region 3' (20, 40) x (1, 3), butted at x = 20. The interfaces: Sigma
// (y = 1, x < 20) between Omega- and Omega+, interface 2 (y = 1, x > 20)
// between Omega- and Region 3, interface 3 (the butt, x = 20) between
// Omega+ and Region 3. They meet at (20, 1), inside the specimen.
// A delamination 'crack' on Sigma from (c, 1) to (a, 1) (c = 4, a = 10;
// a = 20: to the cross-point, refused);
// the butt cracked from the top, 'crack 3' from (20, 3) down to (20, 3 - b)
// (b = 0.75; b = 0: glued; b = 2: cracked to the cross-point, refused).
// butt = 0: the two plies one region Omega+ (no Region 3, no interfaces 2
// and 3; the butt line inside its mesh), the same cells.
// Mesh: transfinite quadrilaterals of size 1 / n (n = 1 / Mesh.MeshSizeFactor);
// a n, b n and c n whole numbers. tests/butt_joint.cc writes copies with other
// a, b and butt; parameter_files/butt_joint.prm states the scene.
Mesh.MshFileVersion = 2.2;
f = Mesh.MeshSizeFactor;
n = Round(1 / f);
If (n < 1)
  n = 1;
EndIf
If (!Exists(a))
  a = 10;
EndIf
If (!Exists(b))
  b = 0.75;
EndIf
If (!Exists(c))
  c = 4;
EndIf
If (!Exists(butt))
  butt = 1;
EndIf

Point(1) = {0, 0, 0, 1};    Point(2) = {40, 0, 0, 1};
Point(3) = {40, 1, 0, 1};   Point(4) = {40, 3, 0, 1};
Point(5) = {20, 3, 0, 1};   Point(6) = {0, 3, 0, 1};
Point(7) = {0, 1, 0, 1};    Point(8) = {20, 1, 0, 1};
Point(11) = {c, 1, 0, 1};
If (a < 20)
  Point(9) = {a, 1, 0, 1};
  tip = 9;
Else
  tip = 8;
EndIf
If (b > 0 && b < 2)
  Point(10) = {20, 3 - b, 0, 1};
EndIf

Line(1) = {1, 2};     // bottom
Line(2) = {2, 3};     // right
Line(3) = {3, 4};
Line(4) = {4, 5};     // top
Line(5) = {5, 6};
Line(6) = {6, 7};     // left
Line(7) = {7, 1};
Line(13) = {7, 11};   // Sigma
Line(8) = {11, tip};  // crack
If (a < 20)
  Line(9) = {9, 8};   // Sigma
  sigma_lines[] = {13, 9};
  loop_1[] = {1, 2, -10, -9, -8, -13, 7};
  loop_2[] = {13, 8, 9};
Else
  sigma_lines[] = {13};
  loop_1[] = {1, 2, -10, -8, -13, 7};
  loop_2[] = {13, 8};
EndIf
Line(10) = {8, 3};    // interface 2
If (b > 0 && b < 2)
  Line(11) = {8, 10}; // interface 3: glued
  Line(12) = {10, 5}; // and cracked
  butt_lines[] = {11, 12};
Else
  Line(11) = {8, 5};
  butt_lines[] = {11};
EndIf

Curve Loop(1) = {loop_1[]};
Plane Surface(1) = {1};
Curve Loop(2) = {loop_2[], butt_lines[], 5, 6};
Plane Surface(2) = {2};
Curve Loop(3) = {10, 3, 4, -butt_lines[{#butt_lines[] - 1:0:-1}]};
Plane Surface(3) = {3};

Transfinite Curve{1} = 40 * n + 1;
Transfinite Curve{13} = c * n + 1;
Transfinite Curve{8} = (a - c) * n + 1;
If (a < 20)
  Transfinite Curve{9} = (20 - a) * n + 1;
EndIf
Transfinite Curve{10, 4, 5} = 20 * n + 1;
Transfinite Curve{2, 7} = n + 1;
Transfinite Curve{3, 6} = 2 * n + 1;
If (b > 0 && b < 2)
  Transfinite Curve{11} = (2 - b) * n + 1;
  Transfinite Curve{12} = b * n + 1;
Else
  Transfinite Curve{11} = 2 * n + 1;
EndIf
Transfinite Surface{1} = {1, 2, 3, 7};
Transfinite Surface{2} = {7, 8, 5, 6};
Transfinite Surface{3} = {8, 3, 4, 5};
Recombine Surface{1, 2, 3};

Physical Surface("Omega-") = {1};
Physical Curve("crack") = {8};
Physical Curve("left") = {6, 7};
Physical Curve("right") = {2, 3};
Physical Curve("bottom") = {1};
Physical Curve("top") = {4, 5};
If (butt)
  Physical Surface("Omega+") = {2};
  Physical Surface("Region 3") = {3};
  Physical Curve("Sigma") = {sigma_lines[]};
  Physical Curve("Sigma 2") = {10};
  If (b > 0 && b < 2)
    Physical Curve("Sigma 3") = {11};
    Physical Curve("crack 3") = {12};
  ElseIf (b >= 2)
    Physical Curve("crack 3") = {11};
  Else
    Physical Curve("Sigma 3") = {11};
  EndIf
Else
  Physical Surface("Omega+") = {2, 3};
  Physical Curve("Sigma") = {sigma_lines[], 10};
EndIf
