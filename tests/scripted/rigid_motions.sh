# Rigid motions that neither the supports nor the possible contact hold are
# found before cycle 0, alike on one process and on two: one line naming
# each free motion, status 1, no cycle started, and the output directory
# as an earlier run left it. Contact alone may hold the body.
source "$TESTS/common.bash"

# unchanged DIRECTORY: whether DIRECTORY holds what before.txt lists.
unchanged() {
  files "$1" | cmp -s - before.txt && echo "  out/ unchanged" || echo "  out/ CHANGED"
}

scene earlier.prm out "subsection Mesh refinement" "  set Number of cycles = 1" "end"
echo "an earlier run into out/:"
run "$SIGNORINI" earlier.prm
files out > before.txt

scene sideways.prm out "subsection Boundary conditions" "  set Dirichlet = 0: y" "end"
for launcher in "" "mpirun -np 2"; do
  echo "beam on a roller, free along x (${launcher:-one process}):"
  run $launcher "$SIGNORINI" sideways.prm
  echo "  cycles started: $(grep -c '^Cycle' run.log)"
  unchanged out
done

echo "beam on a roller, contact off:"
scene roller.prm out "subsection Boundary conditions" "  set Dirichlet = 0: y" "end" \
  "subsection Contact" "  set Method = none" "end"
run "$SIGNORINI" roller.prm
unchanged out

echo "beam on a vertical roller, contact off:"
scene vertical.prm out "subsection Boundary conditions" "  set Dirichlet = 0: x" "end" \
  "subsection Contact" "  set Method = none" "end"
run "$SIGNORINI" vertical.prm
unchanged out

# 3D: a 2 x 1 x 1 block whose face x = 0 slides in its plane, pulled along x.
block() {
  local file=$1
  shift
  {
    echo "set Dimension = 3"
    echo "subsection Geometry"
    echo "  set Upper right corner = 2, 1, 1"
    echo "  set Subdivisions       = 2, 1, 1"
    echo "end"
    echo "subsection Boundary conditions"
    echo "  set Dirichlet             = 0: x"
    echo "  set Traction boundary ids = 1"
    echo "  set Traction              = 1; 0; 0"
    echo "end"
    echo "subsection Output"
    echo "  set Directory     = out"
    echo "  set Print timings = false"
    echo "  set Verbose       = false"
    echo "end"
    for line in "$@"; do echo "$line"; done
  } > "$file"
}
block hinge.prm "subsection Contact" "  set Method = none" "end"
for launcher in "" "mpirun -np 2"; do
  echo "3D block sliding on its face x = 0, contact off (${launcher:-one process}):"
  run $launcher "$SIGNORINI" hinge.prm
  unchanged out
done
echo "3D block sliding on its face x = 0, on the obstacle below:"
block resting.prm "subsection Obstacle" "  set Height = 0" "  set Contact boundary ids = 4" "end"
run "$SIGNORINI" resting.prm
unchanged out

echo "held by contact alone (the quarter ball of prm/hertz_sphere.prm, one cycle):"
{
  echo "include $PRM/hertz_sphere.prm"
  echo "subsection Mesh refinement"
  echo "  set Number of cycles = 1"
  echo "end"
  echo "subsection Output"
  echo "  set Directory     = ball"
  echo "  set Print timings = false"
  echo "  set Verbose       = false"
  echo "end"
} > ball.prm
run "$SIGNORINI" ball.prm
grep "contact force" run.log
echo "the same with contact off:"
{
  cat ball.prm
  echo "subsection Contact"
  echo "  set Method = none"
  echo "end"
} > ball_off.prm
run "$SIGNORINI" ball_off.prm
