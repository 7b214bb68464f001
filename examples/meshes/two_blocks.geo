// The seed scene (docs/method.md section 4) for Gmsh: two blocks touching along
// y = 0 with distinct, coincident interface nodes (two curves, same
// transfinite subdivision), nodes on x = L/2 and x = L/2 +- C.
//   gmsh -2 -setnumber h 0.03125 -format msh41 examples/meshes/two_blocks.geo -o two_blocks.msh
// Physical groups: surfaces 1 (lower block), 2 (upper block); curves
// 1 support (bottom of the lower block over 2C), 2 lower interface,
// 3 upper interface, 4 loaded segment (top of the upper block over 2C),
// 5 symmetry line x = L/2 (both blocks).
If (!Exists(h))
  h = 1/32;
EndIf
L = 1; H1 = 0.25; H2 = 0.25; C = 0.1;
xs[] = {0, L/2 - C, L/2, L/2 + C, L};
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = h / 4;

// Lower block: points 1-5 at y = -H1, 6-10 at y = 0.
For i In {0:4}
  Point(1 + i) = {xs[i], -H1, 0, h};
  Point(6 + i) = {xs[i], 0, 0, h};
EndFor
// Upper block: points 11-15 at y = 0, 16-20 at y = H2.
For i In {0:4}
  Point(11 + i) = {xs[i], 0, 0, h};
  Point(16 + i) = {xs[i], H2, 0, h};
EndFor
// Horizontal curves: 1-4 lower bottom, 5-8 lower top, 9-12 upper bottom,
// 13-16 upper top; vertical curves 17-21 lower, 22-26 upper.
For i In {0:3}
  Line(1 + i) = {1 + i, 2 + i};
  Line(5 + i) = {6 + i, 7 + i};
  Line(9 + i) = {11 + i, 12 + i};
  Line(13 + i) = {16 + i, 17 + i};
  n = Ceil((xs[i + 1] - xs[i]) / h - 1e-9) + 1;
  Transfinite Curve{1 + i, 5 + i, 9 + i, 13 + i} = n;
EndFor
For i In {0:4}
  Line(17 + i) = {1 + i, 6 + i};
  Line(22 + i) = {11 + i, 16 + i};
EndFor
For i In {0:3}
  Curve Loop(1 + i) = {1 + i, 18 + i, -(5 + i), -(17 + i)};
  Plane Surface(1 + i) = {1 + i};
  Curve Loop(5 + i) = {9 + i, 23 + i, -(13 + i), -(22 + i)};
  Plane Surface(5 + i) = {5 + i};
EndFor
Physical Surface(1) = {1, 2, 3, 4};
Physical Surface(2) = {5, 6, 7, 8};
Physical Curve(1) = {2, 3};
Physical Curve(2) = {5, 6, 7, 8};
Physical Curve(3) = {9, 10, 11, 12};
Physical Curve(4) = {14, 15};
Physical Curve(5) = {19, 24};
