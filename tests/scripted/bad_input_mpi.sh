# Bad input found by one process of two: a traction infinite at the loaded
# end (owned by one process), the initial mesh too large for the memory of
# both. Each run stops on both processes with the same one line and status
# 1; none waits for the other.
source "$TESTS/common.bash"
scene traction.prm out \
  "subsection Boundary conditions" "  set Traction = 0; -50 + 1/(x - 10)" "end"
echo "traction infinite at x = 10, two processes:"
run timeout 60 mpirun -np 2 "$SIGNORINI" traction.prm
scene refinement.prm out \
  "subsection Geometry" "  set Initial refinement = 12" "end"
echo "initial refinement 12, two processes:"
run timeout 60 mpirun -np 2 "$SIGNORINI" refinement.prm | sed 's|[0-9.e+]* GB are available|(machine) GB are available|'
