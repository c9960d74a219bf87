# resume.sh on triangles, whose serial mesh is rebuilt by global refinement
# on resume: the study's 640 P1 triangles refined globally, 4 cycles.
source "$TESTS/common.bash"
SCENE=("subsection Geometry" "  set Cell type = simplex" "  set Subdivisions = 20, 4"
  "  set Initial refinement = 0" "end"
  "subsection Mesh refinement" "  set Strategy = global" "end")
CYCLES=4 KILL_AFTER=1 resume_test
