# Checkpoints you can trust. A run stopped by SIGTERM after a checkpoint;
# each piece of that checkpoint (the p4est mesh, the .info, the cell data,
# the state) truncated to half, with one byte changed, or deleted: --resume
# refuses it in one line naming the file, status 1, and leaves the output
# folder as it was. A checkpoint without its state file is one whose writing
# was stopped: passed over with a note, the run starts at cycle 0. Then with
# an older intact checkpoint beside the damaged newest one: --resume says so
# in one line, resumes from the older one and gives the uninterrupted run's
# results.
source "$TESTS/common.bash"
source "$TESTS/consistency.bash"
cycles=("subsection Mesh refinement" "  set Number of cycles = 5" "end")
scene reference.prm reference "${cycles[@]}"
"$SIGNORINI" reference.prm > reference.log 2>&1
echo "uninterrupted run: exit status $?"
scene scene.prm out "${cycles[@]}"
"$SIGNORINI" scene.prm > run.log 2> run.err &
pid=$!
wait_for out/solution-00.vtu
kill -TERM $pid
wait $pid
echo "stopped by SIGTERM: exit status $?"
LAST=$(last_cycle out)
echo "files end at the same cycle: $(consistent out)"
echo "stopped before the last cycle:" $([ "$LAST" -lt 4 ] && echo yes || echo no)
mv out stopped
name=$(printf 'checkpoint-%02d' "$LAST")

# flip FILE: changes the byte in the middle of FILE.
flip() {
  local offset=$(($(stat -c %s "$1") / 2)) byte
  byte=$(od -An -tu1 -j $offset -N 1 "$1" | tr -d ' ')
  printf "$(printf '\\%03o' $((byte ^ 0x20)))" |
    dd of="$1" bs=1 seek=$offset conv=notrunc 2> /dev/null
}

# damage FILE HOW: truncate, flip or delete FILE.
damage() {
  case $2 in
    truncated) truncate -s $(($(stat -c %s "$1") / 2)) "$1" ;;
    changed) flip "$1" ;;
    deleted) rm "$1" ;;
  esac
}

for piece in mesh mesh.info mesh_fixed.data mesh_variable.data state; do
  for how in truncated changed deleted; do
    rm -rf out && cp -r stopped out
    damage out/$name.$piece $how
    (cd out && find . -type f -exec md5sum {} + | LC_ALL=C sort) > before.txt
    echo "checkpoint-NN.$piece $how:"
    run "$SIGNORINI" --resume scene.prm | without_cycle | sed "s/$name/checkpoint-NN/g" |
      sed 's/([0-9]* of [0-9]* bytes)/(K of M bytes)/; s/([0-9]* bytes,/(K bytes,/'
    if [ $piece = state ] && [ $how = deleted ]; then
      grep -E "^(Checkpoint of cycle|No checkpoint)" run.log | without_cycle |
        sed "s/$name/checkpoint-NN/g"
      echo "  statistics.csv equals the uninterrupted run's to 1e-8:" \
        $(same_statistics out/statistics.csv reference/statistics.csv)
      continue
    fi
    (cd out && find . -type f -exec md5sum {} + | LC_ALL=C sort) > after.txt
    echo "  output folder unchanged:" $(cmp -s before.txt after.txt && echo yes || echo no)
  done
done

echo "the whole run resumed from the intact checkpoint:"
rm -rf out && cp -r stopped out
run "$SIGNORINI" --resume scene.prm
echo "  statistics.csv equals the uninterrupted run's to 1e-8:" \
  $(same_statistics out/statistics.csv reference/statistics.csv)
mv out finished

for damaged in "checkpoint-04.mesh_fixed.data truncated" \
  "checkpoint-04.mesh changed" "checkpoint-04.state deleted"; do
  set -- $damaged
  echo "beside an older intact checkpoint, $1 $2:"
  rm -rf out && cp -r finished out && cp stopped/$name.* out/
  damage out/$1 $2
  run "$SIGNORINI" --resume scene.prm | without_cycle |
    sed 's/([0-9]* of [0-9]* bytes)/(K of M bytes)/'
  grep "^Checkpoint of cycle" run.log
  echo "  resumed:" $(grep -q "^Resuming after cycle $LAST from out/$name.state" run.log &&
    echo "from the older checkpoint" || echo "not from the older checkpoint")
  echo "  statistics.csv equals the uninterrupted run's to 1e-8:" \
    $(same_statistics out/statistics.csv reference/statistics.csv)
  echo "  files end at the same cycle: $(consistent out)"
done
