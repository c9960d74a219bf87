"""What scripts/validation, scripts/benchmark and scripts/work-precision
share: building, running a scene with overrides, tables and charts.

Smoke mode, for the test suite only (tests/scripts/): with the environment
variable SIGNORINI_SMOKE=FOLDER a script builds and installs nothing, runs
every scene on at most SMOKE_CYCLES cycles, once, on the first mesh or
value of each sweep, puts its runs in FOLDER, and rewrites copies of the
doc/ files it is documented to rewrite, in FOLDER (doc/NAME), instead of
the tracked files. It checks that the pipeline runs
and touches nothing else; its numbers mean nothing."""
import concurrent.futures
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "doc")
SIGNORINI = os.path.join(ROOT, "build", "signorini")
SMOKE = os.path.abspath(os.environ["SIGNORINI_SMOKE"]) \
    if os.environ.get("SIGNORINI_SMOKE") else None
SMOKE_CYCLES = 2


def work_folder(name):
    """Where a script's runs go: build/NAME, or FOLDER/NAME in smoke
    mode."""
    return os.path.join(SMOKE or os.path.join(ROOT, "build"), name)


def output_file(relative):
    """The file `relative` to the repository (doc/NAME) that a
    script rewrites: itself, or in smoke mode its copy in the smoke
    folder (copied from the repository's on first use)."""
    if not SMOKE:
        return os.path.join(ROOT, relative)
    path = os.path.join(SMOKE, relative)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    original = os.path.join(ROOT, relative)
    if not os.path.lexists(path) and os.path.isfile(original):
        with open(original, "rb") as source:
            write_file(path, source.read())
    return path


def write_file(path, content):
    """Writes `content` (str or bytes) to `path` whole: into a new file
    beside it, renamed over it, so that a link at `path` is replaced, never
    written through."""
    folder = os.path.dirname(os.path.abspath(path))
    descriptor, temporary = tempfile.mkstemp(dir=folder, prefix=".tmp-")
    try:
        with os.fdopen(descriptor, "wb" if isinstance(content, bytes)
                       else "w") as out:
            out.write(content)
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise


def ensure_tools(tools=(("gnuplot-nox", "gnuplot"),)):
    """Builds the program and installs the Debian packages of `tools`
    ((package, command) pairs) whose command is missing. In smoke mode it
    only checks that they are there."""
    missing = [p for p, tool in tools
               if subprocess.run(["sh", "-c", "command -v " + tool],
                                 stdout=subprocess.DEVNULL).returncode]
    if SMOKE:
        if missing or not os.access(SIGNORINI, os.X_OK):
            sys.exit("%s: smoke mode builds and installs nothing, and %s "
                     "is missing" % (sys.argv[0], ", ".join(
                         missing or [SIGNORINI])))
        return
    subprocess.run([os.path.join(ROOT, "scripts", "build")], check=True,
                   stdout=sys.stderr)
    if missing:
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        subprocess.run(["apt-get", "update", "-qq"], check=True, env=env)
        subprocess.run(["apt-get", "install", "-y", "-qq",
                        "--no-install-recommends"] + missing, check=True,
                       env=env, stdout=subprocess.DEVNULL)


def read_table(path):
    """The rows of a csv file as dicts of floats ([] if it is missing)."""
    if not os.path.exists(path):
        return []
    with open(path) as table:
        return [{k: float(v) for k, v in row.items()}
                for row in csv.DictReader(table)]


class Run:
    """One run of the program: exit `status`, the `error` line, `stdout`, the
    rows of statistics.csv and timings.csv, and the `wall` time of the
    process."""


def run(work, name, base, settings, check=True, processes=0, core=None):
    """Runs `base` (a .prm, relative to the repository) with `settings`
    {subsection: {entry: value}} overriding it, in work/name; under
    `mpirun -np processes` if processes > 0, or, if `core` is given, as one
    process under mpirun held to that core alone (`taskset`)."""
    folder = os.path.join(work, name)
    os.makedirs(folder, exist_ok=True)
    for old in ("statistics.csv", "timings.csv"):
        if os.path.exists(os.path.join(folder, old)):
            os.remove(os.path.join(folder, old))
    settings = dict(settings)
    if SMOKE:
        refinement = dict(settings.get("Mesh refinement", {}))
        cycles = int(refinement.get("Number of cycles", SMOKE_CYCLES))
        refinement["Number of cycles"] = str(min(cycles, SMOKE_CYCLES))
        settings["Mesh refinement"] = refinement
    output = {"Print timings": "false", "Verbose": "false"}
    output.update(settings.get("Output", {}))
    output["Directory"] = folder
    settings["Output"] = output
    # A scene that includes another (a variant), or names a mesh file,
    # finds it beside the file given to the program: link the scene's
    # folder's files there.
    scenes = os.path.dirname(os.path.join(ROOT, base))
    for entry in os.listdir(scenes):
        link = os.path.join(work, entry)
        if not os.path.lexists(link):
            try:
                os.symlink(os.path.join(scenes, entry), link)
            except FileExistsError:  # made by a run started beside this one
                pass
    lines = ["include " + os.path.join(ROOT, base)]
    for section, entries in settings.items():
        lines.append("subsection " + section)
        lines += ["  set %s = %s" % item for item in entries.items()]
        lines.append("end")
    # Named apart from the scene files linked above, and never written
    # through a link: a run must not touch the files it was given.
    prm = os.path.join(work, name + "-run.prm")
    write_file(prm, "\n".join(lines) + "\n")
    print("  " + name, file=sys.stderr)
    command = [SIGNORINI, prm]
    env = None
    if core is not None:
        # mpirun would bind every one-process run to the same first core.
        command = ["mpirun", "--bind-to", "none", "-np", "1", "taskset",
                   "-c", str(core)] + command
    elif processes > 0:
        command = ["mpirun", "-np", str(processes)] + command
    session = None
    if core is not None or processes > 0:
        # Each mpirun with a temporary folder of its own: Open MPI's session
        # folder under a shared one races with runs that end at the same
        # moment ("orte_init failed").
        session = tempfile.mkdtemp(prefix="signorini-mpirun-")
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_btl_vader_single_copy_mechanism="none",
                   TMPDIR=session)
    start = time.monotonic()
    try:
        process = subprocess.run(command, stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, text=True, env=env)
    finally:
        if session is not None:
            shutil.rmtree(session, ignore_errors=True)
    result = Run()
    result.wall = time.monotonic() - start
    result.status = process.returncode
    result.stdout = process.stdout
    result.error = process.stderr.strip().splitlines()[-1] \
        if process.stderr.strip() else ""
    if check and result.status != 0:
        sys.exit("%s: %s failed: %s" % (sys.argv[0], name, result.error))
    result.timer = timer_sections(result.stdout)
    match = re.search(r"^Peak memory: (\S+) MB", result.stdout, re.M)
    result.peak_memory = float(match.group(1)) if match else float("nan")
    result.rows = read_table(os.path.join(folder, "statistics.csv"))
    result.timings = read_table(os.path.join(folder, "timings.csv"))
    return result


def run_pair(work, name, base, settings):
    """Two one-process runs of run() at once, each held to a core of its
    own, in work/NAME-a and work/NAME-b: two processes that share the
    machine but no core, so their slowdown against one run alone bounds
    what a second process can gain. The two Runs, or None on fewer than two
    cores."""
    cores = sorted(os.sched_getaffinity(0))
    if len(cores) < 2:
        return None
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        started = [pool.submit(run, work, "%s-%s" % (name, suffix), base,
                               settings, True, 0, core)
                   for suffix, core in zip("ab", cores)]
        return [future.result() for future in started]


def timer_sections(text):
    """The wall times [s] of the timer summary that `Print timings` prints,
    by section; 'Total' is the whole run inside the program."""
    sections = {}
    match = re.search(r"Total wallclock time elapsed since start\s*\|\s*"
                      r"([0-9.e+-]+)s", text)
    if match:
        sections["Total"] = float(match.group(1))
    for name, seconds in re.findall(
            r"^\| (\S[^|]*?)\s*\|\s*\d+ \|\s*([0-9.e+-]+)s \|", text, re.M):
        sections[name] = float(seconds)
    return sections


def write_data(work, name, rows, columns):
    """Writes the `columns` of `rows` as a gnuplot data file; returns its
    path."""
    path = os.path.join(work, name + ".dat")
    write_file(path, "".join(" ".join("%.10g" % row[c] for c in columns) +
                             "\n" for row in rows))
    return path


def gnuplot(script):
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def table(header, rows):
    """A Markdown table."""
    text = "| " + " | ".join(header) + " |\n"
    text += "|" + "---|" * len(header) + "\n"
    for row in rows:
        text += "| " + " | ".join(row) + " |\n"
    return text


def replace_sections(path, sections):
    """Replaces what lies between <!-- begin NAME --> and <!-- end NAME -->
    in `path` by sections[NAME], writing the file whole."""
    with open(path) as f:
        text = f.read()
    for name, body in sections.items():
        pattern = re.compile(r"(<!-- begin %s -->\n).*?(<!-- end %s -->)" %
                             (re.escape(name), re.escape(name)), re.S)
        if not pattern.search(text):
            sys.exit("%s: %s has no section '%s'" % (sys.argv[0], path, name))
        text = pattern.sub(lambda m: m.group(1) + body + m.group(2), text)
    write_file(path, text)
