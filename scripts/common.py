"""What scripts/validation, scripts/benchmark and scripts/work-precision
share: building, running a scene with overrides, tables and charts."""
import csv
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "doc")
SIGNORINI = os.path.join(ROOT, "build", "signorini")


def ensure_tools(tools=(("gnuplot-nox", "gnuplot"),)):
    """Builds the program and installs the Debian packages of `tools`
    ((package, command) pairs) whose command is missing."""
    subprocess.run([os.path.join(ROOT, "scripts", "build")], check=True,
                   stdout=sys.stderr)
    missing = [p for p, tool in tools
               if subprocess.run(["sh", "-c", "command -v " + tool],
                                 stdout=subprocess.DEVNULL).returncode]
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


def run(work, name, base, settings, check=True, processes=0):
    """Runs `base` (a .prm, relative to the repository) with `settings`
    {subsection: {entry: value}} overriding it, in work/name; under
    `mpirun -np processes` if processes > 0."""
    folder = os.path.join(work, name)
    os.makedirs(folder, exist_ok=True)
    for old in ("statistics.csv", "timings.csv"):
        if os.path.exists(os.path.join(folder, old)):
            os.remove(os.path.join(folder, old))
    settings = dict(settings)
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
            os.symlink(os.path.join(scenes, entry), link)
    lines = ["include " + os.path.join(ROOT, base)]
    for section, entries in settings.items():
        lines.append("subsection " + section)
        lines += ["  set %s = %s" % item for item in entries.items()]
        lines.append("end")
    # Named apart from the scene files linked above, and never written
    # through a link: a run must not touch the files it was given.
    prm = os.path.join(work, name + "-run.prm")
    if os.path.islink(prm):
        os.unlink(prm)
    descriptor = os.open(prm, os.O_WRONLY | os.O_CREAT | os.O_TRUNC |
                         os.O_NOFOLLOW, 0o644)
    with os.fdopen(descriptor, "w") as out:
        out.write("\n".join(lines) + "\n")
    print("  " + name, file=sys.stderr)
    command = [SIGNORINI, prm]
    env = None
    if processes > 0:
        command = ["mpirun", "-np", str(processes)] + command
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_btl_vader_single_copy_mechanism="none")
    start = time.monotonic()
    process = subprocess.run(command, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=env)
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
    with open(path, "w") as out:
        for row in rows:
            out.write(" ".join("%.10g" % row[c] for c in columns) + "\n")
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
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)
