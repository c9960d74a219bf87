#!/usr/bin/env python3
"""Runs one of the documented scripts in its smoke mode and checks that it
changed nothing of the repository outside build/: every folder, file (its
bytes) and link (its target) is the same afterwards, and no file appeared
or went. Also checks the files the script must have written in its smoke
folder.

    untouched.py NAME [--plain] [--expect FILE]... [--says TEXT]...
                 [--needs COMMAND]... [--deadline SECONDS] -- COMMAND...

COMMAND runs in a fresh folder build/tests/scripts/NAME, which is also its
SIGNORINI_SMOKE folder (see scripts/common.py), unless --plain: then it runs
as a user runs it, with no smoke mode. Each --expect FILE (relative
to that folder) must exist and not be empty afterwards; each --says TEXT
must be in what the script printed. If a --needs COMMAND is not installed,
the test is skipped (exit status 77): tests install nothing. COMMAND and
everything it started are stopped after SECONDS (270 unless --deadline,
below ctest's limit of 300, so that the verdicts and the script's last lines
are still printed; then it says how many of its processes were left).
Prints the script's exit status, its last lines, the changes to the
repository and the verdicts; exits non-zero if anything failed.
"""
import hashlib
import os
import resource
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SKIPPED = 77
DEADLINE = 270


def session(leader):
    """The live processes of the session that `leader` leads, whatever
    process groups they made (as `timeout` does)."""
    found = []
    for entry in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/stat" % entry) as stat:
                fields = stat.read().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if int(fields[3]) == leader and fields[0] != "Z":
            found.append(int(entry))
    return found


def run(command, cwd, env, log, deadline):
    """Runs `command` in a session of its own; returns its exit status and
    0, or None and the number of its processes still alive if it and all
    it started were stopped at the deadline (SIGTERM, then SIGKILL 5 s
    later)."""
    process = subprocess.Popen(command, cwd=cwd, env=env, stdout=log,
                               stderr=subprocess.STDOUT,
                               start_new_session=True)
    try:
        return process.wait(timeout=deadline), 0
    except subprocess.TimeoutExpired:
        for signal_ in (signal.SIGTERM, signal.SIGKILL):
            for pid in session(process.pid):
                try:
                    os.kill(pid, signal_)
                except ProcessLookupError:
                    pass
            for _ in range(50):
                if not session(process.pid):
                    break
                time.sleep(0.1)
        process.wait()
        return None, len(session(process.pid))


def snapshot(skip):
    """{path relative to ROOT: what it is} for everything under ROOT but
    the folders in `skip` and .git."""
    found = {}
    for folder, folders, files in os.walk(ROOT):
        kept = []
        for name in sorted(folders):
            path = os.path.join(folder, name)
            if name == ".git" and folder == ROOT or \
                    any(os.path.samefile(path, s) for s in skip
                        if os.path.exists(s)):
                continue
            if os.path.islink(path):
                found[os.path.relpath(path, ROOT)] = \
                    "link to " + os.readlink(path)
            else:
                found[os.path.relpath(path, ROOT)] = "folder"
                kept.append(name)
        folders[:] = kept
        for name in files:
            path = os.path.join(folder, name)
            if os.path.islink(path):
                what = "link to " + os.readlink(path)
            else:
                digest = hashlib.sha256()
                with open(path, "rb") as content:
                    for block in iter(lambda: content.read(1 << 20), b""):
                        digest.update(block)
                what = "sha256 " + digest.hexdigest()
            found[os.path.relpath(path, ROOT)] = what
    return found


def tracked(relative):
    """Whether `relative` (to ROOT) is a file of the repository: tracked by
    git, or, outside a git checkout, present and not in a folder the
    repository ignores (.gitignore: build/, output/)."""
    original = os.path.join(ROOT, relative)
    if not os.path.isfile(original):
        return False
    try:
        listed = subprocess.run(
            ["git", "-C", ROOT, "ls-files", "--error-unmatch", "--",
             relative], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            check=False).returncode == 0
        inside = subprocess.run(
            ["git", "-C", ROOT, "rev-parse", "--is-inside-work-tree"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            check=False).returncode == 0
    except OSError:
        inside = False
    if inside:
        return listed
    return relative.split(os.sep)[0] not in ("build", "output")


def main():
    arguments = sys.argv[1:]
    if "--" not in arguments or not arguments:
        sys.exit(__doc__)
    split = arguments.index("--")
    options, command = arguments[1:split], arguments[split + 1:]
    name = arguments[0]
    expected, said, needed, plain, deadline = [], [], [], False, DEADLINE
    while options:
        if options[0] == "--plain":
            plain = True
            options = options[1:]
            continue
        if options[0] == "--expect" and len(options) > 1:
            expected.append(options[1])
        elif options[0] == "--says" and len(options) > 1:
            said.append(options[1])
        elif options[0] == "--deadline" and len(options) > 1:
            deadline = float(options[1])
        elif options[0] == "--needs" and len(options) > 1:
            needed.append(options[1])
        else:
            sys.exit(__doc__)
        options = options[2:]
    missing = [tool for tool in needed if shutil.which(tool) is None]
    if missing:
        print("skipped: %s not installed (scripts/install-packages --test "
              "installs it; tests install nothing)" % ", ".join(missing))
        return SKIPPED

    work = os.path.join(os.getcwd(), "scripts", name)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    build = os.path.join(ROOT, "build")
    before = snapshot([build, os.getcwd()])
    env = dict(os.environ, SIGNORINI_SMOKE=work,
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_btl_vader_single_copy_mechanism="none")
    # As a user runs it: Python may cache bytecode unless the script says
    # not to.
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    if plain:
        del env["SIGNORINI_SMOKE"]
    start = time.monotonic()
    with open(os.path.join(work, "script.log"), "w") as log:
        status, left = run(command, work, env, log, deadline)
    seconds = time.monotonic() - start
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = usage.ru_utime + usage.ru_stime
    after = snapshot([build, os.getcwd()])

    failed = status != 0
    print("%s: %s after %.1f s (%.1f s CPU)" %
          (" ".join(os.path.relpath(c, ROOT) if c.startswith(ROOT) else c
                    for c in command),
           "stopped at the deadline (%d of its processes left)" % left
           if status is None else
           "exit status %d" % status, seconds, cpu))
    with open(os.path.join(work, "script.log"), errors="replace") as log:
        text = log.read()
        lines = text.splitlines()
    for line in lines[-15 if failed else -3:]:
        print("  | " + line)
    changes = sorted(set(before) | set(after))
    changes = [p for p in changes if before.get(p) != after.get(p)]
    # A file of the user's that the repository does not track and that was
    # there before and after (a log the user is writing while the suite
    # runs, `scripts/test > test.log`) may change: the script did not
    # write it. Files the repository tracks, and files that appeared or
    # went, count.
    changes = [p for p in changes
               if p not in before or p not in after or
               not before[p].startswith("sha256") or tracked(p)]
    for path in changes:
        print("CHANGED: %s: %s -> %s" % (path, before.get(path, "absent"),
                                          after.get(path, "absent")))
    print("repository outside build/: %d entries, %s" %
          (len(before), "unchanged" if not changes else
           "%d changed" % len(changes)))
    failed |= bool(changes)
    for relative in expected:
        path = os.path.join(work, relative)
        original = os.path.join(ROOT, relative)
        written = os.path.isfile(path) and not os.path.islink(path) and \
            os.path.getsize(path) > 0
        # A rewritten copy of a repository file differs from it: the
        # script wrote its own results there. Only files the repository
        # tracks are copied (README.md, doc/): a file of the user's own
        # runs (output/, which git ignores) may hold what the script wrote,
        # byte for byte, when the user ran the same scene before.
        if written and tracked(relative):
            with open(path, "rb") as a, open(original, "rb") as b:
                written = a.read() != b.read()
        print("written: %s: %s" % (relative, "yes" if written else "NO"))
        failed |= not written
    for words in said:
        print("says: %s: %s" % (words, "yes" if words in text else "NO"))
        failed |= words not in text
    print("FAILED" if failed else "PASSED")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
