#!/usr/bin/env python3
"""How near its lower bound the contact solver runs. For the shipped scenes
(and the default scene with every method), per cycle: the wall time of the
contact solve over that of one linear elasticity solve on the same mesh with
the same linear solver, both measured in the same run (`Output/Timing table`),
and the peak memory. Medians over repeated runs; the machine is shared.

    scripts/benchmark [--repeat N]   (default 3 runs per scene)

Prints the tables and rewrites the README's section between
<!-- begin benchmark --> and <!-- end benchmark -->. Runs go to
build/benchmark/.
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

WORK = os.path.join(common.ROOT, "build", "benchmark")

# (name, scene, overrides): the default scene with each method, then the
# other shipped scenes as they are.
CASES = [
    ("cantilever_on_plane", "prm/cantilever_on_plane.prm", {}),
    ("cantilever_penalty", "prm/cantilever_on_plane.prm",
     {"Contact": {"Method": "penalty"}}),
    ("cantilever_augmented_lagrangian", "prm/cantilever_on_plane.prm",
     {"Contact": {"Method": "augmented lagrangian"}}),
    ("clamped_beam_on_plane", "prm/clamped_beam_on_plane.prm", {}),
    ("hertz_cylinder", "prm/hertz_cylinder.prm", {}),
]


def measure(name, scene, overrides, repeat):
    """Per cycle: dofs, iterations and the medians over `repeat` runs of the
    contact solve, the linear solve, their ratio and the peak memory."""
    settings = dict(overrides)
    settings["Output"] = {"Timing table": "true"}
    runs = [common.run(WORK, name, scene, settings).timings
            for _ in range(repeat)]
    rows = []
    for cycle in range(len(runs[0])):
        samples = [r[cycle] for r in runs]
        median = {key: statistics.median(s[key] for s in samples)
                  for key in ("contact_solve", "linear_solve", "ratio",
                              "peak_memory")}
        median.update(cycle=cycle, dofs=samples[0]["dofs"],
                      iterations=samples[0]["iterations"])
        rows.append(median)
    return rows


def main():
    repeat = 3
    if len(sys.argv) == 3 and sys.argv[1] == "--repeat":
        repeat = int(sys.argv[2])
    elif len(sys.argv) != 1:
        sys.exit(__doc__)
    common.ensure_tools(())
    os.makedirs(WORK, exist_ok=True)

    header = ["cycle", "dofs", "iterations", "contact solve [s]",
              "linear solve [s]", "ratio", "peak memory [MB]"]
    finals = []
    detail = ""
    for name, scene, overrides in CASES:
        rows = measure(name, scene, overrides, repeat)
        text = common.table(header, [
            ["%d" % r["cycle"], "{:,}".format(int(r["dofs"])),
             "%d" % r["iterations"], "%.3f" % r["contact_solve"],
             "%.3f" % r["linear_solve"], "%.2f" % r["ratio"],
             "%.0f" % r["peak_memory"]] for r in rows])
        print("\n%s (%s)\n\n%s" % (name, scene, text))
        if name == "cantilever_on_plane":
            detail = text
        last = rows[-1]
        method = overrides.get("Contact", {}).get("Method", "active set")
        finals.append(["`%s`" % os.path.basename(scene), method,
                       "{:,}".format(int(last["dofs"])),
                       "%d" % last["iterations"], "%.2f" % last["ratio"],
                       "%.0f" % last["peak_memory"]])
    summary = common.table(["scene", "method", "final dofs", "iterations",
                            "ratio", "peak memory [MB]"], finals)
    print("Final cycles\n\n" + summary)
    common.replace_sections(os.path.join(common.ROOT, "README.md"), {
        "benchmark": "The default scene, medians of %d runs:\n\n%s\n"
                     "The final cycle of each benchmark:\n\n%s" %
                     (repeat, detail, summary)})


if __name__ == "__main__":
    main()
