#!/usr/bin/env python3
"""How near its lower bound the contact solver runs. For the shipped scenes
(and the default scene with every method), per cycle: the wall time of the
contact solve over that of one linear elasticity solve on the same mesh with
the same linear solver, both measured in the same run (`Output/Timing table`),
and the peak memory. Medians over repeated runs; the machine is shared.

    scripts/benchmark [--repeat N] [--2d | --3d]   (default 3 runs per scene)

The 3D part runs the 3D scenes on one and two processes (`mpirun`), the
indentation scene at more than a million dofs as a whole run, deal.II's
step-42 (built from the documentation package, made elastic) against it on
two processes, every shipped scene for its output share, and the 2D Hertz
scene at more than 200k dofs on one and two processes.

Prints the tables and rewrites the README's sections between
<!-- begin benchmark --> and <!-- end benchmark --> (and benchmark-3d).
Runs go to build/benchmark/.

For the test suite only: with SIGNORINI_SMOKE=FOLDER (see scripts/common.py)
every run has at most two cycles, the default is one repeat, each table
but the 2D Hertz line measures its first case only, step-42 is neither built
nor run, and the README rewritten is FOLDER/README.md, a copy.
"""
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

WORK = common.work_folder("benchmark")

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


# 3D and parallel runs: the final cycle's ratio on one and two processes.
CASES_3D = [
    ("hertz_sphere", "prm/hertz_sphere.prm",
     {"Mesh refinement": {"Number of cycles": "6"}}),
    ("sphere_indentation", "prm/sphere_indentation.prm", {}),
    ("sphere_indentation_matrix_free", "prm/sphere_indentation.prm",
     {"Linear solver": {"Type": "matrix-free"}}),
]


def elastic_operator(overrides):
    """The elastic operator a case runs: matrix-free or assembled."""
    chosen = overrides.get("Linear solver", {}).get("Type", "")
    return "matrix-free" if chosen == "matrix-free" else "assembled"
# The indentation scene refined to at least a million dofs.
LARGE = {"Mesh refinement": {"Number of cycles": "7"}}
# The 2D Hertz scene at more than 200k dofs.
HERTZ_2D = {"Mesh refinement": {"Number of cycles": "12"}}
STEP42 = "/usr/share/doc/libdeal.ii-doc/examples/step-42"


def measure(name, scene, overrides, repeat, processes=0):
    """Per cycle: dofs, iterations and the medians over `repeat` runs of the
    contact solve, the linear solve, their ratio and the peak memory."""
    settings = dict(overrides)
    settings["Output"] = {"Timing table": "true"}
    runs = [common.run(WORK, name, scene, settings,
                       processes=processes).timings
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


def whole_runs(name, scene, overrides, repeat, processes,
               long_run=float("inf")):
    """Medians over `repeat` runs (one if it takes `long_run` seconds) of the whole run as a user runs it (output
    included, no timing table): wall time of the process [s], the share of
    the run spent writing output, peak memory [MB] and per dof [kB], and
    the final dofs."""
    settings = dict(overrides)
    settings["Output"] = {"Print timings": "true"}
    runs = [common.run(WORK, name, scene, settings, processes=processes)]
    while len(runs) < repeat and runs[0].wall < long_run:
        runs.append(common.run(WORK, name, scene, settings,
                               processes=processes))
    dofs = runs[0].rows[-1]["dofs"]
    median = statistics.median
    return {
        "wall": median(r.wall for r in runs),
        "output": median(r.timer["Output"] / r.timer["Total"] for r in runs),
        "checkpoint": median(r.timer.get("Output: checkpoint", 0.) /
                             r.timer["Total"] for r in runs),
        "memory": median(r.peak_memory for r in runs),
        "per_dof": median(r.peak_memory * 1024. / dofs for r in runs),
        "dofs": dofs,
        "force": runs[0].rows[-1].get("contact_force_z", float("nan")),
    }


def build_step42():
    """deal.II's step-42 from the documentation package, its yield stress
    raised so that it stays elastic, 6 cycles of its p1_adaptive.prm;
    returns its folder."""
    if not os.path.isdir(STEP42):
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        subprocess.run(["apt-get", "update", "-qq"], check=True, env=env)
        subprocess.run(["apt-get", "install", "-y", "-qq",
                        "--no-install-recommends", "libdeal.ii-doc"],
                       check=True, stdout=subprocess.DEVNULL, env=env)
    folder = os.path.join(WORK, "step-42")
    os.makedirs(folder, exist_ok=True)
    for name in ("CMakeLists.txt", "step-42.cc", "p1_adaptive.prm"):
        shutil.copy(os.path.join(STEP42, name), folder)
    source = os.path.join(folder, "step-42.cc")
    with open(source) as f:
        text = f.read()
    if "sigma_0(400.0)" not in text:
        sys.exit("%s: step-42.cc has no sigma_0(400.0) to raise" % sys.argv[0])
    with open(source, "w") as f:
        f.write(text.replace("sigma_0(400.0)", "sigma_0(1e10)"))
    prm = os.path.join(folder, "p1_adaptive.prm")
    with open(prm) as f:
        text = re.sub(r"number of cycles\s*=\s*\d+", "number of cycles = 6",
                      f.read())
    with open(prm, "w") as f:
        f.write(text)
    quiet = dict(stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                 cwd=folder, check=True)
    subprocess.run(["cmake", "-DCMAKE_BUILD_TYPE=Release", "."], **quiet)
    subprocess.run(["make", "-j2"], **quiet)
    return folder


def run_step42(folder, repeat):
    """Median wall time of step-42 on two processes, and its last contact
    force."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_btl_vader_single_copy_mechanism="none")
    walls, force = [], float("nan")
    for _ in range(repeat):
        print("  step-42", file=sys.stderr)
        start = time.monotonic()
        process = subprocess.run(
            ["mpirun", "-np", "2", "./step-42", "p1_adaptive.prm"],
            cwd=folder, env=env, stdout=subprocess.PIPE, text=True,
            check=True)
        walls.append(time.monotonic() - start)
        forces = re.findall(r"Contact force = (\S+)", process.stdout)
        force = float(forces[-1])
    return statistics.median(walls), force


def three_d(repeat):
    """The 3D and parallel figures; returns the README section."""
    rows = []
    cases = CASES_3D[:1] if common.SMOKE else CASES_3D
    for name, scene, overrides in cases:
        for processes in (1, 2):
            last = measure("%s_np%d" % (name, processes), scene, overrides,
                           repeat, processes)[-1]
            rows.append(["`%s`" % os.path.basename(scene),
                         elastic_operator(overrides), "%d" % processes,
                         "{:,}".format(int(last["dofs"])),
                         "%d" % last["iterations"],
                         "%.2f" % last["ratio"],
                         "%.0f" % last["peak_memory"]])
    ratios = common.table(["scene", "elastic operator", "processes",
                           "final dofs", "iterations", "ratio",
                           "peak memory [MB]"], rows)
    print("\n3D, final cycles\n\n" + ratios)

    large = {n: whole_runs("indentation_large_np%d" % n,
                           "prm/sphere_indentation.prm", LARGE, repeat, n)
             for n in (1, 2)}
    large_rows = [["%d" % n, "{:,}".format(int(r["dofs"])),
                   "%.1f" % r["wall"], "%.1f %%" % (100 * r["output"]),
                   "%.1f %%" % (100 * r["checkpoint"]),
                   "%.0f" % r["memory"], "%.2f" % r["per_dof"]]
                  for n, r in large.items()]
    speedup = large[1]["wall"] / large[2]["wall"]
    large_text = common.table(["processes", "final dofs", "wall time [s]",
                               "output", "checkpoint", "peak memory [MB]",
                               "memory per dof [kB]"], large_rows)
    print("\nIndentation at %s dofs\n\n%s\nspeed-up 1 -> 2 processes: "
          "%.2f" % ("{:,}".format(int(large[2]["dofs"])), large_text,
                    speedup))

    if common.SMOKE:
        print("step-42: not built in smoke mode", file=sys.stderr)
        step42 = (float("nan"), float("nan"))
    else:
        step42 = run_step42(build_step42(), repeat)
    ours = whole_runs("indentation_step42_np2", "prm/sphere_indentation.prm",
                      {}, repeat, 2)
    versus = step42[0] / ours["wall"]
    print("step-42 (elastic), 2 processes: %.1f s, contact force %.3f; "
          "signorini: %.1f s, contact force %.3f; %.1f times faster" %
          (step42[0], step42[1], ours["wall"], ours["force"], versus))

    shares = []
    scenes = sorted(s for s in os.listdir(os.path.join(common.ROOT, "prm"))
                    if s.endswith(".prm"))
    for scene in scenes[:1] if common.SMOKE else scenes:
        if scene.endswith(".prm"):
            r = whole_runs("output_" + scene[:-4], "prm/" + scene, {},
                           repeat, 0, long_run=100.)
            shares.append(["`%s`" % scene, "{:,}".format(int(r["dofs"])),
                           "%.2f" % r["wall"], "%.1f %%" % (100 * r["output"]),
                           "%.1f %%" % (100 * r["checkpoint"])])
    shares_text = common.table(["scene", "final dofs", "wall time [s]",
                                "output", "checkpoint"], shares)
    print("\nOutput share, one process\n\n" + shares_text)

    hertz = {n: whole_runs("hertz_2d_np%d" % n, "prm/hertz_cylinder.prm",
                           HERTZ_2D, repeat, n) for n in (1, 2)}
    hertz_speedup = hertz[1]["wall"] / hertz[2]["wall"]
    amg = dict(HERTZ_2D, **{"Linear solver": {"Type": "amg cg"}})
    hertz_amg = whole_runs("hertz_2d_amg_np1", "prm/hertz_cylinder.prm", amg,
                           repeat, 1)
    print("2D Hertz at %s dofs: %.1f s on one process (direct), %.1f s on "
          "two (amg cg): speed-up %.2f; amg cg on one: %.1f s" %
          ("{:,}".format(int(hertz[1]["dofs"])), hertz[1]["wall"],
           hertz[2]["wall"], hertz_speedup, hertz_amg["wall"]))

    return ("3D scenes (`hertz_sphere.prm` with 6 cycles), final cycle, "
            "%s (`mpirun -np 1` and `-np 2`; the ratio is the contact solve "
            "over one linear solve with the same elastic operator):\n\n%s\n"
            "`sphere_indentation.prm` refined to %s dofs (7 cycles), the "
            "whole run as a user runs it, output included:\n\n%s\n"
            "Speed-up from 1 to 2 processes: **%.2f**. step-42 itself "
            "(elastic, 6 cycles to 493,287 dofs, 2 processes): %.1f s, "
            "contact force %.3f N; signorini on the same meshes: %.1f s, "
            "%.3f N: **%.1f times faster**.\n\n"
            "Output share of the run time, each shipped scene as shipped, "
            "one process (the checkpoint, written after every cycle, is its "
            "own column):\n\n%s\n"
            "2D Hertz at %s dofs (12 cycles), `automatic` linear solver: "
            "%.1f s on one process (direct), %.1f s on two (amg cg): "
            "speed-up **%.2f**; amg cg on one process: %.1f s, so %.2f "
            "with the same solver.\n" %
            ("one run" if repeat == 1 else "medians of %d runs" % repeat,
             ratios, "{:,}".format(int(large[2]["dofs"])),
             large_text, speedup, step42[0], step42[1], ours["wall"],
             ours["force"], versus, shares_text,
             "{:,}".format(int(hertz[1]["dofs"])), hertz[1]["wall"],
             hertz[2]["wall"], hertz_speedup, hertz_amg["wall"],
             hertz_amg["wall"] / hertz[2]["wall"]))


def main():
    repeat, parts = 1 if common.SMOKE else 3, {"2d", "3d"}
    arguments = sys.argv[1:]
    while arguments:
        if arguments[0] == "--repeat" and len(arguments) > 1:
            repeat = int(arguments[1])
            arguments = arguments[2:]
        elif arguments[0] in ("--2d", "--3d"):
            parts = {arguments[0][2:]}
            arguments = arguments[1:]
        else:
            sys.exit(__doc__)
    common.ensure_tools(())
    os.makedirs(WORK, exist_ok=True)

    sections = {}
    if "3d" in parts:
        sections["benchmark-3d"] = three_d(repeat)
    if "2d" in parts:
        sections["benchmark"] = two_d(repeat)
    common.replace_sections(common.output_file("README.md"), sections)


def two_d(repeat):
    """The 2D benchmarks; returns the README section."""
    header = ["cycle", "dofs", "iterations", "contact solve [s]",
              "linear solve [s]", "ratio", "peak memory [MB]"]
    finals = []
    detail = ""
    for name, scene, overrides in CASES[:1] if common.SMOKE else CASES:
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
    return ("The default scene, medians of %d runs:\n\n%s\n"
            "The final cycle of each benchmark:\n\n%s" %
            (repeat, detail, summary))


if __name__ == "__main__":
    main()
