// The Hertz cylinder's quarter disk for Gmsh: R = 1 mm around (0, 1), the
// half x >= 0 of a half-disk whose lowest point (0, 0) touches the plane.
// Boundary ids by physical groups: the curved face 0, the flat top 1, the
// symmetry line x = 0 2. Triangles of size 0.1 mm; Kelly cycles remesh it.
lc = 0.1;
Point(1) = {0, 1, 0, lc};
Point(2) = {0, 0, 0, lc};
Point(3) = {1, 1, 0, lc};
Circle(1) = {2, 1, 3};
Line(2) = {3, 1};
Line(3) = {1, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve(0) = {1};
Physical Curve(1) = {2};
Physical Curve(2) = {3};
Physical Surface(1) = {1};
