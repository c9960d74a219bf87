// An elastic disk of radius 1 mm around the origin between two plates, the
// half x >= 0 by symmetry. Boundary ids by physical groups: the curved face
// 0 (it touches both plates), the symmetry line x = 0 2. Triangles of 0.02
// mm at the poles, 0.2 mm at the side; Kelly cycles remesh it.
Point(1) = {0, 0, 0, 0.2};
Point(2) = {0, -1, 0, 0.02};
Point(3) = {1, 0, 0, 0.2};
Point(4) = {0, 1, 0, 0.02};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve(0) = {1, 2};
Physical Curve(2) = {3};
Physical Surface(1) = {1};
