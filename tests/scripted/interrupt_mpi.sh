# interrupt.sh on two processes. SIGTERM to mpirun, which forwards it to
# both processes (after a SIGCONT and a second's wait, and kills them a
# second later); SIGINT to both processes themselves (as a batch system
# signals every task).
# The processes agree on where to stop: one line, the files end at the same
# cycle, --resume on two processes gives the uninterrupted run's results, to
# the suite's tolerance (1e-6 absolute; the iteration counts exactly).
# Then the newest checkpoint damaged under mpirun: one line on two processes.
source "$TESTS/common.bash"
source "$TESTS/consistency.bash"
cycles=("subsection Mesh refinement" "  set Number of cycles = 12" "end")
scene reference.prm reference "${cycles[@]}"
mpirun -np 2 "$SIGNORINI" reference.prm > reference.log 2>&1
echo "uninterrupted run: exit status $?"
scene scene.prm out "${cycles[@]}"
for stop in "TERM solution-00.pvtu mpirun" "INT solution-01.pvtu processes"; do
  set -- $stop
  rm -rf out
  mpirun -np 2 "$SIGNORINI" scene.prm > run.log 2> run.err &
  pid=$!
  wait_for "out/$2"
  if [ "$3" = mpirun ]; then
    kill -"$1" $pid
  else
    kill -"$1" $(ps -o pid= --ppid $pid)
  fi
  wait $pid
  status=$?
  echo "SIG$1 to $3 once out/$2 exists:"
  # mpirun reports 1 when it was signalled itself, else the processes'.
  echo "  exit status: $status"
  grep "^signorini" run.err | without_cycle
  LAST=$(last_cycle out)
  echo "  files end at the same cycle: $(consistent out)"
  echo "  the line names that cycle:" \
    $(grep -q "after cycle $LAST;" run.err && echo yes || echo no)
  echo "  stopped before the last cycle:" $([ "$LAST" -lt 11 ] && echo yes || echo no)
  mpirun -np 2 "$SIGNORINI" --resume scene.prm > resume.log 2> resume.err
  echo "  resumed: exit status $?," \
    $(grep -q "^Resuming after cycle $LAST from out/$(printf "checkpoint-%02d" "$LAST").state" resume.log &&
      echo "after that cycle" || echo "not after that cycle")
  grep "^signorini" resume.err
  echo "  statistics.csv equals the uninterrupted run's to 1e-8 relative, 1e-6 absolute:" \
    $(same_statistics out/statistics.csv reference/statistics.csv 1e-6)
  echo "  files end at the same cycle: $(consistent out)"
done

echo "a byte of the checkpoint's mesh flipped, resumed on two processes:"
newest=out/$(printf 'checkpoint-%02d' "$(last_cycle out)").mesh
printf '\377' | dd of="$newest" bs=1 seek=4000 conv=notrunc 2> /dev/null
run mpirun -np 2 "$SIGNORINI" --resume scene.prm 2>&1 | sed 's/checkpoint-[0-9]*/checkpoint-NN/'
