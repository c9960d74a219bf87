# Writes that fail, as on a full disk: a file-size limit (ulimit -f, which
# works for root too) makes the write that reaches it fail with EFBIG, a
# directory in the place of a file fails its write too. Each failure is one
# line naming the file and the system's reason, status 5; no temporary
# *.part file and no incomplete checkpoint is left, the files of finished
# cycles stay, and the series ends at one cycle in solution.pvd and
# statistics.csv (and the checkpoint, unless its own write failed after
# the cycle's solution was complete). A run stopped so resumes to the
# uninterrupted run's results.
source "$TESTS/common.bash"
source "$TESTS/consistency.bash"
# MPI's own shared-memory files would exceed the limit: Open MPI keeps its
# process data in a hash and talks over TCP here.
export PMIX_MCA_gds=hash OMPI_MCA_btl=self,tcp
# The solution files zlib-compressed (the sizes below are zlib's).
cycles=("subsection Mesh refinement" "  set Number of cycles = 5" "end"
  "subsection Output" "  set Compression = zlib" "end")
scene reference.prm reference "${cycles[@]}"
"$SIGNORINI" reference.prm > reference.log 2>&1
echo "uninterrupted run: exit status $?"

# limited KB COMMAND...: runs COMMAND with files limited to KB kilobytes.
limited() {
  local kb=$1
  shift
  (ulimit -f "$kb" && run "$@")
}

echo "solution-02.vtu (78 kB) beyond a limit of 60 kB, no checkpoints:"
scene plain.prm plain "${cycles[@]}" \
  "subsection Output" "  set Checkpoint = false" "end"
limited 60 "$SIGNORINI" plain.prm
echo "  files end at the same cycle: $(consistent plain), cycle $(last_cycle plain)"

# A checkpoint is smaller than the solution file of its cycle, which is
# written after it: no file-size limit fails the checkpoint alone.
echo "a directory in the place of checkpoint-03.mesh_variable.data:"
scene scene.prm out "${cycles[@]}"
mkdir -p out/checkpoint-03.mesh_variable.data/in_the_way
run "$SIGNORINI" scene.prm
echo "  cycles finished: $(last_cycle out); temporary files left:" \
  "$(ls out | grep -c '\.part$'); checkpoint files:" \
  $(cd out && ls -d checkpoint-* | tr '\n' ' ')
rm -r out/checkpoint-03.mesh_variable.data
echo "resumed without the directory:"
run "$SIGNORINI" --resume scene.prm
grep "^Resuming" run.log
echo "  statistics.csv equals the uninterrupted run's to 1e-8:" \
  $(same_statistics out/statistics.csv reference/statistics.csv)

echo "two processes, solution-02.0000.vtu (38 kB) beyond a limit of 30 kB:"
limited 30 mpirun -np 2 "$SIGNORINI" plain.prm
echo "  lines from signorini: $(grep -c "^signorini" run.err)"
echo "  files end at the same cycle: $(consistent plain), cycle $(last_cycle plain)"

echo "a directory in the place of statistics.csv:"
rm -rf plain && mkdir -p plain/statistics.csv
run "$SIGNORINI" plain.prm
echo "files:"
files plain
