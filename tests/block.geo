// A 4 x 1 x 1 mm block for Gmsh (OpenCASCADE kernel). Boundary ids by
// physical groups: 1 at x = 0, 2 at x = 4, 5 at z = 0 (below), 6 elsewhere.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 4, 1, 1};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Surface(5) = {5};
Physical Surface(6) = {3, 4, 6};
Physical Volume(1) = {1};
