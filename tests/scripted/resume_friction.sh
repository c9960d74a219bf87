# resume.sh with Coulomb friction and no load history (the Hertz cylinder,
# mu = 0.3): the next cycle's stick and slip states start from the shear
# tractions the refined mesh carries over, which the checkpoint stores, so
# the resumed run takes the uninterrupted run's Newton steps and gives its
# statistics (iteration counts included) to 1e-8.
source "$TESTS/common.bash"
scene() {
  local file=$1 directory=$2
  shift 2
  {
    echo "include $PRM/hertz_cylinder.prm"
    echo "subsection Output"
    echo "  set Directory     = $directory"
    echo "  set Print timings = false"
    echo "  set Verbose       = false"
    echo "end"
    for line in "$@"; do echo "$line"; done
  } > "$file"
}
SCENE=("subsection Obstacle" "  set Friction coefficient = 0.3" "end")
CYCLES=7 KILL_AFTER=3 resume_test
