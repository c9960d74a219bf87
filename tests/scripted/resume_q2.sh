# resume.sh on Q2 (Geometry/Element degree = 2): the checkpoint carries every
# node's values, vertices and mid-nodes, and the run resumed after a cycle
# ends as the uninterrupted one.
source "$TESTS/common.bash"
SCENE=("subsection Geometry" "  set Element degree = 2" "end")
CYCLES=5 KILL_AFTER=2 resume_test
