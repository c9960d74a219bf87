// The study's 10 x 1 mm beam as a structured triangle mesh for Gmsh, nx x ny
// rectangles each split into two triangles (alternating diagonals), so that
// the triangle count 2 nx ny matches the study's exactly:
//   gmsh -2 -setnumber nx 40 -setnumber ny 8 beam.geo -o beam-640.msh
// Physical groups become boundary ids: 1 left, 2 right, 3 bottom, 4 top.
DefineConstant[ nx = 40, ny = 8 ];
Point(1) = {0, 0, 0};
Point(2) = {10, 0, 0};
Point(3) = {10, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1} = {1, 2, 3, 4} Alternate;
Physical Curve(1) = {4};
Physical Curve(2) = {2};
Physical Curve(3) = {1};
Physical Curve(4) = {3};
Physical Surface(1) = {1};
Mesh.MshFileVersion = 2.2;
