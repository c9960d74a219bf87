// A wedge of half-angle 30 degrees and height 1 mm, apex down at the
// origin: the half x >= 0 of a wedge seated in a V-groove. Boundary ids by
// physical groups: the inclined face (on the groove's wall) 0, the flat top
// 1, the symmetry line x = 0 2.
H     = 1;
alpha = Pi / 6;
lc    = 0.25;
Point(1) = {0, 0, 0, lc};
Point(2) = {H * Tan(alpha), H, 0, lc};
Point(3) = {0, H, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve(0) = {1};
Physical Curve(1) = {2};
Physical Curve(2) = {3};
Physical Surface(1) = {1};
