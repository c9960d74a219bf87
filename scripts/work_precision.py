#!/usr/bin/env python3
"""Speed against accuracy: sweeps the contact methods (active set; penalty
at several epsilon; augmented Lagrangian) x refinement (global, Kelly) x
cycles on the Hertz and cantilever scenes, records the error (Hertz: peak
pressure p0; cantilever: energy norm against the overkill reference), the
penetration and the run time (wall time without output, from timings.csv),
and draws error against time, log-log, one curve per method and refinement.

    scripts/work-precision           the sweep and the stability map:
                                     doc/work-precision.md, .png,
                                     doc/work-precision-3d.png and
                                     doc/stability.md (about 15 minutes,
                                     10 of them the comparison with
                                     GetFEM)
    scripts/work-precision --quick   a small sweep (under two minutes) into
                                     build/work-precision-quick/, checked;
                                     what the ctest runs
    scripts/work-precision --friction
                                     the same with friction, on the
                                     Cattaneo-Mindlin scene (error of the
                                     stick zone's width):
                                     doc/friction-work-precision.png and its
                                     table in doc/friction.md (a minute)
    scripts/work-precision --getfem  only the comparison with GetFEM on the
                                     2D and 3D Hertz scenes (part of the
                                     sweep): its tables in
                                     doc/work-precision.md and
                                     doc/work-precision-3d.png (about 10
                                     minutes; the lines of the 2D chart
                                     are redrawn by the whole sweep)

Runs go to build/work-precision/ (or build/work-precision-quick/, or
build/work-precision-getfem/). The comparison with GetFEM installs Debian's
python3-getfem if it is missing; --quick and the test suite's smoke mode
leave it out.

For the test suite only: with SIGNORINI_SMOKE=FOLDER (see scripts/common.py)
every run has at most two cycles, penalty runs with one epsilon (as in
--quick), the stability map tries the first value of the first method, and
the tables and charts are written to copies in FOLDER/doc/.
"""
import math
import os
import re
import statistics
import subprocess
import sys
import time

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


# The peer code GetFEM (scripts/getfem_hertz.py, on Debian's python3-getfem)
# against signorini on the Hertz scenes. Each run is a whole process, and a
# cycle's time is the wall time from the process's start to the line it
# prints at the cycle's end, both codes timed alike by this script (so
# start-up, library loading, imports, Gmsh and signorini's output files
# count; GetFEM writes none). scene: (title, .prm, getfem_hertz.py's scene).
PEER_SCENES = {
    "hertz": ("Hertz cylinder", "prm/hertz_cylinder.prm", "2d"),
    "hertz_sphere": ("Hertz ball (3D)", "prm/hertz_sphere.prm", "3d"),
}
# (scene, label, code, signorini's settings over the scene's .prm or
# getfem_hertz.py's options): another configuration is one more entry.
# Besides each scene's own settings, the 3D ball with Kelly's refine
# fraction at 0.1 instead of 0.3: the error of p0 and a is set by the cells
# at the contact zone, refined once a cycle either way, and the smaller
# fraction refines fewer cells away from it (measured: p0 and a within 1 %
# at 8,955 dofs in about 1 s, where 0.3 needs 83,730 dofs and 6 s).
Q2 = {"Element degree": "2", "Initial refinement": "1"}


def p2(geo):
    """P2 from the .geo @p geo in prm/, remeshed by Gmsh each cycle."""
    return {"Type": "gmsh", "Mesh file": os.path.join(common.ROOT, "prm", geo),
            "Initial refinement": "0", "Element degree": "2"}


PEER_RUNS = [
    ("hertz", "signorini Q1", "signorini",
     {"Mesh refinement": {"Number of cycles": "9"}}),
    ("hertz", "signorini Q2", "signorini",
     {"Geometry": Q2, "Mesh refinement": {"Number of cycles": "9"}}),
    # prm/hertz_cylinder_p2.prm, two cycles on.
    ("hertz", "signorini P2", "signorini",
     {"Geometry": p2("hertz_cylinder.geo"),
      "Mesh refinement": {"Number of cycles": "8"}}),
    ("hertz", "GetFEM P1", "getfem", ["--degree", "1", "--cycles", "9"]),
    ("hertz", "GetFEM P2", "getfem", ["--degree", "2", "--cycles", "8"]),
    ("hertz_sphere", "signorini Q1", "signorini",
     {"Mesh refinement": {"Number of cycles": "6"}}),
    ("hertz_sphere", "signorini Q1, Refine fraction 0.1", "signorini",
     {"Mesh refinement": {"Number of cycles": "8", "Refine fraction": "0.1"}}),
    # prm/hertz_sphere_q2.prm as shipped (Refine fraction 0.1, 8 cycles).
    ("hertz_sphere", "signorini Q2", "signorini",
     {"Geometry": Q2, "Mesh refinement": {"Number of cycles": "8",
                                          "Refine fraction": "0.1"}}),
    # prm/hertz_sphere_p2.prm, one cycle on.
    ("hertz_sphere", "signorini P2", "signorini",
     {"Geometry": p2("quarter_ball.geo"),
      "Mesh refinement": {"Number of cycles": "9"}}),
    ("hertz_sphere", "GetFEM P1", "getfem",
     ["--degree", "1", "--cycles", "4"]),
    ("hertz_sphere", "GetFEM P2", "getfem",
     ["--degree", "2", "--cycles", "3"]),
]
# Every run this often, in turn (all entries, then all again), a cycle's
# time the median of its runs.
PEER_REPEATS = 3
# The Python with Debian's python3-getfem (not another python3 on the
# PATH).
GETFEM_PYTHON = "/usr/bin/python3"
# The targets of the table of what it takes: (label, error columns, bound
# on each).
PEER_TARGETS = [("p0 within 1 %", ("p0_error",), 0.01),
                ("p0 within 0.3 %", ("p0_error",), 0.003),
                ("a within 1 %", ("a_error",), 0.01),
                ("p0 and a within 0.5 %", ("p0_error", "a_error"), 0.005)]
PEER_COLOURS = ["#000000", "#6a3d9a", "#1f78b4", "#e31a1c", "#33a02c",
                "#ff7f00"]


def hertz(scene):
    """Hertz's p0 and a of the scene (its .prm's Reference)."""
    young, poisson, radius = 1000., 0.3, 1.
    e_star = young / (1 - poisson ** 2)
    if scene == "hertz":
        force = 10.
        a = 2 * math.sqrt(force * radius / (math.pi * e_star))
        return 2 * force / (math.pi * a), a
    force = 1.5
    a = (3 * force * radius / (4 * e_star)) ** (1 / 3)
    return 3 * force / (2 * math.pi * a ** 2), a


def ensure_getfem():
    """Installs Debian's python3-getfem if GETFEM_PYTHON cannot import it
    (as common.ensure_tools installs gnuplot)."""
    if subprocess.run([GETFEM_PYTHON, "-c", "import getfem, scipy"],
                      stdout=subprocess.DEVNULL,
                      stderr=subprocess.DEVNULL).returncode == 0:
        return
    print("%s: installing python3-getfem" % sys.argv[0], file=sys.stderr)
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(["apt-get", "update", "-qq"], check=True, env=env)
    subprocess.run(["apt-get", "install", "-y", "-qq",
                    "--no-install-recommends", "python3-getfem"], check=True,
                   env=env, stdout=subprocess.DEVNULL)


def stamped(command, folder):
    """Runs `command` in `folder`; returns its stdout lines, each with the
    wall time [s] from the start at which it arrived, and the process's
    peak memory [MB], processor time [s] and wall time to its exit [s]. Its
    stderr goes to folder/stderr.txt."""
    lines = []
    with open(os.path.join(folder, "stderr.txt"), "w") as errors:
        start = time.monotonic()
        process = subprocess.Popen(command, cwd=folder,
                                   stdout=subprocess.PIPE, stderr=errors,
                                   text=True, bufsize=1)
        for line in process.stdout:
            lines.append((time.monotonic() - start, line.rstrip("\n")))
        _, status, usage = os.wait4(process.pid, 0)
        wall = time.monotonic() - start
    if status != 0:
        sys.exit("%s: %s failed (see %s)" % (
            sys.argv[0], " ".join(command),
            os.path.join(folder, "stderr.txt")))
    return lines, (usage.ru_maxrss / 1024, usage.ru_utime + usage.ru_stime,
                   wall)


def peer_signorini(work, name, scene, settings):
    """One whole run of signorini: a row per cycle, the time at its end
    that of the last line it printed for the cycle (its summary, before it
    writes the cycle's files), and stamped()'s figures of the whole run."""
    folder = os.path.join(work, name)
    os.makedirs(folder, exist_ok=True)
    statistics_csv = os.path.join(folder, "statistics.csv")
    if os.path.exists(statistics_csv):
        os.remove(statistics_csv)
    settings = dict(settings)
    settings["Output"] = {"Directory": folder, "Verbose": "false",
                          "Print timings": "false", "Checkpoint": "false",
                          "Contact pressure table": "false"}
    lines = ["include " + os.path.join(common.ROOT, PEER_SCENES[scene][1])]
    for section, entries in settings.items():
        lines.append("subsection " + section)
        lines += ["  set %s = %s" % item for item in entries.items()]
        lines.append("end")
    prm = os.path.join(work, name + "-run.prm")
    common.write_file(prm, "\n".join(lines) + "\n")
    output, whole = stamped([common.SIGNORINI, prm], folder)
    ends = []
    for stamp, line in output:
        if line.startswith("Cycle "):
            ends.append(stamp)
        elif ends:
            ends[-1] = stamp
    p0, a = hertz(scene)
    rows = []
    for row, end in zip(common.read_table(statistics_csv), ends):
        rows.append({"cycle": row["cycle"], "dofs": row["dofs"],
                     "iterations": row["iterations"],
                     "max_penetration": row["max_penetration"],
                     "p0_error": row["max_pressure"] / p0 - 1,
                     "a_error": row["contact_width"] / a - 1,
                     "run_time": end, "own_time": float("nan")})
    return rows, whole


def peer_getfem(work, name, scene, options):
    """One whole run of scripts/getfem_hertz.py: a row per cycle, the time
    at its end that at which its row arrived (own_time: the script's own
    clock, from its first line), and stamped()'s figures of the whole
    run."""
    folder = os.path.join(work, name)
    os.makedirs(folder, exist_ok=True)
    command = [GETFEM_PYTHON,
               os.path.join(common.ROOT, "scripts", "getfem_hertz.py"),
               PEER_SCENES[scene][2]] + options
    output, whole = stamped(command, folder)
    header = output[0][1].split(",")
    rows = []
    for stamp, line in output[1:]:
        row = dict(zip(header, map(float, line.split(","))))
        row["own_time"], row["run_time"] = row["time"], stamp
        rows.append(row)
    common.write_file(os.path.join(folder, "cycles.csv"),
                      "\n".join(line for _, line in output) + "\n")
    return rows, whole


def peer_sweep(work):
    """Every entry of PEER_RUNS PEER_REPEATS times in turn; returns
    {(scene, label): (rows, (peak memory [MB], processor time [s], wall
    time to the exit [s]))}, a row per cycle with the median time of the
    repeats, and the medians of the whole runs' figures."""
    runs = {}
    for repeat in range(PEER_REPEATS):
        for scene, label, code, settings in PEER_RUNS:
            name = "%s-%s-%d" % (scene, re.sub(r"[^A-Za-z0-9.]+", "_",
                                                label), repeat)
            print("  " + name, file=sys.stderr)
            run = (peer_signorini if code == "signorini" else peer_getfem)(
                work, name, scene, settings)
            runs.setdefault((scene, label), []).append(run)
    results = {}
    for key, repeats in runs.items():
        rows = [dict(row) for row in repeats[0][0]]
        for i, row in enumerate(rows):
            if any(len(r[0]) != len(rows) or r[0][i]["dofs"] != row["dofs"]
                   for r in repeats):
                sys.exit("%s: %s %s: the repeats differ" % ((sys.argv[0],)
                                                            + key))
            for column in ("run_time", "own_time"):
                row[column] = statistics.median(r[0][i][column]
                                                for r in repeats)
        results[key] = (rows, tuple(statistics.median(r[1][i]
                                                      for r in repeats)
                                    for i in range(3)))
    return results


def peer_labels():
    """The labels of PEER_RUNS, signorini's first, each once."""
    labels = []
    for first in (True, False):
        for _, label, code, _ in PEER_RUNS:
            if (code == "signorini") == first and label not in labels:
                labels.append(label)
    return labels


def peer_plots(work, peers, scene, column, whole=False):
    """The gnuplot plot clauses of the peer runs on `scene` (the error in
    `column` against the whole process's time): a colour per label on
    every chart, GetFEM's lines dashed."""
    plots = []
    codes = {label: code for _, label, code, _ in PEER_RUNS}
    for i, label in enumerate(peer_labels()):
        if (scene, label) not in peers:
            continue
        data = common.write_data(work, "peer-%s-%d-%s" % (scene, i, column),
                                 peers[(scene, label)][0],
                                 ["run_time", column])
        plots.append("'%s' using 1:(abs($2)) with linespoints lw 2 dt %d "
                     "lc rgb '%s' pt 5 title '%s%s'" %
                     (data, 1 if codes[label] == "signorini" else 2,
                      PEER_COLOURS[i % len(PEER_COLOURS)], label,
                      ", whole process" if whole else ""))
    return plots


def peer_chart(work, peers, path):
    """The 3D Hertz ball: the error of p0 and of a against the run time,
    log-log, a line per configuration."""
    panels = []
    for column, title in (("p0_error", "peak pressure error"),
                          ("a_error", "contact radius error")):
        panels.append(
            "set title '%s: %s'\nset xlabel 'wall time of the whole process "
            "[s]'\nset ylabel 'relative error'\nplot %s\n" %
            (PEER_SCENES["hertz_sphere"][0], title, ", \\\n  ".join(
                peer_plots(work, peers, "hertz_sphere", column))))
    common.gnuplot(
        "set terminal pngcairo size 1400,560 font ',10'\n"
        "set output '%s'\nset logscale xy\nset grid\nset format y '%%g'\n"
        "set key top right font ',8'\nset multiplot layout 1,2\n%s"
        "unset multiplot\n" % (path, "".join(panels)))


def peer_final_rows(peers):
    """The last cycle of each peer run, as rows of the final-cycles
    table."""
    rows = []
    for (scene, label), (cycles, _) in peers.items():
        last = cycles[-1]
        rows.append([scene, label, "kelly" if label.startswith("signorini")
                     else "stress jump", "%d" % (last["cycle"] + 1),
                     "{:,}".format(int(last["dofs"])),
                     "%d" % sum(r["iterations"] for r in cycles),
                     "%.2f (whole process)" % last["run_time"],
                     "%.2e" % abs(last["p0_error"]),
                     "%.1e" % last["max_penetration"]])
    return rows


def peer_cycles_table(peers):
    """Every cycle of every peer run."""
    rows = []
    for (scene, label), (cycles, (memory, processor, wall)) in \
            peers.items():
        for row in cycles:
            own = row["own_time"]
            rows.append([scene, label, "%d" % row["cycle"],
                         "{:,}".format(int(row["dofs"])),
                         "%d" % row["iterations"],
                         "%.2f" % row["run_time"],
                         "" if math.isnan(own) else "%.2f" % own,
                         "%+.3f" % (100 * row["p0_error"]),
                         "%+.3f" % (100 * row["a_error"])])
        rows.append([scene, label, "whole run", "", "",
                     "%.2f to the exit" % wall, "",
                     "peak memory %.0f MB" % memory,
                     "processor time %.1f s" % processor])
    return common.table(["scene", "code", "cycle", "dofs",
                         "iterations", "run time [s]",
                         "GetFEM's own clock [s]", "p0 error [%]",
                         "a error [%]"], rows)


def worst(row, columns):
    """The largest of a row's errors in `columns`, with its sign."""
    return max((row[c] for c in columns), key=abs)


def settled(rows, columns, bound):
    """The first cycle from which the errors in `columns` stay within
    `bound` on every later cycle of the run, or None."""
    found = None
    for row in rows:
        if abs(worst(row, columns)) < bound:
            found = found or row
        else:
            found = None
    return found


def peer_reach_table(peers):
    """What each configuration takes to reach each target for good (the
    first cycle from which every later cycle of the run stays within it):
    dofs and time."""
    labels = peer_labels()
    rows = []
    for scene, (title, _, _) in PEER_SCENES.items():
        for target, columns, bound in PEER_TARGETS:
            row = ["%s: %s" % (title, target)]
            for label in labels:
                if (scene, label) not in peers:
                    row.append("")
                    continue
                cycles = peers[(scene, label)][0]
                reached = settled(cycles, columns, bound)
                if reached:
                    # Reached on the run's last cycle only: nothing shows
                    # that it stays.
                    row.append("{:,} dofs, {:.2f} s{}".format(
                        int(reached["dofs"]), reached["run_time"],
                        " (last cycle)" if reached is cycles[-1] else ""))
                else:
                    best = min(cycles,
                               key=lambda r: abs(worst(r, columns)))
                    row.append("not reached (best %+.2f %% at %s dofs)" % (
                        100 * worst(best, columns),
                        "{:,}".format(int(best["dofs"]))))
            rows.append(row)
    return common.table(["to reach"] + labels, rows)


def require_sections(path, names):
    """Exits before any run if `path` lacks a section of `names` (its
    <!-- begin NAME --> and <!-- end NAME --> lines):
    common.replace_sections would exit only after all the runs."""
    with open(path) as f:
        text = f.read()
    missing = [name for name in names
               if "<!-- begin %s -->\n" % name not in text or
               "<!-- end %s -->" % name not in text]
    if missing:
        sys.exit("%s: %s has no section %s" % (
            sys.argv[0], path, ", ".join("'%s'" % m for m in missing)))


PEER_SECTIONS = ["getfem-reach", "getfem-cycles"]


def peer_tables(peers):
    """The sections of doc/work-precision.md from the peer runs."""
    return dict(zip(PEER_SECTIONS, (peer_reach_table(peers),
                                     peer_cycles_table(peers))))


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


def chart(work, results, path, scenes=None, peers=None):
    """error against run time, log-log, a panel per scene (with the peer
    runs on it, if given)."""
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
        xlabel = "run time without output [s]"
        if peers and any(s == scene for s, _ in peers):
            plots += peer_plots(work, peers, scene, "p0_error", True)
            xlabel = ("run time without output, or of the whole process "
                      "[s]")
        panels.append(
            "set title '%s'\nset xlabel '%s'\n"
            "set ylabel 'relative error'\nplot %s\n" %
            (title, xlabel, ", \\\n  ".join(plots)))
    common.gnuplot(
        "set terminal pngcairo size %d,560 font ',10'\n"
        "set output '%s'\nset logscale xy\nset grid\nset format y '%%g'\n"
        "set key bottom left font ',8'\nset multiplot layout 1,%d\n%s"
        "unset multiplot\n" % (700 * len(panels), path, len(panels),
                                "".join(panels)))


def final_table(results, scenes=None, extra=()):
    """The last cycle of every run (and the rows `extra`)."""
    rows = []
    for (scene, label, refinement), cycles in results.items():
        last = cycles[-1]
        column = (scenes or SCENES)[scene][2]
        rows.append([scene, label, refinement, "%d" % (last["cycle"] + 1),
                     "{:,}".format(int(last["dofs"])),
                     "%d" % sum(r["iterations"] for r in cycles),
                     "%.2f" % last["run_time"], "%.2e" % abs(last[column]),
                     "%.1e" % last["max_penetration"]])
    rows += extra
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


def getfem():
    """Only the comparison with GetFEM: its tables and the 3D chart."""
    require_sections(common.output_file("doc/work-precision.md"),
                     PEER_SECTIONS)
    work = common.work_folder("work-precision-getfem")
    os.makedirs(work, exist_ok=True)
    common.ensure_tools()
    ensure_getfem()
    peers = peer_sweep(work)
    sections = peer_tables(peers)
    print(sections["getfem-reach"])
    print(sections["getfem-cycles"])
    peer_chart(work, peers, common.output_file("doc/work-precision-3d.png"))
    common.replace_sections(common.output_file("doc/work-precision.md"),
                            sections)


def main():
    quick = sys.argv[1:] == ["--quick"]
    if sys.argv[1:] == ["--friction"]:
        friction()
        return
    if sys.argv[1:] == ["--getfem"] and not common.SMOKE:
        getfem()
        return
    if sys.argv[1:] not in ([], ["--quick"]):
        sys.exit(__doc__)
    work = common.work_folder("work-precision-quick" if quick
                              else "work-precision")
    os.makedirs(work, exist_ok=True)
    if not quick:
        require_sections(
            common.output_file("doc/work-precision.md"),
            ["final-cycles", "p1-cycles"] +
            (PEER_SECTIONS if not common.SMOKE else []))
        common.ensure_tools()
    # The comparison with GetFEM: not in the quick sweep, nor in the test
    # suite's smoke mode.
    peers = None
    if not quick and not common.SMOKE:
        ensure_getfem()
        peers = peer_sweep(os.path.join(work, "getfem"))
    results = sweep(work, quick)
    text = final_table(results, extra=peer_final_rows(peers or {}))
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
    chart(work, results, common.output_file("doc/work-precision.png"),
          peers=peers)
    p1 = p1_table(results)
    print(p1)
    sections = {"final-cycles": text, "p1-cycles": p1}
    if peers:
        sections.update(peer_tables(peers))
        print(sections["getfem-reach"])
        print(sections["getfem-cycles"])
        peer_chart(work, peers,
                   common.output_file("doc/work-precision-3d.png"))
    common.replace_sections(common.output_file("doc/work-precision.md"),
                            sections)
    stability.main(common.work_folder("stability"))


if __name__ == "__main__":
    main()
