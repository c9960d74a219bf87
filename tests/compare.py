#!/usr/bin/env python3
"""Compares a test's output with its reference: compare.py REFERENCE OUTPUT.

The comparison of every test here (the .prm cases, tests/unit, the scripted
tests): deal.II's test rules call it in place of numdiff and pass numdiff's
options (`-a 1e-6 -r 1e-8 -s SEPARATORS`), which are ignored: the rules are
these. Lines are compared one by one, split into words at
` \\t\\r\\n=,:;<>[](){}^` as deal.II splits them.

- Text must be equal, and so must every integer (counts of cells, dofs,
  iterations, active nodes; exit statuses).
- Every other number must agree to a relative 1e-8,
  |x - y| <= 1e-8 max(|x|, |y|): a force, an energy, a displacement, a
  pressure, whatever its size. No number has an absolute tolerance of its
  own; where a quantity is round-off (a support's force along an unloaded
  axis, the equilibrium mismatch, the penetration of an active node, a
  probe's displacement on a symmetry plane) it is compared on the scale of
  its kind instead, as round_off_bounds() states: it may differ by 1e-8 of
  the largest force (or of 1 N), of the largest displacement (or 1e-6), of
  the largest pressure or force the reference prints, by 1e-8 if it is
  dimensionless (a mismatch, a relative error). Round-off is 1e-16 to 1e-9
  of those scales, a physically meaningful change 1e-8 or more.
- energy_error, sqrt(|J(u_h) - J(u)| / |J(u)|), is compared squared, to
  1e-8 like the energy J itself: its square root turns the energies'
  round-off (1e-15) into 3e-8 for an exact solution.
- What single precision computes agrees to a relative 1e-5: it differs
  between processors (AVX2, AVX-512: other copies of the kernels, other
  order of the sums) from its seventh digit: the residual of one cycle of
  the multigrid (floats) in a remedy line, the Kelly estimate (float
  indicators; it may also differ by 1e-10 of the force scale, where it is
  round-off).
- The Newton residual of an iteration ("iteration 2: residual 8.709e-05")
  agrees within a factor of 10 (or by 1e-8 of the force scale): the step
  before it is solved only to the Newton tolerance (1e-4) by CG with a
  single-precision multigrid, so its first digit is all that is known, and
  the CG iterations of that multigrid ("multigrid CG: 5 iterations") may
  differ by one. The converged results are compared as above.
- A unit test's checked difference ("WHAT: 1.5e-16  (ok)") carries its
  verdict, compared as text, and may differ by 1e-9 (relative 1e-8 above).
- A test whose quantities carry less than 1e-8 (an ill-conditioned system
  solved iteratively) says so in NAME.tolerance beside its reference
  (`relative VALUE`, and why): that relative tolerance replaces 1e-8.

Verdicts (PASS, FAIL, yes, (ok), (FAILED)) are text: a violated bound fails
however small it is. Exit status 0 if the files agree, 1 if not (the
differences are printed), 2 on a usage error. `compare.py -v` prints the
version (deal.II's test setup asks).
"""
import math
import os
import re
import sys

RELATIVE = 1e-8
SINGLE_PRECISION = 1e-5
SEPARATORS = re.compile(r"([ \t\r\n=,:;<>\[\](){}^]+)")
NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")
INTEGER = re.compile(r"^[-+]?\d+$")
# The words of a label, then optionally " = (" and the numbers before this
# one inside the parentheses: "supports (1 2", "u = (1".
VECTOR = r"(\s*=?\s*\(?[-+.\deE ]*)?$"

NEVER = r"(?!)"

# Kinds of numbers, by the label before them on their line (a regular
# expression that the line up to the number, without the separators at its
# end, must match) or by their column in a statistics.csv table.
KINDS = [
    # kind, label on a line, statistics.csv column
    ("single", r"geometric multigrid\).*\bresidual$", NEVER),
    ("estimate", NEVER, r"estimated_error"),
    ("residual", r"iteration\s+\d+: residual$", NEVER),
    ("count", r"multigrid CG$", NEVER),
    ("force", r"(load|supports|integrated pressure|force)" + VECTOR,
     r"(contact_force|support_reaction|force)\d*_[xyz]"),
    ("displacement", r"(\bu|penetration)" + VECTOR,
     r"probe\d+_u[xyz]|max_penetration|displacement\d+_[xyz]"),
    ("pressure", r"max pressure$", r"max_pressure\d*|max_shear"),
    ("dimensionless",
     r"(relative mismatch|pressure error|width error|shear error"
     r"|relative difference)$",
     r"equilibrium_error|max_pressure_error|contact_width_error"
     r"|stick_width_error|max_shear_error|pressure_error"),
    ("energy error", r"energy error$", r"energy_error"),
]


def round_off_bounds(largest):
    """{kind: the absolute difference allowed} from {kind: the largest
    number of that kind in the reference}: 1e-8 of the scale of the kind.
    A force's scale is the largest force, or 1 if that is smaller (nothing
    loaded: the program's own scale of the equilibrium mismatch then); a
    displacement's the largest displacement or penetration, at least 1e-6;
    a pressure's the largest pressure or force, at least 1; that of a
    dimensionless error, or of the squared energy error, 1. A Kelly
    estimate may differ by 1e-10 of the force scale (it is round-off where
    the solution is exact), a unit test's checked difference by 1e-9."""
    force = max(largest.get("force", 0.), 1.)
    return {
        "force": RELATIVE * force,
        "residual": RELATIVE * force,
        "displacement": RELATIVE * max(largest.get("displacement", 0.), 1e-6),
        "pressure": RELATIVE * max(largest.get("pressure", 0.), force),
        "dimensionless": RELATIVE,
        "energy error": RELATIVE,  # on the squares (see agree())
        "estimate": 1e-10 * force,
        "checked": 1e-9,
        "single": 0.,
    }


SEPARATOR_CHARACTERS = " \t\r\n=,:;<>[](){}^"
# A unit test's checked difference: "  WHAT: DIFFERENCE  (ok)" (checks.h).
CHECKED = re.compile(r"\((ok|FAILED)\)\s*$")


def words(line):
    """[(word, text of the line before it)] of a line."""
    found, position = [], 0
    for piece in SEPARATORS.split(line):
        if piece and not SEPARATORS.fullmatch(piece):
            found.append((piece, line[:position]))
        position += len(piece)
    return found


def tables(lines):
    """{line index: [column of each word]} for the rows of every
    statistics.csv table (a header `cycle,...`, then rows of as many
    fields)."""
    columns, header = {}, None
    for index, line in enumerate(lines):
        fields = line.rstrip("\n").split(",")
        if fields[0] == "cycle" and len(fields) > 2:
            header = fields
        elif header and len(fields) == len(header):
            columns[index] = [name for name, field in zip(header, fields)
                              for _ in words(field)]
        else:
            header = None
    return columns


def kind_of(before, column, line):
    """The kind of a number: that of its column or of its label, "single"
    for a single-precision number, or None."""
    if column is not None:
        for kind, _, by_column in KINDS:
            if re.fullmatch(by_column, column):
                return kind
        return None
    if CHECKED.search(line):
        return "checked"
    label = before.rstrip(SEPARATOR_CHARACTERS)
    for kind, by_label, _ in KINDS:
        if re.search(by_label, label):
            return kind
    return None


def numbers(lines):
    """[(line index, word index, word, kind)] of every number."""
    columns = tables(lines)
    found = []
    for index, line in enumerate(lines):
        row = columns.get(index)
        for position, (word, before) in enumerate(words(line.rstrip("\n"))):
            if NUMBER.match(word):
                column = row[position] if row and position < len(row) \
                    else None
                found.append((index, position, word,
                              kind_of(before, column, line)))
    return found


def scales(lines):
    """{kind: its round-off bound} from the reference."""
    largest = {}
    for _, _, word, kind in numbers(lines):
        if kind:
            largest[kind] = max(largest.get(kind, 0.), abs(float(word)))
    return round_off_bounds(largest)


def agree(x, y, kind, bounds):
    """Whether two numbers (words) agree, and the tolerance used."""
    if INTEGER.match(x) and INTEGER.match(y):
        if kind == "count":
            return abs(int(x) - int(y)) <= 1, "equal or one apart"
        return int(x) == int(y), "equal"
    a, b = float(x), float(y)
    if not (math.isfinite(a) and math.isfinite(b)):
        return x == y, "equal"
    relative = SINGLE_PRECISION if kind in ("single", "estimate") \
        else RELATIVE
    bound = bounds.get(kind, 0.) if kind else 0.
    # energy_error = sqrt(|J(u_h) - J(u)| / |J(u)|): the energy to a
    # relative 1e-8 is its square to an absolute 1e-8.
    off = abs(a * a - b * b) if kind == "energy error" else abs(a - b)
    ok = abs(a - b) <= relative * max(abs(a), abs(b)) or off <= bound
    if kind == "residual":
        ok = off <= bound or (a * b > 0 and abs(math.log10(a / b)) <= 1)
        return ok, "within a factor of 10 or absolute %.1e (%s)" % (bound,
                                                                      kind)
    what = "relative %g" % relative
    if bound:
        what += " or absolute %.1e (%s%s)" % (
            bound, kind, ", squared" if kind == "energy error" else "")
    return ok, what


def exception_for(path):
    """The relative tolerance that NAME.tolerance, beside the reference
    NAME[.VARIANT].output, sets for the test's numbers (a line `relative
    VALUE`, with comments saying why), or None."""
    folder, name = os.path.split(path)
    try:
        with open(os.path.join(folder, name.split(".")[0] + ".tolerance")) \
                as lines:
            for line in lines:
                words_ = line.split("#")[0].split()
                if len(words_) == 2 and words_[0] == "relative":
                    return float(words_[1])
    except OSError:
        pass
    return None


def compare(reference, output, relative=None):
    """The differences (lines of text) between two lists of lines; with
    `relative`, that is the relative tolerance instead of 1e-8 (where it
    is 1e-8)."""
    global RELATIVE
    if relative is not None:
        RELATIVE = relative
    found = []
    if len(reference) != len(output):
        found.append("%d lines expected, %d written" %
                     (len(reference), len(output)))
    bounds = scales(reference)
    kinds = {(i, p): kind for i, p, _, kind in numbers(reference)}
    for index, (expected, written) in enumerate(zip(reference, output)):
        a, b = words(expected.rstrip("\n")), words(written.rstrip("\n"))
        problems = []
        if len(a) != len(b):
            problems.append("%d words expected, %d written" %
                            (len(a), len(b)))
        for position, ((x, _), (y, _)) in enumerate(zip(a, b)):
            if NUMBER.match(x) and NUMBER.match(y):
                ok, what = agree(x, y, kinds.get((index, position)), bounds)
                if not ok:
                    problems.append("%s -> %s (%s)" % (x, y, what))
            elif x != y:
                problems.append("'%s' -> '%s'" % (x, y))
        if problems:
            found.append("line %d:\n  expected: %s\n  written:  %s\n  %s" % (
                index + 1, expected.rstrip("\n"), written.rstrip("\n"),
                "; ".join(problems)))
        if len(found) >= 20:
            break
    if not found and len(reference) != len(output):
        longer = reference if len(reference) > len(output) else output
        found.append("first extra line: " +
                     longer[min(len(reference), len(output))].rstrip("\n"))
    return found


def main(arguments):
    if arguments[:1] in (["-v"], ["--version"]):
        print("compare.py 1 (tests/compare.py of signorini)")
        return 0
    files = []
    skip = False
    for index, argument in enumerate(arguments):
        if skip:
            skip = False
        elif argument in ("-a", "-r", "-s"):
            skip = True
        elif argument == "--":
            files += arguments[index + 1:]
            break
        elif not argument.startswith("-") or argument == "-":
            files.append(argument)
    if len(files) != 2:
        sys.stderr.write(__doc__)
        return 2
    with open(files[0], errors="replace") as one, \
            open(files[1], errors="replace") as two:
        reference, output = one.readlines(), two.readlines()
    differences = compare(reference, output, exception_for(files[0]))
    for difference in differences:
        print(difference)
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
