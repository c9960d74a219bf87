# Frictionless contact is path independent: the last step of a load
# history equals a run of one step with the same final load, on every
# cycle, to 1e-10 relative (every column of statistics.csv but the
# iterations, each relative to the largest of its kind in the run: forces,
# displacements, or the column itself; the equilibrium mismatch, a
# round-off quantity, to 1e-10 absolute), with the same meshes and contact
# sets. One scene for each kind of entry of t: an obstacle's
# Displacement (the flat punch, as in load_history_punch.prm), a Traction (the
# Hertz cylinder, whose contact zone grows over the steps), a Prescribed
# displacement (the split ring on triangles, remeshed by Gmsh) and a
# Traction resultant (the axisymmetric Hertz sphere, F ~ t^1.5). The
# punch's chart script draws its curve with gnuplot.
history() {
  local name=$1 steps=$2 cycles=$3 include=$4
  shift 4
  for run in history single; do
    {
      echo "include $include"
      for line in "$@"; do echo "$line"; done
      echo "subsection Load history"
      echo "  set Steps = $([ $run = history ] && echo "$steps" || echo 1)"
      echo "end"
      echo "subsection Mesh refinement"
      echo "  set Number of cycles = $cycles"
      echo "end"
      echo "subsection Output"
      echo "  set Directory              = $name-$run"
      echo "  set Contact pressure table = false"
      echo "  set Print timings          = false"
      echo "  set Verbose                = false"
      echo "end"
    } > $name-$run.prm
    "$SIGNORINI" $name-$run.prm > $name-$run.log 2>&1
    echo "$name, $([ $run = history ] && echo "$steps steps" || echo "1 step"): exit status $?"
  done
}
history punch 4 3 "$PRM/flat_punch_axisymmetric.prm" \
  "subsection Obstacle" "  set Displacement = 0, -0.01*t" "end"
history hertz 4 4 "$PRM/hertz_cylinder.prm" \
  "subsection Boundary conditions" "  set Traction = 0; -5*t" "end"
history ring 4 3 "$PRM/split_ring.prm" \
  "subsection Boundary conditions" "  set Prescribed displacement = 0; -0.05*t" "end"
history sphere 3 4 "$PRM/hertz_sphere_axisymmetric.prm" \
  "subsection Boundary conditions" "  set Traction resultant = 0, -1.5*t^1.5" "end"
/usr/bin/python3 - <<'PYTHON'
import csv, os

def rows(directory, name="statistics.csv"):
    with open(directory + "/" + name) as f:
        return list(csv.DictReader(f))

def kind(column):
    if column.startswith(("contact_force", "support_reaction")):
        return "force"
    if column.startswith(("probe", "max_penetration")):
        return "displacement"
    return column

for name in ["punch", "hertz", "ring", "sphere"]:
    history, single = rows(name + "-history"), rows(name + "-single")
    steps = max(int(r["step"]) for r in history)
    last = [r for r in history if int(r["step"]) == steps]
    scale = {}
    for column in single[0]:
        largest = max(abs(float(r[column])) for r in single)
        scale[kind(column)] = max(scale.get(kind(column), 0.), largest)
    worst, same = 0., len(last) == len(single)
    worst_column = ""
    for a, b in zip(last, single):
        same = same and all(a[c] == b[c] for c in ("cycle", "cells", "dofs",
                                                   "active_set"))
        for column in b:
            if column == "iterations":
                continue
            x, y = float(a[column]), float(b[column])
            floor = (1. if column == "equilibrium_error"
                     else scale[kind(column)])
            size = max(abs(x), abs(y), floor)
            if size > 0 and abs(x - y) / size > worst:
                worst, worst_column = abs(x - y) / size, column
        print("%s cycle %s: %s dofs, %s active, contact force y %.6e"
              % (name, b["cycle"], b["dofs"], b["active_set"],
                 float(b["contact_force_y"])))
    if os.environ.get("SIGNORINI_SHOW_DIFFERENCE"):
        print("  (largest relative difference %.1e, %s)"
              % (worst, worst_column))
    print("%s: %d rows of %d steps; last steps equal the one-step run's "
          "(same meshes and contact sets, every column within 1e-10): %s"
          % (name, len(history), steps,
             "PASS" if same and worst < 1e-10 else "FAIL"))

# The punch's contact set does not change with t: its force is linear in
# the travel, step by step, on every cycle.
table = rows("punch-history", "force_displacement.csv")
linear = True
for row in table:
    final = [r for r in table if r["cycle"] == row["cycle"]][-1]
    for column in ("displacement1_y", "force1_y"):
        ratio = float(row[column]) / float(final[column])
        linear = linear and abs(ratio - float(row["time"])) < 1e-10
print("punch: force_displacement.csv has %d rows, force and travel "
      "proportional to t to 1e-10: %s" % (len(table),
                                           "PASS" if linear else "FAIL"))
PYTHON
echo "punch history.pvd:"
grep -o 'timestep="[^"]*" group="" part="0" file="[^"]*"' punch-history/history.pvd
echo "punch force_displacement.gnuplot:"
cat punch-history/force_displacement.gnuplot
(cd punch-history && gnuplot force_displacement.gnuplot 2>&1)
echo "force_displacement.png drawn:" \
  $([ -s punch-history/force_displacement.png ] && echo yes || echo no)
