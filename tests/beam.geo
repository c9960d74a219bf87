// The study's 10 x 1 mm beam for Gmsh: `gmsh -2 beam.geo -o beam.msh` gives
// 642 triangles (the study's coarsest mesh had 640). Physical groups become
// boundary ids: 1 left, 2 right, 3 bottom, 4 top.
lc = 0.194;
Point(1) = {0, 0, 0, lc};
Point(2) = {10, 0, 0, lc};
Point(3) = {10, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve(1) = {4};
Physical Curve(2) = {2};
Physical Curve(3) = {1};
Physical Curve(4) = {3};
Physical Surface(1) = {1};
Mesh.MshFileVersion = 2.2;
