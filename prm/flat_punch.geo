// The flat punch scene's body for Gmsh: the (r, z) section of an elastic
// half-space y <= 0, cut off at the distance L = 10000 mm from the punch of
// radius a = 1 mm: a quarter disk around the origin. Boundary ids by
// physical groups: the surface y = 0 (under the punch, r <= a, and beside
// it) 0, the far boundary 1, the axis x = 0 2. Cells of a / 4 at the punch
// growing to L / 5 far away.
a = 1;
L = 10000;
Point(1) = {0, 0, 0, a / 4};
Point(2) = {a, 0, 0, a / 4};
Point(3) = {L, 0, 0, L / 5};
Point(4) = {0, -L, 0, L / 5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Circle(3) = {3, 1, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve(0) = {1, 2};
Physical Curve(1) = {3};
Physical Curve(2) = {4};
Physical Surface(1) = {1};
