#!/usr/bin/env python3
"""Reruns the accuracy study of doc/validation.md and regenerates its tables
(between the <!-- begin NAME --> and <!-- end NAME --> markers) and charts
(doc/*.png) from the program's own output.

    scripts/validation             the study, about three minutes
    scripts/validation --overkill  also recomputes the cantilever's reference
                                   energy (14 Kelly cycles, 4 GB, ~5 minutes)

Runs go to build/validation/. Needs gnuplot and gmsh (installed if missing).

For the test suite only: with SIGNORINI_SMOKE=FOLDER (see scripts/common.py)
every run has at most two cycles, the study runs on its coarsest mesh only
with one penalty, and the tables and charts are written to copies in
FOLDER/doc/.
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from common import DOC, SMOKE, gnuplot, replace_sections, table  # noqa: E402

WORK = common.work_folder("validation")
# Where the charts and doc/validation.md are written.
DOC_OUT = os.path.dirname(common.output_file("doc/validation.md"))

# The default scene's potential energy J(u) [N mm per mm], extrapolated from
# an overkill run: `scripts/validation --overkill` prints how it is made.
REFERENCE_ENERGY = -6.8812213

# Hertz closed form for prm/hertz_cylinder.prm (R = 1, E = 1000, nu = 0.3,
# F = 10): contact half-width a and peak pressure p0.
HERTZ_A = 2 * math.sqrt(10 * 1 * (1 - 0.3**2) / (math.pi * 1000))
HERTZ_P0 = 2 * 10 / (math.pi * HERTZ_A)


def run(name, base, settings):
    """The rows of statistics.csv of `base` run with `settings`."""
    return common.run(WORK, name, base, settings).rows


def slope(rows, column, first=0):
    """Least-squares slope of log(column) against log(dofs) (over all rows
    if fewer than two are from cycle `first` on)."""
    if sum(r["cycle"] >= first for r in rows) < 2:
        first = 0
    points = [(math.log(r["dofs"]), math.log(abs(r[column])))
              for r in rows if r["cycle"] >= first]
    n = len(points)
    sx = sum(x for x, _ in points)
    sy = sum(y for _, y in points)
    sxx = sum(x * x for x, _ in points)
    sxy = sum(x * y for x, y in points)
    return (n * sxy - sx * sy) / (n * sxx - sx * sx)


def write_data(name, rows, columns):
    return common.write_data(WORK, name, rows, columns)


def hertz():
    kelly = run("hertz_kelly", "prm/hertz_cylinder.prm",
                {"Mesh refinement": {"Number of cycles": "10"}})
    uniform = run("hertz_global", "prm/hertz_cylinder.prm",
                  {"Mesh refinement": {"Strategy": "global",
                                       "Number of cycles": "5"},
                   "Output": {"Contact pressure table": "false"}})
    columns = ["dofs", "max_pressure_error", "contact_width_error",
               "pressure_error"]
    k = write_data("hertz_kelly", kelly, columns)
    g = write_data("hertz_global", uniform, columns)
    gnuplot("""
set terminal pngcairo size 800,560 font ',11'
set output '%s/hertz-convergence.png'
set logscale xy
set format y '10^{%%L}'
set xlabel 'degrees of freedom'
set ylabel 'relative error'
set title 'Hertz half-disk against the closed form'
set key bottom left
set grid
plot '%s' u 1:4 w lp lw 2 pt 7 lc 1 t 'pressure profile (L2), Kelly', \\
     '%s' u 1:4 w lp lw 2 pt 6 lc 1 dt 2 t 'pressure profile (L2), global', \\
     '%s' u 1:2 w lp lw 2 pt 5 lc 2 t 'peak pressure p0, Kelly', \\
     '%s' u 1:2 w lp lw 2 pt 4 lc 2 dt 2 t 'peak pressure p0, global', \\
     '%s' u 1:3 w lp lw 2 pt 9 lc 3 t 'half-width a, Kelly', \\
     '%s' u 1:3 w lp lw 2 pt 8 lc 3 dt 2 t 'half-width a, global'
""" % (DOC_OUT, k, g, k, g, k, g))
    last = int(kelly[-1]["cycle"])
    profile = os.path.join(WORK, "hertz_kelly",
                           "contact_pressure-%02d.csv" % last)
    gnuplot("""
set terminal pngcairo size 800,480 font ',11'
set output '%s/hertz-pressure.png'
set datafile separator ','
set xlabel 'x [mm]'
set ylabel 'contact pressure [MPa]'
set title 'Hertz half-disk, cycle %d (%d dofs)'
set grid
set xrange [0:0.15]
set yrange [0:65]
a = %.10g; p0 = %.10g
p(x) = abs(x) < a ? p0 * sqrt(1 - x**2 / a**2) : 0
set samples 1000
plot p(x) w l lw 2 lc rgb 'black' t 'closed form', \\
     '%s' every ::1 u 1:3 w p pt 7 ps 0.8 lc 1 t 'signorini, nodal pressure'
""" % (DOC_OUT, last, kelly[-1]["dofs"], HERTZ_A, HERTZ_P0, profile))

    def rows_of(rows, strategy):
        return [[strategy, "%d" % r["cycle"], "%d" % r["dofs"],
                 "%.2f" % r["max_pressure"], "%.2f %%" % (100 * r["max_pressure_error"]),
                 "%.4f" % r["contact_width"], "%.2f %%" % (100 * r["contact_width_error"]),
                 "%.2f %%" % (100 * r["pressure_error"]),
                 "%.0e" % r["equilibrium_error"]] for r in rows]
    return table(["refinement", "cycle", "dofs", "p0 [MPa]", "p0 error",
                  "a [mm]", "a error", "profile L2 error", "equilibrium"],
                 rows_of(kelly, "Kelly") + rows_of(uniform, "global"))


def energy():
    reference = {"Reference": {"Energy": "%.8f" % REFERENCE_ENERGY},
                 "Output": {"Probe points": ""}}
    kelly = run("cantilever_kelly", "prm/cantilever_on_plane.prm",
                dict(reference, **{"Mesh refinement": {"Number of cycles": "11"}}))
    uniform = run("cantilever_global", "prm/cantilever_on_plane.prm",
                  dict(reference, **{"Mesh refinement": {"Strategy": "global",
                                                         "Number of cycles": "6"}}))
    columns = ["dofs", "energy_error"]
    k = write_data("cantilever_kelly", kelly, columns)
    g = write_data("cantilever_global", uniform, columns)
    rates = {"Kelly": slope(kelly, "energy_error", 4),
             "global": slope(uniform, "energy_error", 3)}
    gnuplot("""
set terminal pngcairo size 800,560 font ',11'
set output '%s/energy-convergence.png'
set logscale xy
set format y '10^{%%L}'
set xlabel 'degrees of freedom N'
set ylabel 'relative energy-norm error'
set title 'Cantilever on the plane: error against the overkill energy'
set key bottom left
set grid
plot '%s' u 1:2 w lp lw 2 pt 7 lc 1 t 'Kelly (rate %.2f)', \\
     '%s' u 1:2 w lp lw 2 pt 6 lc 2 t 'global (rate %.2f)', \\
     [1e3:1e6] 1.3 * x**-0.5 w l dt 2 lc rgb 'gray' t 'N^{-1/2}'
""" % (DOC_OUT, k, rates["Kelly"], g, rates["global"]))
    rows = []
    for strategy, data in (("Kelly", kelly), ("global", uniform)):
        for r in data:
            rows.append([strategy, "%d" % r["cycle"], "%d" % r["dofs"],
                         "%.9f" % r["energy"], "%.3e" % r["energy_error"],
                         "%d" % r["iterations"], "%.0e" % r["equilibrium_error"]])
    text = table(["refinement", "cycle", "dofs", "energy J(u_h)",
                  "energy-norm error", "iterations", "equilibrium"], rows)
    text += ("\nObserved rates (least-squares slope of log error against log "
             "N): **Kelly %.2f** (cycles 4 to %d), **global %.2f** (cycles 3 "
             "to %d); over all cycles, Kelly %.2f and global %.2f.\n" %
             (rates["Kelly"], kelly[-1]["cycle"], rates["global"],
              uniform[-1]["cycle"], slope(kelly, "energy_error"),
              slope(uniform, "energy_error")))
    return text


def cattaneo_mindlin():
    """prm/cattaneo_mindlin.prm at nu = 0.4999 and 0.3: the stick zone, the
    contact width and the peak shear against Cattaneo's closed form for the
    computed normal force P, per cycle's last step; and the shear traction
    profile of the last cycle."""
    runs = {"0.4999": run("cattaneo_mindlin", "prm/cattaneo_mindlin.prm", {}),
            "0.3": run("cattaneo_mindlin_nu03", "prm/cattaneo_mindlin.prm",
                       {"Material": {"Poisson's ratio": "0.3"},
                        "Reference": {"Function constants": "",
                                      "Contact pressure": "",
                                      "Maximum pressure": "",
                                      "Contact width": "", "Stick width": "",
                                      "Maximum shear": ""}})}
    radius, young, mu = 10., 1000., 0.3
    rows = []
    for nu, data in runs.items():
        for r in data:
            if r["step"] != 2:
                continue
            force, shear = abs(r["contact_force_y"]), abs(r["contact_force_x"])
            a = 2 * math.sqrt(force * radius * (1 - float(nu)**2) /
                              (math.pi * young))
            p0 = 2 * force / (math.pi * a)
            ratio = math.sqrt(max(0., 1 - shear / (mu * force)))
            peak = mu * p0 * math.sqrt(min(1., shear / (mu * force)))
            c_a = (r["stick_width"] / r["contact_width"]
                   if r["contact_width"] > 0 else 0.)
            rows.append([nu, "%d" % r["cycle"], "%d" % r["dofs"],
                         "%.4f" % force, "%.4f" % c_a, "%.4f" % ratio,
                         "%+.2f %%" % (100 * (c_a / ratio - 1)),
                         "%+.2f %%" % (100 * (r["contact_width"] / (2 * a) - 1)),
                         "%+.2f %%" % (100 * (r["max_shear"] / peak - 1)),
                         "%d" % r["iterations"]])
    data = runs["0.4999"]
    last = data[-1]
    force = abs(last["contact_force_y"])
    shear = abs(last["contact_force_x"])
    a = 2 * math.sqrt(force * radius * (1 - 0.4999**2) / (math.pi * young))
    profile = os.path.join(WORK, "cattaneo_mindlin",
                           "contact_pressure-%02d.csv" % last["cycle"])
    gnuplot("""
set terminal pngcairo size 800,480 font ',11'
set output '%s/cattaneo_mindlin-traction.png'
set datafile separator ','
set xlabel 'x [mm]'
set ylabel 'traction [MPa]'
set title 'Cattaneo-Mindlin, nu = 0.4999, cycle %d (%d dofs): shear q and mu p'
set grid
set key top left
set xrange [-1.3*%.10g:1.3*%.10g]
a = %.10g; mu = %.10g; p0 = 2 * %.10g / (pi * a)
c = a * sqrt(1 - %.10g / (mu * %.10g))
p(x) = abs(x) < a ? p0 * sqrt(1 - x**2 / a**2) : 0
q(x) = abs(x) < c ? mu * (p(x) - p0 * (c / a) * sqrt(1 - x**2 / c**2)) : mu * p(x)
set samples 2000
plot mu * p(x) w l lw 2 lc rgb 'gray' t 'mu p, closed form', \
     q(x) w l lw 2 lc rgb 'black' t 'q, Cattaneo', \
     '%s' every ::1 u 1:($6 == 2 ? abs($11) : 1/0) w p pt 7 ps 0.6 lc 1 t 'q, sticking nodes', \
     '%s' every ::1 u 1:($6 == 3 ? abs($11) : 1/0) w p pt 5 ps 0.6 lc 2 t 'q, slipping nodes'
""" % (DOC_OUT, last["cycle"], last["dofs"], a, a, a, mu, force, shear,
       force, profile, profile))
    return table(["nu", "cycle", "dofs", "P [N/mm]", "c/a", "Cattaneo",
                  "c/a error", "a error", "peak shear error", "iterations"],
                 rows)


def spence():
    """prm/spence_sphere_axisymmetric.prm: the stick radius over the load
    steps of the last cycle against Spence's kappa a, and the shear and mu p
    of the last step's contact nodes."""
    kappa, mu = 0.90, 0.3
    data = run("spence_sphere_axisymmetric",
               "prm/spence_sphere_axisymmetric.prm", {})
    last_cycle = data[-1]["cycle"]
    steps = [r for r in data if r["cycle"] == last_cycle]
    # The cell at the final contact edge, from the last step's nodes.
    profile = os.path.join(WORK, "spence_sphere_axisymmetric",
                           "contact_pressure-%02d.csv" % last_cycle)
    with open(profile) as table_file:
        radii = sorted(float(line.split(",")[0])
                       for line in table_file.readlines()[1:])
    a_end = steps[-1]["contact_width"]
    cell = min((r2 - r1 for r1, r2 in zip(radii, radii[1:])
                if r1 < a_end and r2 > 0.5 * a_end), default=float("nan"))
    rows = []
    for r in steps:
        if r["step"] % 10 and r["step"] not in (1, 2, 5) and r is not steps[-1]:
            continue
        a = r["contact_width"]
        c = r["stick_width"]
        rows.append(["%d" % r["step"], "%.4f" % a, "%.4f" % c,
                     "%.3f" % (c / a if a > 0 else 0.),
                     "%+.2f" % ((c - kappa * a) / cell),
                     "%d" % r["iterations"]])
    series = write_data("spence_steps", steps, ["step", "contact_width",
                                                "stick_width"])
    gnuplot("""
set terminal pngcairo size 1100,440 font ',11'
set output '%s/spence_sphere-stick.png'
set datafile separator whitespace
set multiplot layout 1,2 title "Spence's frictional indentation (mu = 0.3, nu = 0.3), cycle %d (%d dofs)"
set xlabel 'load step (a grows by 4 %% a step)'
set ylabel 'stick radius c / contact radius a'
set yrange [0:1.05]
set grid
set key bottom right
plot %.3f w l lw 2 lc rgb 'black' t 'Spence: kappa = %.2f', \
     '%s' u 1:($2 > 0 ? $3 / $2 : 1/0) w lp pt 7 ps 0.6 lc 1 t 'c / a'
set datafile separator ','
set xlabel 'r [mm]'
set ylabel 'traction [MPa]'
set yrange [*:*]
set key top right
set xrange [0:1.3 * %.10g]
plot '%s' every ::1 u 1:($6 >= 2 ? %.3f * abs($3) : 1/0) w l lw 2 lc rgb 'gray' t 'mu p', \
     '%s' every ::1 u 1:($6 == 2 ? abs($11) : 1/0) w p pt 7 ps 0.6 lc 1 t 'shear, sticking nodes', \
     '%s' every ::1 u 1:($6 == 3 ? abs($11) : 1/0) w p pt 5 ps 0.6 lc 2 t 'shear, slipping nodes'
unset multiplot
""" % (DOC_OUT, last_cycle, steps[-1]["dofs"], kappa, kappa, series, a_end,
       profile, mu, profile, profile))
    return table(["step", "a [mm]", "c [mm]", "c/a", "(c - 0.90 a) / cell",
                  "iterations"], rows)


def study_mesh(triangles, nx, ny):
    mesh = os.path.join(WORK, "beam-%d.msh" % triangles)
    if not os.path.exists(mesh):
        subprocess.run(["gmsh", "-2", "-setnumber", "nx", str(nx),
                        "-setnumber", "ny", str(ny),
                        os.path.join(DOC, "validation", "beam.geo"),
                        "-o", mesh], check=True, stdout=subprocess.DEVNULL)
    return mesh


def study(example):
    if example == 1:
        base, probe, gap = "prm/cantilever_on_plane.prm", "10, 0", 0.15
        meshes = {640: (40, 8), 2560: (80, 16), 10240: (160, 32)}
        bc = {"Dirichlet": "1: all", "Traction boundary ids": "2"}
        penalties = {2560: ["16e-3", "32e-3", "64e-3"],
                     10240: ["16e-3", "32e-3", "64e-3"]}
    else:
        base, probe, gap = "prm/clamped_beam_on_plane.prm", "5, 0", 0.05
        meshes = {496: (62, 4), 1984: (124, 8), 7936: (248, 16)}
        bc = {"Dirichlet": "1: all; 2: all", "Traction boundary ids": "4"}
        penalties = {496: ["4e-3", "6e-3", "8e-3"],
                     1984: ["4e-3", "6e-3", "8e-3"],
                     7936: ["4e-3", "6e-3", "8e-3", "16e-3", "32e-3", "64e-3"]}
    if SMOKE:
        meshes = dict(list(meshes.items())[:1])
        penalties = {t: e[:1] for t, e in penalties.items()}
    results = {}
    for triangles, (nx, ny) in meshes.items():
        common = {"Geometry": {"Type": "gmsh", "Initial refinement": "0",
                               "Mesh file": study_mesh(triangles, nx, ny)},
                  "Boundary conditions": bc,
                  "Obstacle": {"Contact boundary ids": "3"},
                  "Mesh refinement": {"Number of cycles": "1"},
                  "Output": {"Probe points": probe}}
        methods = [("none", "none", {}), ("active set", "active set", {})]
        methods += [("penalty " + e, "penalty", {"Penalty parameter": e})
                    for e in penalties.get(triangles, [])]
        for label, method, extra in methods:
            settings = dict(common)
            settings["Contact"] = dict({"Method": method}, **extra)
            name = "example%d_%d_%s" % (example, triangles,
                                        label.replace(" ", "_"))
            row = run(name, base, settings)[-1]
            results[(triangles, label)] = row
    return results, list(meshes), gap


def study_tables():
    text = {}
    for example, study_none, study_penalty in (
            (1, {640: -0.8385, 2560: -0.8681, 10240: -0.8762},
             {("16e-3", 2560): (-0.1769, 0.026941), ("32e-3", 2560): (-0.1885, 0.038512),
              ("64e-3", 2560): (-0.2047, 0.054710), ("16e-3", 10240): (-0.1637, 0.013708),
              ("32e-3", 10240): (-0.1696, 0.019623), ("64e-3", 10240): (-0.1780, 0.028012)}),
            (2, {496: -0.3927, 1984: -0.4102, 7936: -0.4154},
             {("4e-3", 496): (-0.081207, 0.031207), ("6e-3", 496): (-0.088342, 0.038342),
              ("8e-3", 496): (-0.094257, 0.044257), ("4e-3", 1984): (-0.065801, 0.015801),
              ("6e-3", 1984): (-0.069519, 0.046519), ("8e-3", 1984): (-0.072679, 0.022679),
              ("4e-3", 7936): (-0.057935, 0.007935), ("6e-3", 7936): (-0.059734, 0.009734),
              ("8e-3", 7936): (-0.061269, 0.011269), ("16e-3", 7936): (-0.066098, 0.016098),
              ("32e-3", 7936): (-0.073089, 0.023089), ("64e-3", 7936): (-0.083015, 0.033015)})):
        results, meshes, gap = study(example)
        uy = "probe0_uy"
        rows = [["%d" % t, "%.4f" % study_none[t], "%.4f" % results[(t, "none")][uy]]
                for t in meshes]
        text["example%d-free" % example] = table(
            ["triangles", "study u_y(A)", "signorini u_y(A)"], rows)
        rows = []
        for (epsilon, t), (study_uy, study_pen) in study_penalty.items():
            if (t, "penalty " + epsilon) not in results:
                continue  # smoke mode: a mesh not run
            ours = results[(t, "penalty " + epsilon)]
            rows.append([epsilon, "%d" % t, "%.4f" % study_uy, "%.4f" % study_pen,
                         "%.4f" % ours[uy], "%.4f" % ours["max_penetration"],
                         "%d" % ours["iterations"]])
        for t in meshes:
            ours = results[(t, "active set")]
            rows.append(["active set", "%d" % t, "", "", "%.4f" % ours[uy],
                         "%.0e" % ours["max_penetration"], "%d" % ours["iterations"]])
        text["example%d-contact" % example] = table(
            ["method, ε [mm/MPa]", "triangles", "study u_y(A)", "study penetration",
             "signorini u_y(A)", "signorini penetration", "Newton iterations"],
            rows)
    return text


def overkill():
    rows = run("cantilever_overkill", "prm/cantilever_on_plane.prm",
               {"Mesh refinement": {"Number of cycles": "14"},
                "Output": {"Probe points": ""}})
    tail = rows[-4:]
    xs = [1 / r["dofs"] for r in tail]
    ys = [r["energy"] for r in tail]
    n, sx, sy = len(xs), sum(xs), sum(ys)
    c = (n * sum(x * y for x, y in zip(xs, ys)) - sx * sy) / \
        (n * sum(x * x for x in xs) - sx * sx)
    print("overkill: J(u_h) on the last four Kelly cycles (%s dofs): %s" %
          (", ".join("%d" % r["dofs"] for r in tail),
           ", ".join("%.10f" % y for y in ys)))
    print("fitted J(u_h) = J + C/N: J = %.8f (C = %.3g)" % ((sy - c * sx) / n, c))


def main():
    common.ensure_tools((("gnuplot-nox", "gnuplot"), ("gmsh", "gmsh")))
    os.makedirs(WORK, exist_ok=True)
    if "--overkill" in sys.argv[1:]:
        overkill()
    sections = {"hertz": hertz(), "energy": energy(),
                "cattaneo_mindlin": cattaneo_mindlin(), "spence": spence()}
    sections.update(study_tables())
    replace_sections(common.output_file("doc/validation.md"), sections)
    print("scripts/validation: %s/validation.md and the charts regenerated" %
          os.path.relpath(DOC_OUT, common.ROOT))


if __name__ == "__main__":
    main()
