#!/usr/bin/env python3
"""Speed against accuracy: sweeps the contact methods (active set; penalty
at several epsilon; augmented Lagrangian) x refinement (global, Kelly) x
cycles on the Hertz and cantilever scenes, records the error (Hertz: peak
pressure p0; cantilever: energy norm against the overkill reference), the
penetration and the run time (wall time without output, from timings.csv),
and draws error against time, log-log, one curve per method and refinement.

    scripts/work-precision           the sweep and the stability map:
                                     doc/work-precision.md, .png and
                                     doc/stability.md (about N minutes)
    scripts/work-precision --quick   a small sweep (under two minutes) into
                                     build/work-precision-quick/, checked;
                                     what the ctest runs
    scripts/work-precision --friction
                                     the same with friction, on the
                                     Cattaneo-Mindlin scene (error of the
                                     stick zone's width):
                                     doc/friction-work-precision.png and its
                                     table in doc/friction.md (a minute)

Runs go to build/work-precision/ (or build/work-precision-quick/).

For the test suite only: with SIGNORINI_SMOKE=FOLDER (see scripts/common.py)
every run has at most two cycles, penalty runs with one epsilon (as in
--quick), the stability map tries the first value of the first method, and
the tables and charts are written to copies in FOLDER/doc/.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import stability  # noqa: E402

# The cantilever's potential energy from the overkill run (doc/validation.md).
REFERENCE_ENERGY = "-6.8812213"

# scene: (title, .prm, error column, extra settings, penalty epsilons
# [mm/MPa], cycles for kelly and global, cycles in quick mode)
SCENES = {
    "hertz": ("Hertz cylinder: peak pressure error", "prm/hertz_cylinder.prm",
              "max_pressure_error", {}, ["1e-4", "1e-5", "1e-6"],
              {"kelly": 9, "global": 5}, {"kelly": 4, "global": 3}),
    "cantilever": ("Cantilever on plane: energy-norm error",
                   "prm/cantilever_on_plane.prm", "energy_error",
                   {"Reference": {"Energy": REFERENCE_ENERGY}},
                   ["1e-5", "1e-6", "1e-7"],
                   {"kelly": 8, "global": 5}, {"kelly": 4, "global": 3}),
}


# With friction: the Cattaneo-Mindlin scene (two load steps a cycle; a point
# is a cycle's last step), the error of the stick zone's width.
FRICTION_SCENES = {
    "cattaneo_mindlin": ("Cattaneo-Mindlin: stick width error",
                         "prm/cattaneo_mindlin.prm", "stick_width_error", {},
                         ["1e-5", "1e-6", "1e-7"],
                         {"kelly": 8, "global": 4}, {"kelly": 4, "global": 3}),
}


# P1 on the Hertz scene: the active set on triangles from the geometry
# prm/hertz_cylinder.geo, Kelly cycles by Gmsh remeshing and global ones
# (halved sizes): (scene, label, .prm, cycles, cycles in quick mode).
# (prm/hertz_cylinder_p1.prm, as overrides of the Hertz scene: an included
# file's includes are found from the including file's folder.)
P1_RUNS = [("hertz", "P1 active set", "prm/hertz_cylinder.prm",
            {"kelly": 10, "global": 5}, {"kelly": 4, "global": 2})]
P1_GEOMETRY = {"Type": "gmsh",
               "Mesh file": os.path.join(common.ROOT, "prm",
                                         "hertz_cylinder.geo"),
               "Initial refinement": "0"}


def methods(epsilons, quick):
    """(label, Contact settings) of each method swept."""
    chosen = [("active set", {"Method": "active set"})]
    for epsilon in epsilons[1:2] if quick else epsilons:
        chosen.append(("penalty eps=" + epsilon,
                       {"Method": "penalty", "Penalty parameter": epsilon}))
    chosen.append(("augmented lagrangian",
                   {"Method": "augmented lagrangian"}))
    return chosen


def run_case(work, scene, label, prm, settings, refinement, cycles):
    """One run of the sweep; returns its rows, each the statistics and
    timings of one cycle."""
    settings = dict(settings)
    settings["Mesh refinement"] = {"Strategy": refinement,
                                   "Number of cycles": str(cycles)}
    settings["Output"] = {"Timing table": "true",
                          "Contact pressure table": "false"}
    name = "%s-%s-%s" % (scene, label.replace(" ", "_").replace("=", ""),
                         refinement)
    run = common.run(work, name, prm, settings)
    # With a load history, a cycle's last step (the timings are per cycle).
    steps = max(int(row.get("step", 1)) for row in run.rows)
    rows = [row for row in run.rows if int(row.get("step", 1)) == steps]
    return [dict(s, **{"run_time": t["run_time"]})
            for s, t in zip(rows, run.timings)]


def sweep(work, quick, scenes=None):
    """Runs every combination; returns {(scene, method, refinement): rows}
    with each row the statistics and timings of one cycle."""
    results = {}
    for scene, (_, prm, _, extra, epsilons, cycles, quick_cycles) in \
            (scenes or SCENES).items():
        for label, contact in methods(epsilons, quick or common.SMOKE):
            for refinement in ("kelly", "global"):
                settings = dict(extra)
                settings["Contact"] = contact
                results[(scene, label, refinement)] = run_case(
                    work, scene, label, prm, settings, refinement,
                    (quick_cycles if quick else cycles)[refinement])
        for p1_scene, label, p1_prm, cycles, quick_cycles in P1_RUNS:
            if p1_scene != scene:
                continue
            for refinement in ("kelly", "global"):
                results[(scene, label, refinement)] = run_case(
                    work, scene, label, p1_prm,
                    dict(extra, Geometry=P1_GEOMETRY), refinement,
                    (quick_cycles if quick else cycles)[refinement])
    return results


def first_below(rows, column, bound):
    """The first cycle whose error is below `bound`, or None."""
    for row in rows:
        if abs(row[column]) < bound:
            return row
    return None


def chart(work, results, path, scenes=None):
    """error against run time, log-log, a panel per scene."""
    scenes = scenes or SCENES
    colours = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e",
               "#e6ab02"]
    panels = []
    for scene, (title, _, column, *_rest) in scenes.items():
        labels = []
        for (s, label, _), _rows in results.items():
            if s == scene and label not in labels:
                labels.append(label)
        plots = []
        for i, label in enumerate(labels):
            for refinement, dash in (("kelly", 1), ("global", 2)):
                rows = results[(scene, label, refinement)]
                data = common.write_data(
                    work, "%s-%d-%s" % (scene, i, refinement), rows,
                    ["run_time", column])
                plots.append(
                    "'%s' using 1:(abs($2)) with linespoints dt %d lc rgb "
                    "'%s' pt %d title '%s, %s'" %
                    (data, dash, colours[i % len(colours)], 7 if dash == 1
                     else 6, label, refinement))
        panels.append(
            "set title '%s'\nset xlabel 'run time without output [s]'\n"
            "set ylabel 'relative error'\nplot %s\n" %
            (title, ", \\\n  ".join(plots)))
    common.gnuplot(
        "set terminal pngcairo size %d,560 font ',10'\n"
        "set output '%s'\nset logscale xy\nset grid\n"
        "set key bottom left font ',8'\nset multiplot layout 1,%d\n%s"
        "unset multiplot\n" % (700 * len(panels), path, len(panels),
                                "".join(panels)))


def final_table(results, scenes=None):
    """The last cycle of every run."""
    rows = []
    for (scene, label, refinement), cycles in results.items():
        last = cycles[-1]
        column = (scenes or SCENES)[scene][2]
        rows.append([scene, label, refinement, "%d" % (last["cycle"] + 1),
                     "{:,}".format(int(last["dofs"])),
                     "%d" % sum(r["iterations"] for r in cycles),
                     "%.2f" % last["run_time"], "%.2e" % abs(last[column]),
                     "%.1e" % last["max_penetration"]])
    return common.table(["scene", "method", "refinement", "cycles", "dofs",
                         "linear solves (all cycles)", "run time [s]",
                         "error", "max penetration [mm]"], rows)


def p1_table(results):
    """Hertz on P1, per cycle: Kelly remeshing against global (halved
    sizes), beside the Q1 active set's Kelly cycles."""
    rows = []
    for label, refinement in (("P1 active set", "kelly"),
                              ("P1 active set", "global"),
                              ("active set", "kelly")):
        for row in results.get(("hertz", label, refinement), []):
            rows.append(["Q1" if label == "active set" else "P1",
                         refinement, "%d" % row["cycle"],
                         "{:,}".format(int(row["dofs"])),
                         "%.2e" % abs(row["max_pressure_error"]),
                         "%.2e" % abs(row["contact_width_error"]),
                         "%d" % row["iterations"],
                         "%.2f" % row["run_time"]])
    return common.table(["elements", "refinement", "cycle", "dofs",
                         "p0 error", "a error", "iterations",
                         "run time [s]"], rows)


def check(results):
    """What the quick sweep must show; returns the failures."""
    failures = []
    for (scene, label, refinement), rows in results.items():
        column = SCENES[scene][2]
        for row in rows:
            if not all(math.isfinite(row[k]) for k in
                       (column, "run_time", "max_penetration")):
                failures.append("%s %s %s: not finite" %
                                (scene, label, refinement))
        exact = results[(scene, "active set", refinement)]
        if label.startswith("P1") and refinement == "kelly":
            # Kelly remeshing reaches 1 % with fewer dofs than halved sizes
            kelly = first_below(rows, column, 0.01)
            uniform = first_below(results[(scene, label, "global")],
                                  column, 0.01)
            if kelly is None or (uniform is not None and
                                 kelly["dofs"] >= uniform["dofs"]):
                failures.append("%s %s: kelly %s, global %s reach 1 %%" % (
                    scene, label, kelly and kelly["dofs"],
                    uniform and uniform["dofs"]))
        if label == "augmented lagrangian":
            # the same constrained solution as the active set
            for a, b in zip(rows, exact):
                if abs(a[column] - b[column]) > 1e-5 * abs(b[column]) + 1e-12:
                    failures.append("%s %s %s: error %g, active set %g" % (
                        scene, label, refinement, a[column], b[column]))
        if label.startswith("penalty"):
            # the penetration costs accuracy that refinement cannot recover
            if rows[-1]["max_penetration"] <= 0 or \
                    abs(rows[-1][column]) <= abs(exact[-1][column]):
                failures.append("%s %s %s: penetration %g, error %g" % (
                    scene, label, refinement, rows[-1]["max_penetration"],
                    rows[-1][column]))
        if rows[-1]["run_time"] <= 0:
            failures.append("%s %s: no run time" % (scene, label))
    return failures


def friction():
    """The sweep with friction: its chart, and its table in
    doc/friction.md."""
    work = common.work_folder("work-precision-friction")
    os.makedirs(work, exist_ok=True)
    common.ensure_tools()
    results = sweep(work, common.SMOKE, FRICTION_SCENES)
    text = final_table(results, FRICTION_SCENES)
    print(text)
    chart(work, results, common.output_file("doc/friction-work-precision.png"),
          FRICTION_SCENES)
    common.replace_sections(common.output_file("doc/friction.md"),
                            {"friction-cycles": text})


def main():
    quick = sys.argv[1:] == ["--quick"]
    if sys.argv[1:] == ["--friction"]:
        friction()
        return
    if sys.argv[1:] not in ([], ["--quick"]):
        sys.exit(__doc__)
    work = common.work_folder("work-precision-quick" if quick
                              else "work-precision")
    os.makedirs(work, exist_ok=True)
    if not quick:
        common.ensure_tools()
    results = sweep(work, quick)
    text = final_table(results)
    print(text)
    if quick:
        chart(work, results, os.path.join(work, "work-precision.png"))
        failures = check(results)
        for failure in failures:
            print("FAIL: " + failure)
        if failures or not os.path.getsize(
                os.path.join(work, "work-precision.png")):
            sys.exit(1)
        print("work-precision --quick: %d runs, all checks passed" %
              len(results))
        return
    chart(work, results, common.output_file("doc/work-precision.png"))
    p1 = p1_table(results)
    print(p1)
    common.replace_sections(common.output_file("doc/work-precision.md"),
                            {"final-cycles": text, "p1-cycles": p1})
    stability.main(common.work_folder("stability"))


if __name__ == "__main__":
    main()
