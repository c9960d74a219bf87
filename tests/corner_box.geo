// The unit cube [0, 1]^3 as 4 x 4 x 4 hexahedra, for the box in a rigid
// corner; with `theta` set (corner_box_turned.geo) turned by theta about the
// x axis. Boundary ids: x = 0 0, x = 1 1, y = 1 2, z = 1 3, y = 0 4,
// z = 0 5 (before turning).
SetFactory("OpenCASCADE");
If (!Exists(theta))
  theta = 0;
EndIf
Box(1) = {0, 0, 0, 1, 1, 1};
If (theta != 0)
  Rotate {{1, 0, 0}, {0, 0, 0}, theta} { Volume{1}; }
EndIf
Transfinite Curve {:} = 5;
Transfinite Surface {:};
Recombine Surface {:};
Transfinite Volume {1};
Physical Surface(0) = {1};
Physical Surface(1) = {2};
Physical Surface(2) = {4};
Physical Surface(3) = {6};
Physical Surface(4) = {3};
Physical Surface(5) = {5};
Physical Volume(1) = {1};
