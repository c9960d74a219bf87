// prm/hertz_cylinder.geo turned by -90 degrees, (x, y) -> (y, -x): the
// quarter disk around (1, 0) that touches the wall x = 0 at the origin, from
// x > 0. Boundary ids: the curved face 0, the flat face x = 1 1, the
// symmetry line y = 0 2.
lc = 0.1;
Point(1) = {1, 0, 0, lc};
Point(2) = {0, 0, 0, lc};
Point(3) = {1, -1, 0, lc};
Circle(1) = {2, 1, 3};
Line(2) = {3, 1};
Line(3) = {1, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve(0) = {1};
Physical Curve(1) = {2};
Physical Curve(2) = {3};
Physical Surface(1) = {1};
