# resume.sh on P2 triangles: the default scene split into triangles of
# degree 2, refined globally (a simplex mesh is not saved: the checkpoint
# holds the vectors in dof order, vertices and mid-nodes); the resumed run
# ends as the uninterrupted one.
source "$TESTS/common.bash"
SCENE=("subsection Geometry" "  set Cell type = simplex"
  "  set Element degree = 2" "  set Initial refinement = 0" "end"
  "subsection Mesh refinement" "  set Strategy = global" "end")
CYCLES=4 KILL_AFTER=1 resume_test
