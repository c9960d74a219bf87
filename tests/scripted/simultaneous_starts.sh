# Ten runs of the program started at once, as a parameter sweep run in
# parallel starts them (`parallel scripts/run ::: *.prm`, two terminals):
# every one must start, finish and write its statistics. Open MPI keeps a
# session directory for each run (a singleton run too) in a folder that all
# runs of the user share, ompi.HOST.UID under the temporary folder, and a
# run that ends removes it once it is empty: a run starting at that moment
# failed ("A call to mkdir was unable to create the desired directory ...
# File exists", "orte_init failed"). The runs here share this test's
# temporary folder as a user's runs share /tmp; three rounds of ten, so
# that starts meet ends.
# shellcheck source=common.bash
source "$TESTS/common.bash"

scene tiny.prm out "subsection Mesh refinement" \
  "  set Number of cycles = 1" "end"
for round in 1 2 3; do
  for i in 0 1 2 3 4 5 6 7 8 9; do
    mkdir -p "run-$round-$i"
    (
      cd "run-$round-$i" || exit
      "$SIGNORINI" ../tiny.prm > log 2>&1
      echo $? > status
    ) &
  done
  wait
  started=0
  for i in 0 1 2 3 4 5 6 7 8 9; do
    folder=run-$round-$i
    if [ "$(cat "$folder/status")" = 0 ] && [ -s "$folder/out/statistics.csv" ]
    then
      started=$((started + 1))
    else
      echo "round $round, run $i: exit status $(cat "$folder/status"):"
      tail -n 5 "$folder/log"
    fi
  done
  echo "round $round: $started of 10 runs started at once ran and wrote" \
    "their statistics"
done
