# Helpers for the scripted tests (sourced).
# Open MPI refuses to run as root unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none

# scene FILE DIRECTORY [LINES...]: a variant of the default scene writing
# DIRECTORY, quiet, with the extra LINES (e.g. "subsection X" ... "end").
scene() {
  local file=$1 directory=$2
  shift 2
  {
    echo "include $PRM/cantilever_on_plane.prm"
    echo "subsection Output"
    echo "  set Directory     = $directory"
    echo "  set Print timings = false"
    echo "  set Verbose       = false"
    echo "end"
    for line in "$@"; do echo "$line"; done
  } > "$file"
}

# run [PROGRAM ARGUMENTS...]: runs and prints the exit status and the
# program's messages on standard error (not mpirun's own).
run() {
  "$@" > run.log 2> run.err
  echo "exit status: $?"
  grep "^signorini" run.err
}

# files DIRECTORY: the files in DIRECTORY, sorted.
files() {
  (cd "$1" && find . -type f | sed 's|^\./||' | LC_ALL=C sort)
}

# resume_test [LAUNCHER...]: the default scene with CYCLES cycles (6 unless
# set, and the lines of the array SCENE, if set) run whole, and run again,
# killed (SIGKILL, every process) once the checkpoint of cycle KILL_AFTER (2
# unless set, or a later one)
# is written, then resumed with --resume; the resumed results must equal the
# uninterrupted ones. LAUNCHER is e.g. `mpirun -np 2`.
resume_test() {
  local n=${CYCLES:-6} k=${KILL_AFTER:-2}
  local cycles=("${SCENE[@]}"
    "subsection Mesh refinement" "  set Number of cycles = $n" "end")
  local later="[$k-$((n - 1))]"
  scene reference.prm reference "${cycles[@]}"
  scene scene.prm out "${cycles[@]}"
  "$@" "$SIGNORINI" reference.prm > reference.log 2>&1
  echo "uninterrupted run: exit status $?"

  "$@" "$SIGNORINI" scene.prm > killed.log 2>&1 &
  local pid=$! i
  for i in $(seq 12000); do
    ls out/checkpoint-0$later.state > /dev/null 2>&1 && break
    sleep 0.01
  done
  # The program's processes: under mpirun its children, else itself.
  kill -KILL $(ps -o pid= --ppid $pid) $pid 2> /dev/null
  wait $pid 2> /dev/null
  local status=$?
  # The cycles with rows (a load history writes a row per step).
  local rows=$(tail -n +2 out/statistics.csv | cut -d, -f1 | sort -u | wc -l)
  echo "killed after a checkpoint, before the last cycle:" \
    $([ $status -ne 0 ] && [ $rows -lt $n ] && echo yes || echo "no (status $status, $rows cycles)")

  run "$@" "$SIGNORINI" --resume scene.prm
  # With a load history the kill may land after a step's checkpoint of the
  # cycle after KILL_AFTER (a loaded machine runs on while the test looks).
  echo "resumed:" $(grep -Eq "^Resuming after (load step [0-9]+ of )?cycle $later from out/checkpoint-0$later(-[0-9]{3})?\.state" run.log && echo yes || echo no)
  echo "statistics.csv equals the uninterrupted run's to 1e-8:" \
    $(numdiff -q -a 1e-8 -r 1e-8 -s ' \t\n,' out/statistics.csv reference/statistics.csv > /dev/null && echo yes || echo no)
  echo "solution.pvd lists:"
  grep -o 'file="[^"]*"' out/solution.pvd | while read -r entry; do
    file=${entry#file=\"}; file=${file%\"}
    echo "  $file" $([ -f "out/$file" ] && echo "(exists)" || echo "(MISSING)")
  done
  echo "files:"
  files out
  echo "statistics.csv:"
  cat out/statistics.csv

  echo "resumed again after the last cycle:"
  cp out/statistics.csv finished.csv
  run "$@" "$SIGNORINI" --resume scene.prm
  grep "cycles were finished" run.log
  cmp -s out/statistics.csv finished.csv && echo "statistics.csv unchanged"

  echo "resumed with a different parameter set:"
  scene other.prm out "${cycles[@]}" \
    "subsection Material" "  set Young's modulus = 2e5" "end"
  run "$@" "$SIGNORINI" --resume other.prm
  cmp -s out/statistics.csv finished.csv && echo "statistics.csv unchanged"
}
