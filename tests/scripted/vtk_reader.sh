# Every VTU, PVTU and PVD file of a 2D run on one process and on two, of the
# same run with zlib instead of LZ4 and of a 3D run opens in ParaView's
# readers and holds the fields the README names (check_vtk.py, Debian's
# python3 with python3-paraview); the solution files name the compressor
# chosen, and the LZ4 and zlib runs' arrays are the same.
source "$TESTS/common.bash"
lines=("subsection Geometry" "  set Initial refinement = 0" "end"
  "subsection Mesh refinement" "  set Number of cycles = 2" "end")
scene serial.prm serial "${lines[@]}"
scene parallel.prm parallel "${lines[@]}"
scene zlib.prm zlib "${lines[@]}" "subsection Output" \
  "  set Compression = zlib" "end"
{
  echo "include $TESTS/../box_on_plane_3d.prm"
  echo "subsection Output"
  echo "  set Directory = box"
  echo "end"
} > box.prm
run "$SIGNORINI" serial.prm
run mpirun -np 2 "$SIGNORINI" parallel.prm
run "$SIGNORINI" zlib.prm
run "$SIGNORINI" box.prm
for file in serial/solution-01.vtu parallel/solution-01.0001.vtu \
  zlib/solution-01.vtu serial/obstacle.vtu; do
  echo "$file: $(grep -o 'compressor="[A-Za-z0-9]*"' "$file")"
done
/usr/bin/python3 "$TESTS/check_vtk.py" serial parallel zlib box 2>&1
/usr/bin/python3 "$TESTS/check_vtk.py" --same serial zlib 2>&1
