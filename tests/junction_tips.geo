// Two layers meeting along a Sigma made of two pieces that join at
// J = (0, 1) with the tangent (1, 0) on both sides (a C1 junction: only the
// curvature jumps), or at an angle (shape = 2):
//
//   shape = 0: the segment y = 1, -1.2 <= x <= 0, then the arc of the unit
//              circle about (0, 0) from 90 degrees clockwise over 1 rad
//              (curvature 0, then 1);
//   shape = 1: the arc of the unit circle about (0, 0) from 90 + 68.75
//              degrees (1.2 rad) clockwise to J, then the arc of radius 2
//              about (0, 3) from 270 degrees counter-clockwise over 0.5 rad
//              (curvatures -1 and +1/2 along the direction of s: an S bend);
//   shape = 2: the segment of shape 0, then the unit circle about
//              (-sin 10, 1 - cos 10) from 80 degrees clockwise over 1 rad: its
//              tangent at J is turned by 10 degrees (a corner of Sigma).
//
// The crack runs from the point of Sigma 0.6 before J (arc length) to the
// tip: J itself (tip = 0), or the point 0.04 after J (tip = 1). Omega- lies
// on the side of the centre of the unit circles, Omega+ on the other, each a
// band of width h = 0.25 bounded by the parallel curves of Sigma ("inner",
// "outer"; for shape = 2 the parallel lines of the segment end where the
// parallel arcs begin), closed by the normal lines at the ends of Sigma
// ("left", "right").
//
// Mesh: transfinite quadrilaterals, f * 20 cells per unit length along
// Sigma, 5 f across each layer; the normal lines through J, the crack's end
// and the tip are mesh lines. Physical groups as in tests/shallow_arcs.geo.
//
//   gmsh -2 -format msh2 -setnumber shape S -setnumber tip T -setnumber f F \
//        junction_tips.geo -o junction_tips_S_T.msh

Mesh.MshFileVersion = 2.2;

If (!Exists(shape))
  shape = 0;
EndIf
If (!Exists(tip))
  tip = 0;
EndIf
If (!Exists(f))
  f = 1;
EndIf

h  = 0.25;  // width of each layer
L  = 1.2;   // length of the piece before J
M  = 1.0;   // length of the piece after J
sc = 0.6;   // the crack starts sc before J
st = 0.04;  // the tip lies st after J (tip = 1)
w  = 10 * Pi / 180;
lc = 0.1;

// Centres: 1 of the piece before J (shape 1), 2 of the piece after J.
Point(1) = {0, 0, 0, lc};
If (shape == 0)
  Point(2) = {0, 0, 0, lc};
ElseIf (shape == 1)
  Point(2) = {0, 3, 0, lc};
Else
  Point(2) = {-Sin(w), 1 - Cos(w), 0, lc};
EndIf

// Points 10 + 10 k + j at arc length sgs[j] before (j <= 2) or after J
// on the parallel curve at distance nn of Sigma (nn > 0: towards Omega+):
// k = 0 Sigma, 1 inner, 2 outer; j = 0 the left end, 1 the start of the
// crack, 2 J, 3 the tip (tip = 1), 4 the right end.
sgs[] = {L, sc, 0, st, M};
For k In {0 : 2}
  nn = (k == 0) ? 0 : ((k == 1) ? -h : h);
  For j In {0 : 4}
    sg = sgs[j];
    If (j <= 2 && shape == 1)
      px = (1 + nn) * Cos(Pi / 2 + sg);
      py = (1 + nn) * Sin(Pi / 2 + sg);
    EndIf
    If (j <= 2 && shape != 1)
      px = -sg;
      py = 1 + nn;
    EndIf
    If (j <= 2 && shape == 2)
      // the line from (-L, 1 + nn) to where the parallel arc begins
      qx = -Sin(w) + (1 + nn) * Cos(Pi / 2 - w);
      qy = 1 - Cos(w) + (1 + nn) * Sin(Pi / 2 - w);
      px = -L + (1 - sg / L) * (qx + L);
      py = 1 + nn + (1 - sg / L) * (qy - 1 - nn);
    EndIf
    If (j > 2 && shape == 0)
      px = (1 + nn) * Cos(Pi / 2 - sg);
      py = (1 + nn) * Sin(Pi / 2 - sg);
    EndIf
    If (j > 2 && shape == 1)
      px = (2 - nn) * Cos(3 * Pi / 2 + sg / 2);
      py = 3 + (2 - nn) * Sin(3 * Pi / 2 + sg / 2);
    EndIf
    If (j > 2 && shape == 2)
      px = -Sin(w) + (1 + nn) * Cos(Pi / 2 - w - sg);
      py = 1 - Cos(w) + (1 + nn) * Sin(Pi / 2 - w - sg);
    EndIf
    If (j != 3 || tip == 1)
      Point(10 + 10 * k + j) = {px, py, 0, lc};
    EndIf
  EndFor
EndFor

// Curves 100 + 10 k + j from point j to the next one on curve k.
For k In {0 : 2}
  If (shape == 1)
    Circle(100 + 10 * k) = {10 + 10 * k, 1, 11 + 10 * k};
    Circle(101 + 10 * k) = {11 + 10 * k, 1, 12 + 10 * k};
  Else
    Line(100 + 10 * k) = {10 + 10 * k, 11 + 10 * k};
    Line(101 + 10 * k) = {11 + 10 * k, 12 + 10 * k};
  EndIf
  If (tip == 1)
    Circle(102 + 10 * k) = {12 + 10 * k, 2, 13 + 10 * k};
    Circle(103 + 10 * k) = {13 + 10 * k, 2, 14 + 10 * k};
  Else
    Circle(102 + 10 * k) = {12 + 10 * k, 2, 14 + 10 * k};
  EndIf
EndFor
Line(200) = {20, 10};  // left, Omega-
Line(201) = {10, 30};  // left, Omega+
Line(202) = {24, 14};  // right, Omega-
Line(203) = {14, 34};  // right, Omega+

If (tip == 1)
  Curve Loop(1) = {200, 100, 101, 102, 103, -202, -113, -112, -111, -110};
  Curve Loop(2) = {201, 120, 121, 122, 123, -203, -103, -102, -101, -100};
Else
  Curve Loop(1) = {200, 100, 101, 102, -202, -112, -111, -110};
  Curve Loop(2) = {201, 120, 121, 122, -203, -102, -101, -100};
EndIf
Plane Surface(1) = {1};
Plane Surface(2) = {2};

For k In {0 : 2}
  Transfinite Curve{100 + 10 * k} = Round(20 * f * (L - sc)) + 1;
  Transfinite Curve{101 + 10 * k} = Round(20 * f * sc) + 1;
  If (tip == 1)
    Transfinite Curve{102 + 10 * k} = 2 * f + 1;
    Transfinite Curve{103 + 10 * k} = Round(20 * f * (M - st)) + 1;
  Else
    Transfinite Curve{102 + 10 * k} = Round(20 * f * M) + 1;
  EndIf
EndFor
Transfinite Curve{200, 201, 202, 203} = 5 * f + 1;
Transfinite Surface{1} = {20, 10, 14, 24};
Transfinite Surface{2} = {10, 30, 34, 14};
Recombine Surface{1, 2};

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
If (tip == 1)
  Physical Curve("Sigma") = {100, 103};
  Physical Curve("crack") = {101, 102};
  Physical Curve("inner") = {110, 111, 112, 113};
  Physical Curve("outer") = {120, 121, 122, 123};
Else
  Physical Curve("Sigma") = {100, 102};
  Physical Curve("crack") = {101};
  Physical Curve("inner") = {110, 111, 112};
  Physical Curve("outer") = {120, 121, 122};
EndIf
Physical Curve("left") = {200, 201};
Physical Curve("right") = {202, 203};
