#!/usr/bin/env python3
"""Checks doc/architecture.md against the tree as it is when the test runs.

    architecture.py files      every file under include/ and source/ is named
                               in the file map, and every entry of the map's
                               first column exists
    architecture.py includes   no #include <signorini/...> runs upward
                               against the page's "Dependency order"

Prints one line per finding (the file and what is wrong) and a last line
that the test's .output expects when nothing is wrong; exits 1 on a finding.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
PAGE = os.path.join(ROOT, "doc", "architecture.md")
# Where the sources are, and the prefix of their paths in the map.
FOLDERS = (("include", os.path.join("include", "signorini")),
           ("source", "source"))
EXTENSIONS = (".h", ".cc")


def section(text, title):
    """The text of the section `## title` of the page, up to the next one
    of its level."""
    match = re.search(r"^## %s[ \t]*\n(.*?)(?=^## |\Z)" % re.escape(title),
                      text, re.S | re.M)
    if not match:
        sys.exit("doc/architecture.md has no section '## %s'" % title)
    return match.group(1)


def sources():
    """(path from the repository, path below include/signorini/ or source/)
    of every .h and .cc file, sorted."""
    found = []
    for _, top in FOLDERS:
        base = os.path.join(ROOT, top)
        for folder, folders, files in os.walk(base):
            folders.sort()
            for name in sorted(files):
                if name.endswith(EXTENSIONS):
                    path = os.path.join(folder, name)
                    found.append((os.path.relpath(path, ROOT),
                                  os.path.relpath(path, base)))
    return sorted(found)


def check_files(text):
    """Files not named in the file map, and map entries that do not exist."""
    table = section(text, "File map")
    named = set(re.findall(r"`([^`\s]+)`", table))
    findings, missing = [], {}
    for path, relative in sources():
        stem = os.path.splitext(relative)[0]
        names = {path, relative, stem, os.path.basename(relative)}
        if not names & named:
            missing.setdefault(stem, []).append(path)
    for stem, paths in sorted(missing.items()):
        findings.append("not named in the file map of doc/architecture.md: "
                        "%s (name it as `%s`)" % (", ".join(paths), stem))
    for entry in re.findall(r"^\|\s*`([^`]+)`\s*\|", table, re.M):
        stem = os.path.splitext(entry)[0]
        candidates = [os.path.join(ROOT, top, stem + extension)
                      for _, top in FOLDERS for extension in EXTENSIONS]
        candidates += [os.path.join(ROOT, top, entry) for _, top in FOLDERS]
        if not any(os.path.isfile(c) for c in candidates):
            findings.append("named in the file map of doc/architecture.md but "
                            "not in the tree: %s" % entry)
    for line in findings:
        print(line)
    print("file map of doc/architecture.md: %s" %
          ("%d finding(s)" % len(findings) if findings else
           "every file under include/ and source/ named, every entry there"))
    return findings


def folder_of(relative):
    """The folder of a path below include/signorini/ or source/ ('' for
    the top level)."""
    parts = relative.split(os.sep)
    return parts[0] if len(parts) > 1 else ""


def check_includes(text):
    """Includes from a folder below the including file's own."""
    order = re.findall(r"^\d+\.\s+`([a-z_0-9]+)/`", section(
        text, "Dependency order"), re.M)
    if not order:
        sys.exit("doc/architecture.md: its Dependency order lists no folders "
                 "(lines '1. `base/`')")
    rank = {folder: i for i, folder in enumerate(order)}
    rank[""] = len(order)  # the top level: program, main.cc
    findings = []
    unlisted = set()
    include = re.compile(r"^\s*#\s*include\s*[<\"]signorini/([^>\"]+)[>\"]")
    for path, relative in sources():
        own = folder_of(relative)
        if own not in rank:
            unlisted.add(own)
            continue
        with open(os.path.join(ROOT, path), errors="replace") as source:
            for number, line in enumerate(source, 1):
                match = include.match(line)
                if not match:
                    continue
                target = folder_of(match.group(1).replace("/", os.sep))
                if target not in rank:
                    unlisted.add(target)
                elif rank[target] > rank[own]:
                    findings.append("upward: %s:%d (%s) includes %s (%s)" % (
                        path, number, own, match.group(1), target))
    for folder in sorted(unlisted):
        findings.append("not in the Dependency order of doc/architecture.md: "
                        "the folder %s/" % folder)
    for line in findings:
        print(line)
    if findings:
        print("the Dependency order of doc/architecture.md (a folder includes "
              "only from itself and those before it): "
              + ", ".join(order) + ", the top level")
    print("includes against the Dependency order of doc/architecture.md: %s"
          % ("%d finding(s)" % len(findings) if findings else "none upward"))
    return findings


def main():
    if len(sys.argv) != 2 or sys.argv[1] not in ("files", "includes"):
        sys.exit(__doc__)
    with open(PAGE) as page:
        text = page.read()
    check = check_files if sys.argv[1] == "files" else check_includes
    return 1 if check(text) else 0


if __name__ == "__main__":
    sys.exit(main())
