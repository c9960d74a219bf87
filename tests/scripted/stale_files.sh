# A run owns its output directory: it removes the files of its series that
# an earlier run left (cycles, per-process pieces, tables, checkpoints)
# before writing, and leaves every other file alone.
source "$TESTS/common.bash"
scene long.prm out \
  "subsection Geometry" "  set Initial refinement = 0" "end" \
  "subsection Mesh refinement" "  set Number of cycles = 3" "end" \
  "subsection Output" "  set Contact pressure table = true" "  set Timing table = true" "end"
echo "three cycles on two processes:"
run mpirun -np 2 "$SIGNORINI" long.prm
echo "user's files added:"
for file in notes.txt solution-final.vtu my_solution-01.vtu solution-01.vtu.bak; do
  echo "mine" > "out/$file"
  echo "  $file"
done
files out > before.txt

scene short.prm out \
  "subsection Geometry" "  set Initial refinement = 0" "end" \
  "subsection Mesh refinement" "  set Number of cycles = 1" "end"
echo "one cycle on one process into the same directory:"
run "$SIGNORINI" short.prm
echo "files:"
files out
echo "removed:"
files out | LC_ALL=C comm -23 before.txt -
echo "user's files unchanged:" $(cat out/notes.txt out/solution-final.vtu out/my_solution-01.vtu out/solution-01.vtu.bak | grep -c mine)
echo "solution.pvd lists:"
grep -o 'file="[^"]*"' out/solution.pvd

echo "three cycles again, then a run that fails on cycle 1:"
run mpirun -np 2 "$SIGNORINI" long.prm
scene failing.prm out \
  "subsection Geometry" "  set Initial refinement = 0" "end" \
  "subsection Obstacle" "  set Height = -0.78" "end" \
  "subsection Contact" "  set Maximum iterations = 1" "end" \
  "subsection Mesh refinement" "  set Number of cycles = 3" "end"
run "$SIGNORINI" failing.prm
echo "files:"
files out
echo "statistics.csv:"
cat out/statistics.csv
