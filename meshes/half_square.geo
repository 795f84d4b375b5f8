// One half of the paper's square Omega = (-1,1)^2: Omega- = (-1,1)x(-1,0)
// (side = -1) or Omega+ = (-1,1)x(0,1) (side = 1), unstructured triangles.
//
// P vertices on Sigma (y = 0), uniformly spaced on each of the three pieces
// [-1,-1/2], [-1/2,1/2] (the crack) and [1/2,1], so that the crack end points
// are vertices and both halves have the same trace on Sigma. M is the number
// of vertices on the outer boundary of the whole square: M/4 segments on the
// bottom (top) side and M/8 on each vertical side of each half.
//
//   gmsh -2 -format msh2 -setnumber P 12 -setnumber M 32 -setnumber side -1 \
//        half_square.geo -o table1_P12_M32_minus.msh
//
// bilayer assigns the boundary ids itself from the coordinates, so no
// physical curves are needed.
If (!Exists(P))
  P = 12;
EndIf
If (!Exists(M))
  M = 32;
EndIf
If (!Exists(side))
  side = -1;
EndIf

na = Round((P - 1) / 4);
nc = P - 1 - 2 * na;
nb = M / 4;
ns = M / 8;

Point(1) = {-1, 0, 0};
Point(2) = {-0.5, 0, 0};
Point(3) = {0.5, 0, 0};
Point(4) = {1, 0, 0};
Point(5) = {1, side, 0};
Point(6) = {-1, side, 0};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};

Transfinite Curve{1} = na + 1;
Transfinite Curve{2} = nc + 1;
Transfinite Curve{3} = na + 1;
Transfinite Curve{4} = ns + 1;
Transfinite Curve{5} = nb + 1;
Transfinite Curve{6} = ns + 1;

Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
If (side < 0)
  Reverse Surface{1};
EndIf
Physical Surface(1) = {1};

Mesh.Algorithm = 6;
Mesh.RandomSeed = 1;
