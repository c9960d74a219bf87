#!/usr/bin/env python3
"""signorini against a peer, GetFEM (Debian's python3-getfem, 5.4), on the
2D Hertz cylinder: Q1 and Q2 Kelly cycles (prm/hertz_cylinder.prm,
prm/hertz_cylinder_q2.prm) against GetFEM's P1 and P2 with its own adaptive
refinement and nodal Alart-Curnier contact (scripts/getfem_hertz.py, the
same scene and the same measures).

    scripts/peer-hertz [--repeat N]     (default 3)

For each accuracy target and configuration: the first cycle that reaches
it (from one run each), then whole processes that stop after that cycle,
timed in turn (signorini Q1, Q2, GetFEM P1, P2, again N times; medians):
the wall time from start to exit, as a user waits for it. The targets:
p0 within 1 % of Hertz's; a within 1 % of Hertz's; and p0 within 0.1 % of
the finite disk's converged value with a within 1 % (the issue's target).
The converged p0, 58.975 MPa (0.285 % under Hertz's half-space value), is
where Q2 settles to five digits at 406,534 and 770,622 dofs and GetFEM's P1
at 111,718 dofs (58.974); doc/second-order.md.

Prints the table and rewrites the section `peers` of doc/work-precision.md.
Runs go to build/peers/.
"""
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

WORK = common.work_folder("peers")
PYTHON = "/usr/bin/python3"  # Debian's, which has python3-getfem
GETFEM = os.path.join(common.ROOT, "scripts", "getfem_hertz.py")
HERTZ_P0, HERTZ_A = 59.14314, 0.1076405
CONVERGED_P0 = 58.975

# (label, kind, scene or degree, cycles of the accuracy run)
CONFIGURATIONS = [
    ("signorini Q1", "signorini", "prm/hertz_cylinder.prm", 9),
    ("signorini Q2", "signorini", "prm/hertz_cylinder_q2.prm", 9),
    ("GetFEM P1", "getfem", 1, 10),
    ("GetFEM P2", "getfem", 2, 8),
]

TARGETS = [
    ("p0 within 1 % of Hertz",
     lambda p0, a: abs(p0 / HERTZ_P0 - 1) < 0.01),
    ("a within 1 % of Hertz",
     lambda p0, a: abs(a / HERTZ_A - 1) < 0.01),
    ("p0 within 0.1 % of the converged value and a within 1 %",
     lambda p0, a: abs(p0 / CONVERGED_P0 - 1) < 0.001 and
     abs(a / HERTZ_A - 1) < 0.01),
]


def ensure_getfem():
    """Installs python3-getfem from Debian if Debian's python3 lacks it."""
    if subprocess.run([PYTHON, "-c", "import getfem, numpy"],
                      capture_output=True).returncode == 0:
        return
    print("scripts/peer-hertz: installing python3-getfem", file=sys.stderr)
    environment = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(["apt-get", "update", "-qq"], check=True, env=environment)
    subprocess.run(["apt-get", "install", "-y", "-qq",
                    "--no-install-recommends", "python3-getfem",
                    "python3-numpy"], check=True, env=environment,
                   stdout=subprocess.DEVNULL)


def run(configuration, cycles):
    """One whole process of `configuration` stopping after `cycles`
    cycles: (wall time [s], rows of dofs, p0, a per cycle)."""
    label, kind, what, _ = configuration
    name = label.replace(" ", "_")
    if kind == "signorini":
        result = common.run(WORK, name, what, {
            "Mesh refinement": {"Number of cycles": str(cycles)},
            "Output": {"Checkpoint": "false"}})
        rows = [(int(r["dofs"]), float(r["max_pressure"]),
                 float(r["contact_width"])) for r in result.rows]
        return result.wall, rows
    start = time.monotonic()
    process = subprocess.run(
        [PYTHON, GETFEM, "2d", "--degree", str(what), "--cycles",
         str(cycles)], capture_output=True, text=True, check=True)
    wall = time.monotonic() - start
    lines = process.stdout.strip().splitlines()
    header = lines[0].split(",")
    rows = []
    for line in lines[1:]:
        row = dict(zip(header, line.split(",")))
        rows.append((int(row["dofs"]), float(row["p0"]), float(row["a"])))
    return wall, rows


def main():
    repeat = 3
    if sys.argv[1:2] == ["--repeat"] and len(sys.argv) > 2:
        repeat = int(sys.argv[2])
    elif sys.argv[1:]:
        sys.exit(__doc__)
    ensure_getfem()
    os.makedirs(WORK, exist_ok=True)

    # The accuracy of every cycle, one run each.
    accuracy = {c[0]: run(c, c[3])[1] for c in CONFIGURATIONS}
    # Per target and configuration the cycles that reach it.
    reach = {}
    for target, holds in TARGETS:
        for configuration in CONFIGURATIONS:
            label = configuration[0]
            cycle = next((k for k, (_, p0, a) in enumerate(accuracy[label])
                          if holds(p0, a)), None)
            reach[(target, label)] = cycle
    # Whole processes to those cycles, in turn.
    wanted = sorted({(label, cycle + 1) for (_, label), cycle in
                     reach.items() if cycle is not None})
    walls = {key: [] for key in wanted}
    by_label = {c[0]: c for c in CONFIGURATIONS}
    for _ in range(repeat):
        for label, cycles in wanted:
            walls[(label, cycles)].append(run(by_label[label], cycles)[0])

    rows = []
    for target, _ in TARGETS:
        shown = target
        for configuration in CONFIGURATIONS:
            label = configuration[0]
            cycle = reach[(target, label)]
            if cycle is None:
                rows.append([shown, label, "not within %d cycles" %
                             configuration[3], "", "", ""])
                shown = ""
                continue
            dofs, p0, a = accuracy[label][cycle]
            rows.append([shown, label, "{:,}".format(dofs),
                         "%+.3f %%" % (100 * (p0 / HERTZ_P0 - 1)),
                         "%+.2f %%" % (100 * (a / HERTZ_A - 1)),
                         "%.2f" % statistics.median(
                             walls[(label, cycle + 1)])])
            shown = ""
    text = common.table(["to reach", "code", "dofs", "p0 vs Hertz",
                         "a vs Hertz", "wall time [s]"], rows)
    print(text)
    common.replace_sections(
        common.output_file("doc/work-precision.md"),
        {"peers": "Whole processes, medians of %d, run in turn:\n\n%s" %
         (repeat, text)})
    # The accuracy runs, for the record.
    for label, cycles in accuracy.items():
        print("\n" + label)
        for k, (dofs, p0, a) in enumerate(cycles):
            print("  %d  %8d  p0 %+.3f %%  a %+.2f %%" %
                  (k, dofs, 100 * (p0 / HERTZ_P0 - 1),
                   100 * (a / HERTZ_A - 1)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
