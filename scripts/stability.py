"""The stability map of doc/stability.md: for each method, a range of its
parameter on the default scene's 8 Kelly cycles (410 to 29,626 dofs), with
the remedies off and on. A cell gives the linear solves of the cycle (with
the multiplier updates for the augmented Lagrangian), `R` where a remedy was
applied, or how the run failed there (exit status); later cycles do not run.
Called by scripts/work-precision."""
import os
import re

import common

SCENE = "prm/cantilever_on_plane.prm"

FAILURES = {2: "no convergence", 3: "cycling", 4: "linear solver",
            6: "stalled", 7: "slow multipliers"}

# method: (Contact settings, parameter entry, values, what is varied)
SWEEPS = {
    "active-set": ({"Method": "active set"}, "Complementarity constant",
                   ["1e-6", "1e-2", "0", "1e12", "1e15"],
                   "c [MPa/mm] (0: E / h_min, from 4e5 to 5e7)"),
    "penalty": ({"Method": "penalty"}, "Penalty parameter",
                ["1e-6", "1e-8", "1e-10", "1e-12", "1e-14"],
                "epsilon [mm/MPa]"),
    "augmented-lagrangian": ({"Method": "augmented lagrangian"},
                             "Penalty parameter",
                             ["0", "1e-8", "1e-7", "1e-6", "1e-4"],
                             "epsilon [mm/MPa] (0: h_min / (10 E))"),
}


def cells(run, cycles):
    """The text of each cycle's cell."""
    remedies = {}
    cycle = -1
    for line in run.stdout.splitlines():
        match = re.match(r"Cycle (\d+):", line)
        if match:
            cycle = int(match.group(1))
        elif line.strip().startswith("remedy:"):
            remedies[cycle] = True
    texts = []
    for c in range(cycles):
        if c < len(run.rows):
            row = run.rows[c]
            text = "%d" % row["iterations"]
            if "multiplier_updates" in row:
                text += " (%d)" % row["multiplier_updates"]
            texts.append(text + (" R" if remedies.get(c) else ""))
        elif c == len(run.rows) and run.status != 0:
            texts.append("**%s (%d)**" % (FAILURES.get(run.status, "failed"),
                                         run.status))
        else:
            texts.append("–")
    return texts


def main(work):
    os.makedirs(work, exist_ok=True)
    cycles = 8
    sections = {}
    sweeps = list(SWEEPS.items())
    for name, (contact, entry, values, varied) in \
            sweeps[:1] if common.SMOKE else sweeps:
        rows = []
        dofs = None
        for value in values[:1] if common.SMOKE else values:
            for remedies in ("false", "true"):
                settings = {"Contact": dict(contact, **{entry: value,
                                                        "Remedies": remedies})}
                run = common.run(work, "%s-%s-%s" % (name, value, remedies),
                                 SCENE, settings, check=False)
                if run.status == 0:
                    dofs = dofs or ["{:,}".format(int(r["dofs"]))
                                    for r in run.rows]
                rows.append([value, "on" if remedies == "true" else "off"] +
                            cells(run, cycles))
        header = [varied, "remedies"] + (dofs or [str(c) for c in
                                                  range(cycles)])
        sections[name] = common.table(header, rows)
    common.replace_sections(common.output_file("doc/stability.md"), sections)
