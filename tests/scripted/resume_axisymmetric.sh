# resume.sh on an axisymmetric body: the default scene turned into a circular
# plate (radius 10 mm) clamped at its axis and loaded at its rim, above the
# plane; the axis constraints are rebuilt with the resumed mesh and the run
# ends as the uninterrupted one.
source "$TESTS/common.bash"
SCENE=("subsection Material" "  set Plane state = axisymmetric" "end")
CYCLES=5 KILL_AFTER=2 resume_test
