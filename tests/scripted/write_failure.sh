# Writes that fail, as on a full disk: a file-size limit (ulimit -f, which
# works for root too) makes the write that reaches it fail with EFBIG. Each
# failure is one line naming the file and the system's reason, status 5; no
# temporary *.part file and no incomplete checkpoint is left, and the
# series ends at one cycle in solution.pvd, statistics.csv and the
# checkpoint. A run stopped so resumes to the uninterrupted run's results.
source "$TESTS/common.bash"
source "$TESTS/consistency.bash"
# MPI's own shared-memory files would exceed the limit: Open MPI keeps its
# process data in a hash and talks over TCP here.
export PMIX_MCA_gds=hash OMPI_MCA_btl=self,tcp
# The solution files zlib-compressed: LZ4's are larger than the checkpoint
# of their cycle, and no limit would fall between the two (the sizes below
# are zlib's).
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

echo "checkpoint-03.mesh_fixed.data (150 kB) beyond a limit of 100 kB:"
scene scene.prm out "${cycles[@]}"
limited 100 "$SIGNORINI" scene.prm
echo "  files end at the same cycle: $(consistent out), cycle $(last_cycle out)"
echo "resumed without the limit:"
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
