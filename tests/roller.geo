// A rigid roller for the geometry-file obstacle test: the disk of radius
// 2 mm around (0, -2) (OpenCASCADE, so that Gmsh can export it as BREP).
SetFactory("OpenCASCADE");
Disk(1) = {0, -2, 0, 2};
