// A curve loop that is not closed: Gmsh cannot mesh the surface.
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 1, 0, 0.1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Curve Loop(1) = {1, 2};
Plane Surface(1) = {1};
