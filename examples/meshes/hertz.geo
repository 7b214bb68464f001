// The Hertz scene's geometry (src/studies/scenes/hertz.rs, half model) for
// Gmsh, probes/ring_study.rs and tests/gmsh_interfaces.rs: the block [0, 2R] x [-2R, 0]
// (physical surface 1) and the part 0 <= x <= 0.8R of a cylinder of
// radius R touching it at the origin (surface 2), each meshed on its own
// (the interface nodes do not match). Size h within 1.5a of the contact
// point, growing by 15 % per element beyond. Physical curves: 1 the
// block's supported bottom, 2 its top (contact), 3 the cylinder's arc
// (contact), 4 the cylinder's loaded centre line y = R, 5 the axis x = 0.
//   gmsh -2 -format msh41 -setnumber h 0.00125 hertz.geo -o hertz.msh
If (!Exists(h))
  h = 0.02 / 16;
EndIf
If (!Exists(a))
  a = 0.02;
EndIf
R = 1; hmax = 0.1;
Point(1) = {0, 0, 0};
Point(2) = {2 * R, 0, 0};
Point(3) = {2 * R, -2 * R, 0};
Point(4) = {0, -2 * R, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(11) = {0, 0, 0};
Point(12) = {0.8 * R, R - 0.6 * R, 0};
Point(13) = {0.8 * R, R, 0};
Point(14) = {0, R, 0};
Circle(11) = {11, 14, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
Field[1] = Distance;
Field[1].PointsList = {1, 11};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hmax;
Field[2].DistMin = 1.5 * a;
Field[2].DistMax = 1.5 * a + (hmax - h) / 0.15;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(1) = {3};
Physical Curve(2) = {1};
Physical Curve(3) = {11};
Physical Curve(4) = {13};
Physical Curve(5) = {4, 14};
