// A layered strip with a hole and a debonded zone (the showcase scene).
// Lengths in the unit of the geometry.
//
//   Omega = (0,4) x (-0.5,0.5), Sigma the line y = 0 over the whole length
//   (its normal e_y points into Omega+),
//   Omega- = (0,4) x (-0.5,0)  (the lower half),
//   Omega+ = (0,4) x (0,0.5) minus the disc of radius 0.2 centred at
//            (2, 0.25) (the hole keeps a ligament of 0.05 to Sigma and to
//            the top side),
//   crack (the debonded zone) on Sigma from x = 1.2 to x = 2.8 (its tips are
//   geometry points).
//
// Mesh: unstructured quadrilaterals, cell size about 0.15, graded down to
// about 0.05 at the crack tips and on the hole (size fields: Threshold on
// the distance to the tips and to the hole), about 525 cells. The sizes
// scale with Mesh.MeshSizeFactor (gmsh -clscale F, bilayer's Mesh/Gmsh mesh
// size factor). The hole is four Gmsh Circle arcs (bilayer attaches a polar
// manifold to them).
// All cells are quadrilaterals by Gmsh's "simple full-quad" recombination
// (Mesh.RecombinationAlgorithm = 2: recombine, then split every cell into
// quadrilaterals; Gmsh meshes at twice the size first, so the final cells
// have about the sizes set here). Plain Blossom (1) leaves a few triangles,
// and Mesh.Algorithm = 8 (Frontal-Delaunay for quads) crashes in Debian's
// gmsh 4.8.4, hence the Frontal-Delaunay algorithm 6.
//
// Physical groups (read by name by bilayer):
//   Surface "Omega-", "Omega+"
//   Curve   "Sigma" (two pieces), "crack" (one piece)
//   Curve   "left" (x = 0, two segments), "right" (x = 4, two segments),
//           "bottom" (y = -0.5), "top" (y = 0.5), "hole" (the circle)
//
//   gmsh -2 -format msh2 strip_with_hole.geo -o strip_with_hole.msh

Mesh.MshFileVersion = 2.2;
Mesh.Algorithm = 6;                // Frontal-Delaunay
Mesh.RecombinationAlgorithm = 2;   // simple full-quad
Mesh.RecombineAll = 1;
Mesh.MeshSizeFromPoints = 0;       // sizes from the fields below
Mesh.MeshSizeExtendFromBoundary = 0;

lc = 0.15;       // cell size away from the tips and the hole
lt = 0.05;       // at the crack tips
lh = 0.05;       // on the hole
dt = 0.5;        // distance from a tip over which the size grows to lc
dh = 0.3;        // the same from the hole

L = 4;  H = 0.5;
xa = 1.2;  xb = 2.8;             // crack
xc = 2;  yc = 0.25;  rh = 0.2;   // hole

Point(1) = {0, -H, 0, lc};
Point(2) = {L, -H, 0, lc};
Point(3) = {L, 0, 0, lc};
Point(4) = {L, H, 0, lc};
Point(5) = {0, H, 0, lc};
Point(6) = {0, 0, 0, lc};
Point(7) = {xa, 0, 0, lt};       // crack tip
Point(8) = {xb, 0, 0, lt};       // crack tip

Point(10) = {xc, yc, 0, lh};     // centre of the hole
Point(11) = {xc + rh, yc, 0, lh};
Point(12) = {xc, yc + rh, 0, lh};
Point(13) = {xc - rh, yc, 0, lh};
Point(14) = {xc, yc - rh, 0, lh};

Line(1) = {1, 2};     // bottom
Line(2) = {2, 3};     // right, Omega-
Line(3) = {3, 4};     // right, Omega+
Line(4) = {4, 5};     // top
Line(5) = {5, 6};     // left, Omega+
Line(6) = {6, 1};     // left, Omega-
Line(7) = {6, 7};     // Sigma, 0 .. 1.2
Line(8) = {7, 8};     // crack, 1.2 .. 2.8
Line(9) = {8, 3};     // Sigma, 2.8 .. 4

Circle(11) = {11, 10, 12};
Circle(12) = {12, 10, 13};
Circle(13) = {13, 10, 14};
Circle(14) = {14, 10, 11};

Curve Loop(1) = {1, 2, -9, -8, -7, 6};   // Omega-
Plane Surface(1) = {1};
Curve Loop(2) = {7, 8, 9, 3, 4, 5};      // Omega+, outer boundary
Curve Loop(3) = {11, 12, 13, 14};        // the hole
Plane Surface(2) = {2, 3};

Recombine Surface{1, 2};

// Size: lt at the crack tips, lh on the hole, growing linearly to lc.
Field[1] = Distance;
Field[1].PointsList = {7, 8};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lt;
Field[2].SizeMax = lc;
Field[2].DistMin = 0;
Field[2].DistMax = dt;
Field[3] = Distance;
Field[3].CurvesList = {11, 12, 13, 14};
Field[3].NumPointsPerCurve = 50;
Field[4] = Threshold;
Field[4].InField = 3;
Field[4].SizeMin = lh;
Field[4].SizeMax = lc;
Field[4].DistMin = 0;
Field[4].DistMax = dh;
Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;

Physical Surface("Omega-") = {1};
Physical Surface("Omega+") = {2};
Physical Curve("Sigma") = {7, 9};
Physical Curve("crack") = {8};
Physical Curve("left") = {5, 6};
Physical Curve("right") = {2, 3};
Physical Curve("bottom") = {1};
Physical Curve("top") = {4};
Physical Curve("hole") = {11, 12, 13, 14};
