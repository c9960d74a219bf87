// A quarter of a ball of radius 1 mm, centre (0, 0, 1), its lower half cut
// by the symmetry planes x = 0 and y = 0: the Hertz ball of
// prm/hertz_sphere.prm for Gmsh (OpenCASCADE). Physical groups become
// boundary ids: 0 the sphere, 1 the flat top z = 1, 2 the plane x = 0,
// 3 the plane y = 0.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 1, 1};
Box(2) = {0, 0, 0, 1, 1, 1};
BooleanIntersection{ Volume{1}; Delete; }{ Volume{2}; Delete; }
e = 1e-3;
top[] = Surface In BoundingBox{-e, -e, 1 - e, 1 + e, 1 + e, 1 + e};
sx[]  = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
sy[]  = Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e};
sphere[] = Surface{:};
sphere[] -= {top[], sx[], sy[]};
Physical Surface(0) = {sphere[]};
Physical Surface(1) = {top[]};
Physical Surface(2) = {sx[]};
Physical Surface(3) = {sy[]};
Physical Volume(1) = {1};
MeshSize{ PointsOf{ Volume{1}; } } = 0.25;
