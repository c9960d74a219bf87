# Helpers for the scripted tests of interrupted, failed and resumed runs
# (sourced after common.bash).

# consistent DIRECTORY: whether the run's files in DIRECTORY end at the same
# cycle: statistics.csv has the rows 0..N, solution.pvd lists the cycles
# 0..N and each file it lists exists, no solution or contact pressure file
# of a later cycle, the checkpoint (if any) is exactly checkpoint-N.* with
# its state file, and no temporary *.part file. Prints "yes" or what
# differs.
consistent() {
  local dir=$1 faults=() rows entries cycle file name LAST
  LAST=$(last_cycle "$dir")
  rows=$(($(wc -l < "$dir/statistics.csv") - 1))
  [ "$rows" -eq $((LAST + 1)) ] || faults+=("statistics.csv has $rows rows")
  entries=$(grep -o 'file="[^"]*"' "$dir/solution.pvd" | wc -l)
  [ "$entries" -eq $((LAST + 1)) ] ||
    faults+=("solution.pvd lists $entries cycles, statistics.csv $((LAST + 1))")
  for file in $(grep -o 'file="[^"]*"' "$dir/solution.pvd" | sed 's/file="//; s/"//'); do
    [ -f "$dir/$file" ] || faults+=("solution.pvd lists the missing $file")
  done
  for file in $(cd "$dir" && ls); do
    case $file in
      *.part) faults+=("temporary $file left") ;;
      solution-[0-9]*|contact_pressure-[0-9]*|checkpoint-[0-9]*)
        cycle=$(echo "$file" | sed -E 's/^[a-z_]+-0*([0-9]+).*/\1/')
        [ "$cycle" -le "$LAST" ] || faults+=("$file is of a later cycle")
        case $file in
          checkpoint-*) [ "$cycle" -eq "$LAST" ] ||
            faults+=("$file is not of cycle $LAST") ;;
        esac ;;
    esac
  done
  if ls "$dir"/checkpoint-* > /dev/null 2>&1; then
    name=$(printf 'checkpoint-%02d' "$LAST")
    for file in $name.mesh $name.mesh.info $name.mesh_fixed.data \
      $name.mesh_variable.data $name.state; do
      [ -f "$dir/$file" ] || faults+=("$file missing")
    done
  fi
  if [ ${#faults[@]} -eq 0 ]; then echo yes; else printf '%s; ' "${faults[@]}"; echo; fi
}

# last_cycle DIRECTORY: the cycle of the last row of statistics.csv.
last_cycle() {
  tail -n 1 "$1/statistics.csv" | cut -d, -f1
}

# same_statistics A B [ABSOLUTE]: whether two statistics.csv files agree to
# 1e-8 relative or ABSOLUTE (1e-8 unless given).
same_statistics() {
  numdiff -q -a "${3:-1e-8}" -r 1e-8 -s ' \t\n,' "$1" "$2" > /dev/null && echo yes || echo no
}

# wait_for FILE: waits until FILE exists (at most two minutes).
wait_for() {
  local i
  for i in $(seq 12000); do
    [ -e "$1" ] && break
    sleep 0.01
  done
}

# without_cycle LINE: the line with its cycle number replaced by N.
without_cycle() {
  sed -E 's/cycle [0-9]+/cycle N/g'
}
