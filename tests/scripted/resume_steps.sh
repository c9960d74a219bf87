# Checkpoints after every load step: a run of a load history killed
# (SIGKILL) once the checkpoint of a load step in the middle of a cycle is
# written resumes with the next step of that cycle, on its mesh, from the
# displacement, contact pressure and shear tractions of the checkpoint, and
# gives the uninterrupted run's statistics.csv, force_displacement.csv and
# contact pressure tables, and its solution.pvd and history.pvd. Five cases:
# the default scene ramped over six steps; the Cattaneo-Mindlin disk with
# Coulomb friction (pressed in two steps, then sheared in two: the slip of
# the shear steps is counted from the displacement of the step before, which
# the resumed run must start from); both killed on two processes, the
# default scene resumed on one (the same but for the iteration counts of the
# loose linear solves), the disk on two; and a SIGTERM between two steps,
# whose line names the step. The signal is sent once the checkpoint of step
# 1 of cycle 2 or later is written, before the cycle's last steps.
source "$TESTS/common.bash"
source "$TESTS/consistency.bash"

# scene_of NAME FILE DIRECTORY: the scene NAME (default, friction) writing
# DIRECTORY, with CYCLES cycles.
scene_of() {
  local name=$1 file=$2 directory=$3
  if [ "$name" = default ]; then
    scene "$file" "$directory" \
      "subsection Boundary conditions" "  set Traction = 0; -50*t" "end" \
      "subsection Load history" "  set Steps = 6" "end" \
      "subsection Mesh refinement" "  set Number of cycles = $CYCLES" "end"
  else
    {
      echo "include $PRM/cattaneo_mindlin.prm"
      echo "subsection Output"
      echo "  set Directory     = $directory"
      echo "  set Print timings = false"
      echo "  set Verbose       = false"
      echo "end"
      echo "subsection Load history"
      echo "  set Steps = 4"
      echo "end"
      echo "subsection Mesh refinement"
      echo "  set Number of cycles = $CYCLES"
      echo "end"
    } > "$file"
  fi
}

# compare_runs SAME_COUNT [TOLERANCE] [ITERATIONS]: the tables of out/
# against those of reference/, to TOLERANCE (1e-8 unless given); with
# SAME_COUNT = no (resumed on another number of processes) all but the
# iteration counts, and not the series, whose files differ (a .pvtu with a
# piece per process, or one .vtu); with ITERATIONS = no, the series but not
# the iteration counts.
compare_runs() {
  local table tolerance=${2:-1e-8}
  for table in statistics.csv force_displacement.csv $(cd reference && ls contact_pressure-*.csv 2> /dev/null); do
    if { [ "$1" = no ] || [ "${3:-yes}" = no ]; } && [ $table = statistics.csv ]; then
      cut -d, -f6 --complement out/$table > out.csv
      cut -d, -f6 --complement reference/$table > reference.csv
      echo "  $table equals the uninterrupted run's to $tolerance but for the iteration counts:" \
        $(numdiff -q -a $tolerance -r $tolerance -s ' \t\n,' out.csv reference.csv > /dev/null && echo yes || echo no)
    else
      echo "  $table equals the uninterrupted run's to $tolerance:" \
        $(numdiff -q -a $tolerance -r $tolerance -s ' \t\n,' out/$table reference/$table > /dev/null && echo yes || echo no)
    fi
  done
  echo "  checkpoint left:" $(cd out && ls checkpoint-*.state)
  [ "$1" = no ] && return
  # (The first lines of a PVD file say when it was written.)
  for table in solution.pvd history.pvd; do
    echo "  $table equals the uninterrupted run's:" \
      $(cmp -s <(grep -v generated out/$table) <(grep -v generated reference/$table) && echo yes || echo no)
  done
  local missing=0 file
  for file in $(grep -ho 'file="[^"]*"' out/solution.pvd out/history.pvd | sed 's/file="//; s/"//'); do
    [ -f "out/$file" ] || missing=$((missing + 1))
  done
  echo "  every file they list exists:" $([ $missing -eq 0 ] && echo yes || echo "no ($missing missing)")
  echo "  the same files as the uninterrupted run:" \
    $(diff <(files out | grep -v '^checkpoint') <(files reference | grep -v '^checkpoint') > /dev/null && echo yes || echo no)
}

# resume_case NAME SIGNAL KILLED_ON RESUMED_ON [TOLERANCE]: scene NAME run
# whole on KILLED_ON processes, run again and sent SIGNAL (every process)
# once the checkpoint of load step 1 of cycle 2 or later is written, then
# resumed on RESUMED_ON processes.
resume_case() {
  local name=$1 signal=$2 killed_on=$3 resumed_on=$4 tolerance=${5:-1e-8} launch=() resume=() pid status
  [ "$killed_on" -gt 1 ] && launch=(mpirun -np "$killed_on")
  [ "$resumed_on" -gt 1 ] && resume=(mpirun -np "$resumed_on")
  echo "$name scene, SIG$signal on $killed_on process(es), resumed on $resumed_on:"
  rm -rf out reference
  scene_of "$name" reference.prm reference
  scene_of "$name" scene.prm out
  "${launch[@]}" "$SIGNORINI" reference.prm > reference.log 2>&1
  echo "  uninterrupted run: exit status $?"
  "${launch[@]}" "$SIGNORINI" scene.prm > killed.log 2> killed.err &
  pid=$!
  local i
  for i in $(seq 12000); do
    ls out/checkpoint-0[2-$((CYCLES - 1))]-001.state > /dev/null 2>&1 && break
    sleep 0.01
  done
  if [ "$signal" = KILL ]; then
    kill -KILL $(ps -o pid= --ppid $pid) $pid 2> /dev/null
  else
    kill -"$signal" $pid
  fi
  wait $pid 2> /dev/null
  status=$?
  echo "  stopped: exit status $status"
  grep "^signorini" killed.err | sed -E 's/(step|cycle) [0-9]+/\1 N/g'
  # The newest checkpoint is a step's (checkpoint-CC-SSS sorts before
  # checkpoint-CC; an older one may still be there, being removed).
  echo "  stopped within a cycle's history:" \
    $(ls out/checkpoint-*.state 2> /dev/null | sort | tail -n 1 |
      grep -qE -- '-[0-9]{2}-[0-9]{3}\.state$' && echo yes || echo no)
  "${resume[@]}" "$SIGNORINI" --resume scene.prm > resume.log 2> resume.err
  echo "  resumed: exit status $?"
  cat resume.err
  echo "  resumed after a load step within a cycle:" \
    $(grep -qE "^Resuming after load step [0-9]+ of cycle [2-9] from out/checkpoint-0[2-9]-[0-9]{3}\.state" resume.log &&
      echo yes || echo no)
  # On several processes the resumed run's partition is not the
  # uninterrupted one's: the loose linear solves of the Newton steps, and
  # with friction where they turn tight, may differ in iteration counts.
  compare_runs $([ "$killed_on" = "$resumed_on" ] && echo yes || echo no) $tolerance \
    $([ "$resumed_on" -gt 1 ] && echo no || echo yes)
}

CYCLES=5 resume_case default KILL 1 1
CYCLES=4 resume_case friction KILL 1 1
CYCLES=5 resume_case default KILL 2 1
# On two processes the loaded mesh is partitioned evenly, where the
# uninterrupted run's refinement kept its partition: the parallel solves'
# round-off differs, which the nearly incompressible disk (nu = 0.4999)
# magnifies to 1e-7 (the uninterrupted runs on one and on two processes
# differ by 2.4e-7).
CYCLES=4 resume_case friction KILL 2 2 1e-6
CYCLES=5 resume_case default TERM 1 1
