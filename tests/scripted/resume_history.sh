# resume.sh with a load history: the default scene's end load ramped over
# three steps (Traction = 0; -50 t), each cycle replaying them. Killed after
# the checkpoint of a cycle and resumed, the run replays the next cycle from
# t = 0 and gives the uninterrupted run's statistics (a row per step),
# force-displacement table and final cycle's history series.
source "$TESTS/common.bash"
SCENE=("subsection Boundary conditions" "  set Traction = 0; -50*t" "end"
  "subsection Load history" "  set Steps = 3" "end")
CYCLES=5 KILL_AFTER=2
resume_test
echo "force_displacement.csv equals the uninterrupted run's to 1e-8:" \
  $(numdiff -q -a 1e-8 -r 1e-8 -s ' \t\n,' out/force_displacement.csv \
    reference/force_displacement.csv > /dev/null && echo yes || echo no)
echo "history.pvd lists:"
grep -o 'timestep="[^"]*" group="" part="0" file="[^"]*"' out/history.pvd |
  while read -r entry; do
    file=${entry#*file=\"}; file=${file%\"}
    echo "  $entry" $([ -f "out/$file" ] && echo "(exists)" || echo "(MISSING)")
  done
