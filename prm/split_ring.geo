// A split ring for Gmsh: outer radius 1 mm, inner 0.6 mm, centred at (0, 1)
// so that its lowest point (0, 0) touches the plane y = 0, with a 60 degree
// gap at the top (between 60 and 120 degrees). Boundary ids by physical
// groups: the outer face 0, the two cut faces 1, the inner face 2.
lc = 0.1;
R = 1;
r = 0.6;
Point(1) = {0, 1, 0, lc};
angles[] = {120, 195, 270, 345, 420};
For i In {0 : 4}
  a = angles[i] * Pi / 180;
  Point(10 + i) = {R * Cos(a), 1 + R * Sin(a), 0, lc};
  Point(20 + i) = {r * Cos(a), 1 + r * Sin(a), 0, lc};
EndFor
For i In {0 : 3}
  Circle(10 + i) = {10 + i, 1, 11 + i};
  Circle(20 + i) = {21 + i, 1, 20 + i};
EndFor
Line(30) = {14, 24};
Line(31) = {20, 10};
Curve Loop(1) = {10, 11, 12, 13, 30, 23, 22, 21, 20, 31};
Plane Surface(1) = {1};
Physical Curve(0) = {10, 11, 12, 13};
Physical Curve(1) = {30, 31};
Physical Curve(2) = {20, 21, 22, 23};
Physical Surface(1) = {1};
