# A vanishing friction coefficient reproduces the frictionless results. Each
# shipped scene with one obstacle (on fewer cycles) is run as it is and with
# Friction coefficient = 1e-12: the friction law then holds every node in
# contact (stick, or slip at a bound of 1e-12 times its pressure, by the
# non-symmetric Newton system), and every statistics column of the
# frictionless run must be the same, to 1e-10 of the column's largest
# value, plus 1e-9 absolute for the columns that are round-off (the
# tangential forces, which now hold mu N). Iterations may differ. The
# energy_error columns are compared squared: sqrt(|J_h - J| / |J|) turns the
# round-off of J into about 1e-7 where the solution is exact (the wedge),
# whose differences on another processor's kernels are 1e-9, beyond the
# tolerance (an AVX2 machine); their squares are the energy's own.
for entry in hertz_cylinder:4 cantilever_on_plane:4 clamped_beam_on_plane:4 \
  hertz_sphere_axisymmetric:4 flat_punch_axisymmetric:4 wedge_in_groove:3 \
  sphere_indentation:2; do
  name=${entry%%:*}
  cycles=${entry##*:}
  for variant in frictionless friction; do
    {
      echo "include $PRM/$name.prm"
      echo "subsection Mesh refinement"
      echo "  set Number of cycles = $cycles"
      echo "end"
      echo "subsection Output"
      echo "  set Directory              = $name-$variant"
      echo "  set Print timings          = false"
      echo "  set Verbose                = false"
      echo "  set Checkpoint             = false"
      echo "  set Contact pressure table = false"
      echo "end"
      if [ $variant = friction ]; then
        echo "subsection Obstacle"
        echo "  set Friction coefficient = 1e-12"
        echo "end"
      fi
    } > $name-$variant.prm
    "$SIGNORINI" $name-$variant.prm > $name-$variant.log 2>&1
    echo "$name, $variant: exit status $?"
  done
done
/usr/bin/python3 - <<'PYTHON'
import csv, glob

def rows(directory):
    with open(directory + "/statistics.csv") as f:
        return list(csv.DictReader(f))

for path in sorted(glob.glob("*-frictionless")):
    name = path[:-len("-frictionless")]
    a, b = rows(path), rows(name + "-friction")
    worst, where = 0., ""
    for column in a[0]:
        if column in ("iterations", "equilibrium_error") or column not in b[0]:
            continue
        scale = max(abs(float(r[column])) for r in a)
        power = 2 if column.endswith("energy_error") else 1
        scale = scale**power
        for ra, rb in zip(a, b):
            difference = abs(float(ra[column])**power -
                             float(rb[column])**power)
            excess = difference / (1e-10 * scale + 1e-9)
            if excess > worst:
                worst, where = excess, "%s on cycle %s" % (column, ra["cycle"])
    same = len(a) == len(b) and all(ra["dofs"] == rb["dofs"]
                                    for ra, rb in zip(a, b))
    # (The largest difference itself is round-off: printed on failure only.)
    print("%s: %d cycles, the same dofs: %s, within the tolerance: %s" %
          (name, len(a), "yes" if same else "NO",
           "PASS" if same and worst <= 1 else
           "FAIL (%.2f of it, %s)" % (worst, where)))
PYTHON
