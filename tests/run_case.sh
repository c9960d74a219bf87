#!/bin/sh
# Test driver: run_case.sh SIGNORINI FILE.prm [PROCESSES MPIEXEC]
# Prints the program's output, its exit status, the files it wrote, the
# statistics table it wrote, and the verdict of every check listed in
# FILE.checks (if that file exists). With PROCESSES > 1 (an MPI variant,
# NAME.mpirun=N.output) the program runs as `MPIEXEC PROCESSES SIGNORINI
# FILE.prm` (MPIEXEC: the launcher and its flags up to the number, e.g.
# `mpiexec --quiet -n`), and all of that is printed the same way.
# Every run has a temporary folder of its own (TMPDIR), removed afterwards:
# Open MPI keeps its session directory there, and runs that share one race
# for it (one run removing the shared folder ompi.HOST.UID as it ends while
# another creates its own in it: "mkdir ... File exists", "orte_init
# failed").
# If FILE.args exists, its words are the program's arguments instead of
# FILE.prm (the word FILE stands for FILE.prm): a test of the command line.
# A check line reads   ROW COLUMN OP VALUE [TOLERANCE]
#   ROW:   a cycle number, `last` or `all`; or `rate` (`rate:K`): the check
#          is on the observed rate, the least-squares slope of log COLUMN
#          against log dofs over all cycles (from cycle K on). With a load
#          history (Load history/Steps > 1) a number counts the rows, one
#          per step: row K is step K % Steps + 1 of cycle K / Steps
#   OP:    near (|x-VALUE| <= TOLERANCE), rnear (relative), lt, le, gt, ge;
#          or `decreasing` / `increasing` (no VALUE): every row below /
#          above the one before
#   VALUE: a number, or [OFFSET+]NUMBER*NAME: the number times the row's
#          column NAME (e.g. -21.978*time, a force proportional to the load
#          history's t), plus OFFSET (0.002+2*penalty_parameter; a - before
#          NUMBER subtracts)
# Checks print PASS or FAIL, so the comparison (compare.py) turns a violated
# bound into a failing test even where the bound is far tighter than the
# comparison's own tolerance.
# If FILE.roundoff exists, it holds a cycle K: from cycle K on, the mesh was
# chosen by round-off (a patch test's Kelly indicators are 1e-19, and which
# cells they refine differs between processors), so the numbers of cells and
# dofs of those cycles print as `#`, in the program's `Cycle` lines and in
# the statistics; the test's checks say what must hold of them instead.
program=$1
prm=$2
processes=${3:-1}
mpiexec=${4:-mpiexec -n}
# deal.II's test runner keeps a file `output` here: run one folder down.
rm -rf run && mkdir run && cd run || exit 1
TMPDIR=$(mktemp -d "${TMPDIR:-/tmp}/signorini-test.XXXXXX") || exit 1
export TMPDIR
trap 'rm -rf "$TMPDIR"' EXIT
launcher=
# shellcheck disable=SC2086 # MPIEXEC is a command and its flags
[ "$processes" -gt 1 ] && launcher="$mpiexec $processes"
if [ -f "${prm%.prm}.args" ]; then
  # shellcheck disable=SC2046,SC2086 # the words of the file are the arguments
  $launcher "$program" $(sed "s|FILE|$prm|g" "${prm%.prm}.args") > run.log 2>&1
else
  # shellcheck disable=SC2086
  $launcher "$program" "$prm" > run.log 2>&1
fi
status=$?
roundoff=-1
[ -f "${prm%.prm}.roundoff" ] && roundoff=$(cat "${prm%.prm}.roundoff")
# Messages name files by absolute path, and the memory of the machine; keep
# the output independent of both.
sed -e "s|$(dirname "$prm")/||g" \
  -e 's|[0-9.e+]* GB are available|(machine) GB are available|' run.log |
  awk -v from="$roundoff" '
    from >= 0 && /^Cycle [0-9]+: [0-9]+ cells, [0-9]+ dofs/ &&
      substr($2, 1, length($2) - 1) + 0 >= from {
      print "Cycle " $2 " # cells, # dofs"; next }
    { print }'
echo "exit status: $status"
stats=$(find . -name statistics.csv | sort | head -n 1)
written=$(find . -type f ! -path ./run.log | sed 's|^\./||' | LC_ALL=C sort)
[ -n "$written" ] && { echo "files written:"; echo "$written"; }
[ -n "$stats" ] && {
  echo "statistics.csv:"
  awk -F, -v OFS=, -v from="$roundoff" '
    NR > 1 && from >= 0 && $1 + 0 >= from { $2 = "#"; $3 = "#" }
    { print }' "$stats"
}
# A load history's table of the obstacles' travel and forces.
table=$(find . -name force_displacement.csv | sort | head -n 1)
[ -n "$table" ] && { echo "force_displacement.csv:"; cat "$table"; }
checks="${prm%.prm}.checks"
[ -f "$checks" ] || exit 0
if [ -z "$stats" ]; then
  echo "checks: FAIL (no statistics.csv)"
  exit 0
fi
awk -F, -v checks="$checks" '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { rows = NR - 1; for (i = 1; i <= NF; ++i) value[rows, i] = $i }
  function ok(x, op, v, tol) {
    if (op == "near")  return (x - v <= tol && v - x <= tol)
    if (op == "rnear") return (x - v <= tol * (v < 0 ? -v : v) && v - x <= tol * (v < 0 ? -v : v))
    if (op == "lt") return x < v
    if (op == "le") return x <= v
    if (op == "gt") return x > v
    if (op == "ge") return x >= v
    return 0
  }
  END {
    while ((getline line < checks) > 0) {
      if (line ~ /^[ \t]*(#|$)/) continue
      n = split(line, w, /[ \t]+/)
      if (w[1] == "") { for (i = 1; i < n; ++i) w[i] = w[i + 1]; --n }
      row = w[1]; name = w[2]; op = w[3]; v = w[4] + 0; tol = w[5] + 0
      # VALUE as NUMBER*NAME: times column NAME of each row.
      by = ""; offset = 0
      if (w[4] ~ /\*/) {
        by = substr(w[4], index(w[4], "*") + 1)
        factor = substr(w[4], 1, index(w[4], "*") - 1)
        # OFFSET+NUMBER: split at the last sign that follows a digit or a
        # point (not that of an exponent).
        split_at = 0
        for (i = 2; i <= length(factor); ++i)
          if (substr(factor, i, 1) ~ /[-+]/ && substr(factor, i - 1, 1) ~ /[0-9.]/)
            split_at = i
        if (split_at) { offset = substr(factor, 1, split_at - 1) + 0
                        factor = substr(factor, split_at) }
        v = factor + 0 }
      verdict = "PASS"
      if (!(name in col)) verdict = "FAIL (no column " name ")"
      else if (by != "" && !(by in col)) verdict = "FAIL (no column " by ")"
      else if (row ~ /^rate/) {
        from = (row ~ /^rate:/) ? substr(row, 6) + 0 : 0
        n_fit = sx = sy = sxx = sxy = 0
        for (r = from + 1; r <= rows; ++r) {
          e = value[r, col[name]] + 0; if (e < 0) e = -e
          x = log(value[r, col["dofs"]]); y = log(e)
          ++n_fit; sx += x; sy += y; sxx += x * x; sxy += x * y
        }
        if (n_fit < 2) verdict = "FAIL (fewer than two rows)"
        else {
          slope = (n_fit * sxy - sx * sy) / (n_fit * sxx - sx * sx)
          if (!ok(slope, op, v, tol)) verdict = sprintf("FAIL (%.3f)", slope)
          else verdict = sprintf("PASS (%.2f)", slope)
        }
      }
      else if (op == "decreasing" || op == "increasing") {
        for (r = 2; r <= rows && verdict == "PASS"; ++r) {
          step = value[r, col[name]] - value[r - 1, col[name]]
          if (!(op == "decreasing" ? step < 0 : step > 0))
            verdict = "FAIL (cycle " (r - 1) ": " value[r, col[name]] ")"
        }
      }
      else {
        first = (row == "all") ? 1 : (row == "last" ? rows : row + 1)
        last  = (row == "all") ? rows : first
        if (first < 1 || last > rows) verdict = "FAIL (no row " row ")"
        for (r = first; r <= last && verdict == "PASS"; ++r) {
          target = (by == "") ? v : offset + v * value[r, col[by]]
          if (!ok(value[r, col[name]] + 0, op, target, tol)) verdict = "FAIL (" value[r, col[name]] ")"
        }
      }
      printf "check: %s %s %s %s %s: %s\n", row, name, op, w[4], (n > 4 ? w[5] : ""), verdict
    }
  }' "$stats"
