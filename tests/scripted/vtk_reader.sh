# Every VTU, PVTU and PVD file of a 2D run on one process and on two and of
# a 3D run opens in ParaView's readers and holds the fields the README
# names (check_vtk.py, Debian's python3 with python3-paraview).
source "$TESTS/common.bash"
lines=("subsection Geometry" "  set Initial refinement = 0" "end"
  "subsection Mesh refinement" "  set Number of cycles = 2" "end")
scene serial.prm serial "${lines[@]}"
scene parallel.prm parallel "${lines[@]}"
{
  echo "include $TESTS/../box_on_plane_3d.prm"
  echo "subsection Output"
  echo "  set Directory = box"
  echo "end"
} > box.prm
run "$SIGNORINI" serial.prm
run mpirun -np 2 "$SIGNORINI" parallel.prm
run "$SIGNORINI" box.prm
/usr/bin/python3 "$TESTS/check_vtk.py" serial parallel box 2>&1
