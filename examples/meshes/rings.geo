// Two full rings in a shrink fit for probes/ring_study.rs and tests/gmsh_interfaces.rs:
// the inner ring a <= r <= b + delta, the outer ring b <= r <= c, each
// interface circle made of `narcs` arcs starting at angle `rot`, grouped
// into two half-circles (physical curves 11, 12 on the inner ring and 21,
// 22 on the outer ring: two contact pairs whose ends and inner arc
// junctions are nodes of both sides). The far circles r = a and r = c
// (physical curves 1, 2) have points at 0, pi/2, pi, 3pi/2 for the
// rigid-motion constraints. Sizes: h on the inner ring's surface,
// ratio*h on the outer ring's bore, 2h on the far circles.
//   gmsh -2 -format msh41 -setnumber h 0.03125 -setnumber ratio 1.5 rings.geo -o rings.msh
If (!Exists(h))
  h = 1/32;
EndIf
If (!Exists(ratio))
  ratio = 1;
EndIf
If (!Exists(delta))
  delta = 1e-3;
EndIf
If (!Exists(rot))
  rot = 0;
EndIf
If (!Exists(narcs))
  narcs = 4;
EndIf
a = 0.5; b = 1; c = 1.5; b1 = b + delta;
hi = h; ho = h * ratio; hf = 2 * h;
Mesh.MeshSizeFromCurvature = 0;
Point(1) = {0, 0, 0};
For k In {0:3}
  Point(101 + k) = {a * Cos(k * Pi / 2), a * Sin(k * Pi / 2), 0, hf};
  Point(401 + k) = {c * Cos(k * Pi / 2), c * Sin(k * Pi / 2), 0, hf};
EndFor
For k In {0:3}
  Circle(101 + k) = {101 + k, 1, 101 + (k + 1) % 4};
  Circle(401 + k) = {401 + k, 1, 401 + (k + 1) % 4};
EndFor
For k In {0:narcs - 1}
  t = rot + 2 * Pi * k / narcs;
  Point(201 + k) = {b1 * Cos(t), b1 * Sin(t), 0, hi};
  Point(301 + k) = {b * Cos(t), b * Sin(t), 0, ho};
EndFor
For k In {0:narcs - 1}
  Circle(201 + k) = {201 + k, 1, 201 + (k + 1) % narcs};
  Circle(301 + k) = {301 + k, 1, 301 + (k + 1) % narcs};
EndFor
Curve Loop(1) = {201:200 + narcs};
Curve Loop(2) = {101:104};
Plane Surface(1) = {1, 2};
Curve Loop(3) = {401:404};
Curve Loop(4) = {301:300 + narcs};
Plane Surface(2) = {3, 4};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(11) = {201:200 + narcs / 2};
Physical Curve(12) = {201 + narcs / 2:200 + narcs};
Physical Curve(21) = {301:300 + narcs / 2};
Physical Curve(22) = {301 + narcs / 2:300 + narcs};
Physical Curve(1) = {101:104};
Physical Curve(2) = {401:404};
