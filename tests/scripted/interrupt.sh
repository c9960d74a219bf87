# SIGTERM or SIGINT in the middle of a run: the run stops at its next
# collective point (before a cycle or a Newton step), prints one line and
# exits with 128 + the signal; solution.pvd, statistics.csv, the solution
# files and the checkpoint end at the same cycle, no temporary is left, and
# --resume then gives the uninterrupted run's results. The signal is sent as
# soon as (or 0.1 s after) a file of cycle 0 or 1 appears, which lands it in
# the next cycle's Newton steps, its refinement or the output of a cycle,
# depending on the moment.
source "$TESTS/common.bash"
source "$TESTS/consistency.bash"
cycles=("subsection Mesh refinement" "  set Number of cycles = 9" "end")
scene reference.prm reference "${cycles[@]}"
"$SIGNORINI" reference.prm > reference.log 2>&1
echo "uninterrupted run: exit status $?"
scene scene.prm out "${cycles[@]}"
for stop in "TERM solution-00.vtu 0" "INT solution.pvd 0" \
  "TERM solution-01.vtu 0" "TERM solution-01.vtu 0.1"; do
  set -- $stop
  rm -rf out
  "$SIGNORINI" scene.prm > run.log 2> run.err &
  pid=$!
  wait_for "out/$2"
  sleep $3
  kill -"$1" $pid
  wait $pid
  echo "SIG$1 $3 s after out/$2 appeared: exit status $?"
  grep "^signorini" run.err | without_cycle
  LAST=$(last_cycle out)
  echo "  files end at the same cycle: $(consistent out)"
  echo "  the line names that cycle:" \
    $(grep -q "after cycle $LAST;" run.err && echo yes || echo no)
  echo "  stopped before the last cycle:" $([ "$LAST" -lt 8 ] && echo yes || echo no)
  "$SIGNORINI" --resume scene.prm > resume.log 2> resume.err
  echo "  resumed: exit status $?," \
    $(grep -q "^Resuming after cycle $LAST from out/checkpoint-0$LAST.state" resume.log &&
      echo "after that cycle" || echo "not after that cycle")
  cat resume.err
  echo "  statistics.csv equals the uninterrupted run's to 1e-8:" \
    $(same_statistics out/statistics.csv reference/statistics.csv)
  echo "  files end at the same cycle: $(consistent out)"
done

echo "without checkpoints:"
scene plain.prm plain "${cycles[@]}" \
  "subsection Output" "  set Checkpoint = false" "end"
"$SIGNORINI" plain.prm > run.log 2> run.err &
pid=$!
wait_for plain/solution-00.vtu
kill -TERM $pid
wait $pid
echo "exit status: $?"
grep "^signorini" run.err | without_cycle
echo "  files end at the same cycle: $(consistent plain)"
