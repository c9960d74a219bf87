# Frame invariance: a scene and the same scene turned give the same
# physics. The Hertz cylinder on triangles (frame_hertz_floor.prm) and
# turned by -90 degrees against a side wall (frame_hertz_wall.prm); the box
# in a rigid corner (frame_box.prm, two obstacles, the nodes of the bottom
# edge touching both) and turned by 30 degrees about the x axis
# (frame_box_turned.prm). Per cycle: dofs and iterations equal, the contact
# force's magnitude (each obstacle's for the box), the peak pressure, the
# contact width and area and the probe's displacement magnitude equal to
# 1e-8 relative.
for scene in frame_hertz_floor frame_hertz_wall frame_box frame_box_turned; do
  "$SIGNORINI" "$TESTS/$scene.prm" > $scene.log 2>&1
  echo "$scene: exit status $?"
done
/usr/bin/python3 - <<'PYTHON'
import csv, math

def rows(directory):
    with open(directory + "/statistics.csv") as f:
        return list(csv.DictReader(f))

def magnitude(row, prefix, axes):
    return math.sqrt(sum(float(row[prefix + a]) ** 2 for a in axes))

def compare(name, a, b, quantities):
    worst = 0.
    for ra, rb in zip(a, b):
        same = ra["dofs"] == rb["dofs"] and ra["iterations"] == rb["iterations"]
        line = "%s cycle %s: dofs %s/%s, iterations %s/%s" % (
            name, ra["cycle"], ra["dofs"], rb["dofs"], ra["iterations"],
            rb["iterations"])
        for label, value in quantities:
            x, y = value(ra), value(rb)
            difference = abs(x - y) / max(abs(x), abs(y), 1e-300)
            worst = max(worst, difference)
            line += ", %s %.6e" % (label, x)
        print(line + (" (same counts)" if same else " (COUNTS DIFFER)"))
        worst = worst if same else 1.
    print("%s: %d cycles each, largest relative difference %.1e: %s"
          % (name, len(a), worst,
             "PASS" if len(a) == len(b) and worst < 1e-8 else "FAIL"))

floor, wall = rows("floor"), rows("wall")
compare("hertz", floor, wall,
        [("|F|", lambda r: magnitude(r, "contact_force_", "xy")),
         ("p0", lambda r: float(r["max_pressure"])),
         ("width", lambda r: float(r["contact_width"])),
         ("area", lambda r: float(r["contact_area"])),
         ("p0 error", lambda r: float(r["max_pressure_error"]))])
box, turned = rows("box"), rows("turned")
compare("box", box, turned,
        [("|F1|", lambda r: magnitude(r, "contact_force1_", "xyz")),
         ("|F2|", lambda r: magnitude(r, "contact_force2_", "xyz")),
         ("p max", lambda r: float(r["max_pressure"])),
         ("area", lambda r: float(r["contact_area"])),
         ("|u probe|", lambda r: magnitude(r, "probe0_u", "xyz"))])
PYTHON
