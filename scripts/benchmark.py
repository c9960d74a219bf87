#!/usr/bin/env python3
"""How near its lower bound the contact solver runs. For the shipped scenes
(and the default scene with every method), per cycle: the wall time of the
contact solve over that of one linear elasticity solve on the same mesh with
the same linear solver, both measured in the same run (`Output/Timing table`),
and the peak memory. Medians over repeated runs; the machine is shared.

    scripts/benchmark [--repeat N] [--2d | --3d | --friction-3d |
                       --degree-2]
                      (default: all four parts, 3 runs per scene)

The 3D part runs the 3D scenes on one and two processes (`mpirun`), the
indentation scene at more than a million dofs as a whole run, deal.II's
step-42 (built from the documentation package, made elastic) against it on
two processes, every shipped scene for its output share, and the 2D Hertz
scene at more than 200k dofs on one and two processes. The friction-3d
part runs the indentation scene past a million dofs on two processes
(matrix-free) with Coulomb friction and without, in turn: per cycle the
contact solve of each over one linear solve, their quotient, and the memory
per dof. The degree-2 part runs scenes on Q1 and on Q2 (Element degree
= 2) in turn, with the assembled operator and, in 3D, the matrix-free one:
one linear solve's time per dof and core on the last cycle of each, and
Q2's over Q1's with the same operator.

Prints the tables and rewrites the sections of doc/performance.md between
<!-- begin benchmark --> and <!-- end benchmark --> (and benchmark-3d,
benchmark-friction-3d, benchmark-degree-2).
Runs go to build/benchmark/.

For the test suite only: with SIGNORINI_SMOKE=FOLDER (see scripts/common.py)
every run has at most two cycles, the default is one repeat, each table
but the 2D Hertz line measures its first case only, step-42 is neither built
nor run, and the page rewritten is FOLDER/doc/performance.md, a copy.
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
    # The same scene with Coulomb friction: its cycles against the
    # frictionless ones above (the cost of a frictional load step).
    ("hertz_cylinder_friction", "prm/hertz_cylinder.prm",
     {"Obstacle": {"Friction coefficient": "0.3"}}),
]


# 3D and parallel runs: the final cycle's ratio on one and two processes.
AMG_CG = {"Linear solver": {"Type": "amg cg"}}
MATRIX_FREE = {"Linear solver": {"Type": "matrix-free"}}
CASES_3D = [
    ("hertz_sphere", "prm/hertz_sphere.prm",
     {"Mesh refinement": {"Number of cycles": "6"}, **AMG_CG}),
    ("hertz_sphere_matrix_free", "prm/hertz_sphere.prm",
     {"Mesh refinement": {"Number of cycles": "6"}, **MATRIX_FREE}),
    ("sphere_indentation", "prm/sphere_indentation.prm", AMG_CG),
    ("sphere_indentation_matrix_free", "prm/sphere_indentation.prm",
     MATRIX_FREE),
]


def elastic_operator(overrides):
    """The elastic operator a case runs: matrix-free or assembled."""
    chosen = overrides.get("Linear solver", {}).get("Type", "")
    return "matrix-free" if chosen == "matrix-free" else "assembled"


# The indentation scene refined to more than 1.4 million dofs.
LARGE = {"Mesh refinement": {"Number of cycles": "7"}}
# The 2D Hertz scene at more than 200k dofs.
HERTZ_2D = {"Mesh refinement": {"Number of cycles": "12"}}
STEP42 = "/usr/share/doc/libdeal.ii-doc/examples/step-42"


def median_rows(runs):
    """Per cycle of the runs' timing tables: dofs, iterations and the
    medians of the contact solve, the linear solve, their ratio and the
    peak memory."""
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


def measure(name, scene, overrides, repeat, processes=0):
    """Per cycle: dofs, iterations and the medians over `repeat` runs of the
    contact solve, the linear solve, their ratio and the peak memory."""
    return measure_in_turn([(name, scene, overrides, processes)],
                           repeat)[name]


def measure_in_turn(cases, repeat):
    """measure() for each of `cases` (name, scene, overrides, processes),
    the cases run in turn `repeat` times, so that the machine's drift meets
    each alike; per case name the rows."""
    runs = {case[0]: [] for case in cases}
    for _ in range(repeat):
        for name, scene, overrides, processes in cases:
            settings = dict(overrides)
            settings["Output"] = {"Timing table": "true"}
            runs[name].append(common.run(WORK, name, scene, settings,
                                         processes=processes).timings)
    return {name: median_rows(r) for name, r in runs.items()}


def whole_runs(name, scene, overrides, repeat, processes,
               long_run=float("inf")):
    """Medians over `repeat` runs (one if it takes `long_run` seconds) of
    the whole run as a user runs it (output included, no timing table):
    wall time of the process [s], the share of the run spent writing
    output, peak memory [MB] and per dof [kB], and the final dofs."""
    return whole_runs_in_turn([(name, scene, overrides, processes)], repeat,
                              long_run)[name]


def whole_runs_in_turn(cases, repeat, long_run=float("inf"), between=None):
    """whole_runs() for each of `cases` (name, scene, overrides,
    processes), run in turn `repeat` times; `between`, if given, is called
    once per turn before the cases (another program timed alike)."""
    runs = {case[0]: [] for case in cases}
    for turn in range(repeat):
        if between:
            between()
        for name, scene, overrides, processes in cases:
            if turn and runs[name][0].wall >= long_run:
                continue
            settings = dict(overrides)
            settings["Output"] = {"Print timings": "true"}
            runs[name].append(common.run(WORK, name, scene, settings,
                                         processes=processes))
    median = statistics.median
    result = {}
    for name, done in runs.items():
        dofs = done[0].rows[-1]["dofs"]
        result[name] = {
            "wall": median(r.wall for r in done),
            "output": median(r.timer["Output"] / r.timer["Total"]
                             for r in done),
            "checkpoint": median(r.timer.get("Output: checkpoint", 0.) /
                                 r.timer["Total"] for r in done),
            "memory": median(r.peak_memory for r in done),
            "per_dof": median(r.peak_memory * 1024. / dofs for r in done),
            "dofs": dofs,
            "force": done[0].rows[-1].get("contact_force_z", float("nan")),
        }
    return result


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


def run_step42(folder):
    """One run of step-42 on two processes: its wall time and its last
    contact force."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_btl_vader_single_copy_mechanism="none")
    print("  step-42", file=sys.stderr)
    start = time.monotonic()
    process = subprocess.run(
        ["mpirun", "-np", "2", "./step-42", "p1_adaptive.prm"],
        cwd=folder, env=env, stdout=subprocess.PIPE, text=True, check=True)
    forces = re.findall(r"Contact force = (\S+)", process.stdout)
    return time.monotonic() - start, float(forces[-1])


OPERATORS = (("assembled", AMG_CG), ("matrix-free", MATRIX_FREE))


class Pairs:
    """Two one-process runs of a case at once, one per core
    (common.run_pair), once per turn of whole_runs_in_turn() (pass the
    object as its `between`): the machine's own bound on a speed-up from 1
    to 2 processes is 2 * (one run alone) / (each of two at once)."""

    def __init__(self, name, scene, overrides):
        self.case = (name, scene, with_overrides(
            overrides, {"Output": {"Print timings": "true"}}))
        self.walls = []

    def __call__(self):
        runs = common.run_pair(WORK, *self.case)
        if runs:
            self.walls.append(statistics.mean(r.wall for r in runs))

    def bound(self, alone):
        """(median wall of each of two at once [s], the bound) for one
        process's median wall `alone`; NaNs on fewer than two cores."""
        if not self.walls:
            return float("nan"), float("nan")
        together = statistics.median(self.walls)
        return together, 2. * alone / together


def with_overrides(base, extra):
    """`base` overrides with the subsections of `extra` added."""
    merged = {key: dict(value) for key, value in base.items()}
    for key, value in extra.items():
        merged.setdefault(key, {}).update(value)
    return merged


def three_d(repeat):
    """The 3D and parallel figures; returns the section of
    doc/performance.md."""
    rows = []
    cases = CASES_3D[:2] if common.SMOKE else CASES_3D
    # A scene's cases (both operators, one and two processes) in turn.
    for scene in sorted(set(case[1] for case in cases),
                        key=[case[1] for case in cases].index):
        runs = [("%s_np%d" % (name, n), scene, overrides, n)
                for n in (1, 2)
                for name, case_scene, overrides in cases
                if case_scene == scene]
        measured = measure_in_turn(runs, repeat)
        for run_name, _, overrides, processes in runs:
            last = measured[run_name][-1]
            rows.append(["`%s`" % os.path.basename(scene),
                         elastic_operator(overrides), "%d" % processes,
                         "{:,}".format(int(last["dofs"])),
                         "%d" % last["iterations"],
                         "%.2f" % last["linear_solve"],
                         "%.1f" % (1e6 * last["linear_solve"] * processes /
                                   last["dofs"]),
                         "%.2f" % last["ratio"],
                         "%.0f" % last["peak_memory"]])
    ratios = common.table(["scene", "elastic operator", "processes",
                           "final dofs", "Newton steps",
                           "one linear solve [s]",
                           "µs per dof per core", "ratio",
                           "peak memory [MB]"], rows)
    print("\n3D, final cycles\n\n" + ratios)

    # The large run with both operators, one and two processes, in turn.
    large_cases = [("indentation_large_%s_np%d" % (label, n),
                    "prm/sphere_indentation.prm",
                    with_overrides(LARGE, overrides), n)
                   for n in (1, 2) for label, overrides in OPERATORS]
    large_pairs = Pairs("indentation_large_pair", "prm/sphere_indentation.prm",
                        with_overrides(LARGE, MATRIX_FREE))
    large = whole_runs_in_turn(large_cases, repeat, between=large_pairs)
    large_rows = []
    for name, _, overrides, n in large_cases:
        r = large[name]
        large_rows.append([elastic_operator(overrides), "%d" % n,
                           "{:,}".format(int(r["dofs"])), "%.1f" % r["wall"],
                           "%.1f %%" % (100 * r["output"]),
                           "%.0f" % r["memory"], "%.2f" % r["per_dof"]])
    large_text = common.table(["elastic operator", "processes", "final dofs",
                               "wall time [s]", "output", "peak memory [MB]",
                               "memory per dof [kB]"], large_rows)
    wall = {(label, n): large["indentation_large_%s_np%d" % (label, n)]["wall"]
            for n in (1, 2) for label, _ in OPERATORS}
    speedup = {label: wall[(label, 1)] / wall[(label, 2)]
               for label, _ in OPERATORS}
    gain = wall[("assembled", 2)] / wall[("matrix-free", 2)]
    together, bound = large_pairs.bound(wall[("matrix-free", 1)])
    print("\nIndentation at %s dofs\n\n%s\nspeed-up 1 -> 2 processes: "
          "assembled %.2f, matrix-free %.2f; matrix-free on 2 processes "
          "%.2f times faster; two 1-process matrix-free runs at once %.1f s "
          "each: bound %.2f" %
          ("{:,}".format(int(large_cases and large[large_cases[-1][0]]["dofs"])),
           large_text, speedup["assembled"], speedup["matrix-free"], gain,
           together, bound))

    # step-42 and signorini on its meshes, 2 processes, in turn.
    step42_cases = [("indentation_step42_%s" % label,
                     "prm/sphere_indentation.prm", overrides, 2)
                    for label, overrides in OPERATORS]
    step42_runs = []
    if common.SMOKE:
        print("step-42: not built in smoke mode", file=sys.stderr)
        step42_cases = step42_cases[:1]
        between = None
    else:
        folder = build_step42()
        def between():
            step42_runs.append(run_step42(folder))
    ours = whole_runs_in_turn(step42_cases, repeat, between=between)
    step42 = ((statistics.median(w for w, _ in step42_runs),
               step42_runs[0][1]) if step42_runs
              else (float("nan"), float("nan")))
    versus = {label: step42[0] / ours["indentation_step42_%s" % label]["wall"]
              for label, _ in OPERATORS
              if "indentation_step42_%s" % label in ours}
    versus.setdefault("matrix-free", float("nan"))
    mf = ours.get("indentation_step42_matrix-free",
                  ours["indentation_step42_assembled"])
    print("step-42 (elastic), 2 processes: %.1f s, contact force %.3f; "
          "signorini assembled %.1f s (%.1f times faster), matrix-free %.1f s "
          "(%.1f times faster), contact force %.3f" %
          (step42[0], step42[1],
           ours["indentation_step42_assembled"]["wall"],
           versus["assembled"], mf["wall"], versus["matrix-free"],
           mf["force"]))

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

    amg = with_overrides(HERTZ_2D, {"Linear solver": {"Type": "amg cg"}})
    direct = with_overrides(HERTZ_2D, {"Linear solver": {"Type": "direct"}})
    hertz_pairs = Pairs("hertz_2d_pair", "prm/hertz_cylinder.prm", HERTZ_2D)
    hertz = whole_runs_in_turn(
        [("hertz_2d_np1", "prm/hertz_cylinder.prm", HERTZ_2D, 1),
         ("hertz_2d_np2", "prm/hertz_cylinder.prm", HERTZ_2D, 2),
         ("hertz_2d_direct_np1", "prm/hertz_cylinder.prm", direct, 1),
         ("hertz_2d_amg_np1", "prm/hertz_cylinder.prm", amg, 1)], repeat,
        between=hertz_pairs)
    hertz_speedup = hertz["hertz_2d_np1"]["wall"] / hertz["hertz_2d_np2"]["wall"]
    hertz_together, hertz_bound = hertz_pairs.bound(
        hertz["hertz_2d_np1"]["wall"])
    print("2D Hertz at %s dofs, automatic: %.1f s on one process, %.1f s on "
          "two: speed-up %.2f; two 1-process runs at once %.1f s each: bound "
          "%.2f; on one process direct %.1f s, amg cg %.1f s" %
          ("{:,}".format(int(hertz["hertz_2d_np1"]["dofs"])),
           hertz["hertz_2d_np1"]["wall"], hertz["hertz_2d_np2"]["wall"],
           hertz_speedup, hertz_together, hertz_bound,
           hertz["hertz_2d_direct_np1"]["wall"],
           hertz["hertz_2d_amg_np1"]["wall"]))

    return ("3D scenes (`hertz_sphere.prm` with 6 cycles), final cycle, "
            "%s, each scene's runs in turn (`mpirun -np 1` and `-np 2`; one "
            "linear solve is the elasticity system of the final mesh with "
            "the same elastic operator, and the ratio the contact solve over "
            "it):\n\n%s\n"
            "`sphere_indentation.prm` refined to %s dofs (7 cycles), the "
            "whole run as a user runs it, output included, the four runs "
            "in turn:\n\n%s\n"
            "Speed-up from 1 to 2 processes: assembled **%.2f**, matrix-free "
            "**%.2f**; on two processes the matrix-free run is **%.2f** times "
            "faster than the assembled one. Two 1-process matrix-free runs "
            "at once, each held to a core of its own, take %.1f s each: "
            "sharing the machine, a second process can gain at most "
            "**%.2f**. step-42 itself (elastic, 6 "
            "cycles to 493,287 dofs, 2 processes, run in turn with "
            "signorini's): %.1f s, contact force %.3f N; signorini on the "
            "same meshes: assembled %.1f s (**%.1f times faster**), "
            "matrix-free %.1f s (**%.1f times faster**), %.3f N.\n\n"
            "Output share of the run time, each shipped scene as shipped, "
            "one process (the checkpoint, written after every cycle, is its "
            "own column):\n\n%s\n"
            "2D Hertz at %s dofs (12 cycles), `automatic` linear solver: "
            "%.1f s on one process, %.1f s on two: speed-up **%.2f** (two "
            "1-process runs at once: %.1f s each, a bound of %.2f); on one "
            "process direct %.1f s, amg cg %.1f s.\n" %
            ("one run" if repeat == 1 else "medians of %d runs" % repeat,
             ratios, "{:,}".format(int(large[large_cases[-1][0]]["dofs"])),
             large_text, speedup["assembled"], speedup["matrix-free"], gain,
             together, bound, step42[0], step42[1],
             ours["indentation_step42_assembled"]["wall"],
             versus["assembled"], mf["wall"], versus["matrix-free"],
             mf["force"], shares_text,
             "{:,}".format(int(hertz["hertz_2d_np1"]["dofs"])),
             hertz["hertz_2d_np1"]["wall"], hertz["hertz_2d_np2"]["wall"],
             hertz_speedup, hertz_together, hertz_bound,
             hertz["hertz_2d_direct_np1"]["wall"],
             hertz["hertz_2d_amg_np1"]["wall"]))


def main():
    repeat = 1 if common.SMOKE else 3
    parts = {"2d", "3d", "friction-3d", "degree-2"}
    arguments = sys.argv[1:]
    while arguments:
        if arguments[0] == "--repeat" and len(arguments) > 1:
            repeat = int(arguments[1])
            arguments = arguments[2:]
        elif arguments[0] in ("--2d", "--3d", "--friction-3d", "--degree-2"):
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
    if "friction-3d" in parts:
        sections["benchmark-friction-3d"] = friction_3d(repeat)
    if "degree-2" in parts:
        sections["benchmark-degree-2"] = degree_2(repeat)
    common.replace_sections(common.output_file("doc/performance.md"),
                            sections)


def two_d(repeat):
    """The 2D benchmarks; returns the section of doc/performance.md."""
    header = ["cycle", "dofs", "iterations", "contact solve [s]",
              "linear solve [s]", "ratio", "peak memory [MB]"]
    finals = []
    detail = ""
    measured = {}
    for name, scene, overrides in CASES[:1] if common.SMOKE else CASES:
        rows = measure(name, scene, overrides, repeat)
        measured[name] = rows
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
        if "Obstacle" in overrides:
            method += ", friction"
        finals.append(["`%s`" % os.path.basename(scene), method,
                       "{:,}".format(int(last["dofs"])),
                       "%d" % last["iterations"], "%.2f" % last["ratio"],
                       "%.0f" % last["peak_memory"]])
    summary = common.table(["scene", "method", "final dofs", "iterations",
                            "ratio", "peak memory [MB]"], finals)
    print("Final cycles\n\n" + summary)
    text = ("The default scene, medians of %d runs:\n\n%s\n"
            "The final cycle of each benchmark:\n\n%s" %
            (repeat, detail, summary))
    if "hertz_cylinder" in measured and "hertz_cylinder_friction" in measured:
        friction = friction_table(measured["hertz_cylinder"],
                                  measured["hertz_cylinder_friction"])
        print("Friction\n\n" + friction)
        text += ("\nA frictional load step against a frictionless one: the "
                 "2D Hertz scene with Coulomb friction (mu = 0.3) and without, "
                 "per cycle each one's contact solve over one linear solve on "
                 "its mesh, and their quotient:\n\n" + friction)
    return text


# Q1 against Q2: (name, scene, [(element, operator, overrides)]), the Q2
# runs from a coarser start so that both end near the same dofs; in 3D both
# operators, the matrix-free one a cycle further (its per-dof cost is
# that of large meshes).
DIRECT = {"Linear solver": {"Type": "direct"}}
SOLVERS = {"direct": DIRECT, "AMG-CG": AMG_CG, "matrix-free": MATRIX_FREE}


def degree_runs(operator, cycles, q2_refinement, q2_cycles=None):
    """Q1 and Q2 with `operator` to `cycles` cycles (Q2 to `q2_cycles` if
    given), Q2 from `q2_refinement` initial refinements (Q1 from the
    scene's)."""
    return [("Q1", operator, {"Mesh refinement": {"Number of cycles": cycles},
                              **SOLVERS[operator]}),
            ("Q2", operator, {"Geometry": {"Element degree": "2",
                                           "Initial refinement":
                                           q2_refinement},
                              "Mesh refinement": {"Number of cycles":
                                                  q2_cycles or cycles},
                              **SOLVERS[operator]})]


DEGREE_CASES = [
    # (In 2D Q2 two cycles further: its Kelly cycles add fewer dofs.)
    ("hertz_cylinder (2D, curved)", "prm/hertz_cylinder.prm",
     degree_runs("direct", "10", "1", "12")),
    ("sphere_indentation (3D box)", "prm/sphere_indentation.prm",
     degree_runs("AMG-CG", "4", "2") + degree_runs("matrix-free", "5", "2")),
    ("hertz_sphere (3D, curved)", "prm/hertz_sphere.prm",
     degree_runs("AMG-CG", "5", "1") + degree_runs("matrix-free", "6", "1")),
]


def degree_2(repeat):
    """Q1 against Q2: one linear solve per dof and core on the last cycle,
    each measured in the same run as its contact solve, a scene's runs in
    turn; returns the section of doc/performance.md."""
    rows = []
    cases = DEGREE_CASES[:1] if common.SMOKE else DEGREE_CASES
    for name, scene, runs in cases:
        slug = name.split()[0]
        keys = ["%s_%s_%s" % (slug, element.lower(), operator.lower()
                              .replace("-", "_"))
                for element, operator, _ in runs]
        measured = measure_in_turn(
            [(key, scene, overrides, 0)
             for key, (_, _, overrides) in zip(keys, runs)], repeat)
        per_dof = {}
        shown = name
        for key, (element, operator, _) in zip(keys, runs):
            last = measured[key][-1]
            per_dof[(element, operator)] = (1e6 * last["linear_solve"] /
                                            last["dofs"])
            rows.append([shown, element, operator,
                         "{:,}".format(int(last["dofs"])),
                         "%.3f" % last["linear_solve"],
                         "%.2f" % per_dof[(element, operator)],
                         "%.2f" % last["ratio"]])
            shown = ""
        for operator in dict.fromkeys(op for _, op, _ in runs):
            if ("Q1", operator) in per_dof and ("Q2", operator) in per_dof:
                rows.append(["", "Q2 / Q1", operator, "", "", "%.2f" % (
                    per_dof[("Q2", operator)] / per_dof[("Q1", operator)]),
                    ""])
    text = common.table(["scene", "element", "operator", "last cycle dofs",
                         "linear solve [s]", "per dof [µs]",
                         "contact solve / linear solve"], rows)
    print("Degree 2 against degree 1\n\n" + text)
    return ("One linear solve on the last cycle (direct in 2D; in 3D the "
            "assembled operator with AMG-CG and the matrix-free one with "
            "geometric multigrid, Q2's stepping down to Q1 on its own mesh "
            "first), one process, medians of %d runs, a scene's runs in "
            "turn:\n\n%s" % (repeat, text))


def friction_3d(repeat):
    """The indentation scene past a million dofs, matrix-free on two
    processes, with Coulomb friction (mu = 0.3) and without, run in turn;
    returns the section of doc/performance.md."""
    large = with_overrides(LARGE, MATRIX_FREE)
    if common.SMOKE:
        large = dict(MATRIX_FREE)
    friction = with_overrides(large,
                              {"Obstacle": {"Friction coefficient": "0.3"}})
    measured = measure_in_turn(
        [("indentation_frictionless", "prm/sphere_indentation.prm", large, 2),
         ("indentation_friction", "prm/sphere_indentation.prm", friction, 2)],
        repeat)
    plain, rubbing = (measured["indentation_frictionless"],
                      measured["indentation_friction"])
    table = friction_table(plain, rubbing)
    # Memory and wall time of the whole runs as a user runs them (the
    # timing table's extra linear solve adds to the peak).
    whole = whole_runs_in_turn(
        [("indentation_whole_frictionless", "prm/sphere_indentation.prm",
          large, 2),
         ("indentation_whole_friction", "prm/sphere_indentation.prm",
          friction, 2)], 1)
    per_dof = [whole["indentation_whole_" + name]["per_dof"]
               for name in ("frictionless", "friction")]
    walls = [whole["indentation_whole_" + name]["wall"]
             for name in ("frictionless", "friction")]
    seconds = [sum(r["contact_solve"] for r in rows)
               for rows in (plain, rubbing)]
    print("\nFriction in 3D, matrix-free, 2 processes\n\n" + table +
          "\nmemory per dof: %.2f kB frictionless, %.2f kB with friction; "
          "contact solves %.1f s and %.1f s; whole runs %.1f s and %.1f s" %
          (per_dof[0], per_dof[1], seconds[0], seconds[1], walls[0],
           walls[1]))
    return ("`sphere_indentation.prm` refined to %s dofs (7 cycles) on two "
            "processes, matrix-free, with Coulomb friction (mu = 0.3) and "
            "without, %s, the two in turn: per cycle each one's contact "
            "solve over one linear solve on its mesh (the friction's GMRES "
            "against the frictionless CG, both with the same multigrid), "
            "and their quotient:\n\n%s\n"
            "All cycles' contact solves: %.1f s frictionless, %.1f s with "
            "friction. The whole runs as a user runs them (output "
            "included, no timing table, one run each): %.1f s and %.1f s, "
            "peak memory **%.2f kB per dof** frictionless and **%.2f kB per "
            "dof** with friction (two processes together).\n" %
            ("{:,}".format(int(rubbing[-1]["dofs"])),
             "one run" if repeat == 1 else "medians of %d runs" % repeat,
             table, seconds[0], seconds[1], walls[0], walls[1], per_dof[0],
             per_dof[1]))


def friction_table(frictionless, frictional):
    """The Hertz scene's cycles with and without friction side by side."""
    rows = []
    for plain, friction in zip(frictionless, frictional):
        rows.append(["%d" % plain["cycle"],
                     "{:,}".format(int(friction["dofs"])),
                     "%d" % plain["iterations"], "%d" % friction["iterations"],
                     "%.2f" % plain["ratio"], "%.2f" % friction["ratio"],
                     "%.2f" % (friction["ratio"] / plain["ratio"])])
    return common.table(["cycle", "dofs (friction)", "iterations",
                         "iterations (friction)", "ratio",
                         "ratio (friction)", "friction / frictionless"], rows)


if __name__ == "__main__":
    main()
