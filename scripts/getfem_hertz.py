#!/usr/bin/python3
"""The Hertz scenes of signorini modelled in GetFEM (the Debian package
python3-getfem, 5.4), a peer code for scripts/work_precision.py and
scripts/peer_hertz.py:

    2d  prm/hertz_cylinder.prm: the quarter disk R = 1 centred (0, 1),
        E = 1000 MPa, nu = 0.3, plane strain, its symmetry line x = 0
        sliding, its flat top y = 1 loaded by the traction (0, -5) (F/2 =
        5 N/mm of the half model), pressed onto the rigid plane y = 0
    3d  prm/hertz_sphere.prm: the quarter ball R = 1 centred (0, 0, 1),
        its symmetry planes x = 0 and y = 0 sliding, its flat top z = 1
        loaded by a uniform traction of resultant (0, 0, -0.375) (F/4 of
        F = 1.5 N), held vertically only by the rigid plane z = 0

    scripts/getfem_hertz.py 2d|3d [--degree 1|2] [--contact nodal|integral]
                            [--cycles N] [--size H] [--graded H0]
                            [--fraction F]

Lagrange elements of degree 1 or 2 (P1, P2) on triangles or tetrahedra.
The first mesh is Gmsh's: cells of size H (0.2 mm in 2D, 0.25 in 3D),
graded to H0 within 1.2 a of the contact point (0.05 mm in 2D, 0.02 in 3D;
0 for a uniform mesh), curved for P1 and P2 alike (a geometric
transformation of degree 2, GT_PK(d,2), the mid-edge nodes of the arc or
sphere on it). Then GetFEM's own adaptive refinement: a cycle solves,
estimates the error of each cell by the jump of the normal stress across
its inner faces (a Kelly-like indicator: eta_K^2 = sum over the inner
faces F of K of h_K/2 |[sigma(u) n]|^2 integrated over F), and
Bank-refines the fraction F of the cells with the largest indicators (30 %
in 2D, as signorini's Kelly cycles; 15 % in 3D, where the closure of
refined tetrahedra grows the mesh 4.5-fold a cycle at 30 %, 3-fold at
15 %, as signorini's 30 % of hexahedra). GetFEM does not coarsen. New
nodes lie on the parent cell's curved boundary, so the geometry is the
first mesh's quadratic arc or sphere throughout, hence the grading: moving
the new nodes onto the circle or sphere, as signorini's manifolds place
them, leaves GetFEM's record of its closure cells with their old
coordinates, and a later refinement then made cells that no longer share
faces (measured: the outer faces' area 4.9 where it is 3.9 mm^2). The
next cycle starts from the previous solution and pressure interpolated
onto the refined mesh.

Frictionless contact with the plane by Alart-Curnier's augmented
Lagrangian: nodal (add_nodal_contact_with_rigid_obstacle_brick, the
obstacle as the signed distance y or z, a multiplier per node of the arc,
the node's contact force) or integral
(add_integral_contact_with_rigid_obstacle_brick, a multiplier field of the
same degree on the arc, the pressure); r = E. Newton's method with MUMPS.
The symmetry lines or planes by normal Dirichlet conditions with
multipliers.

Measured as signorini measures (source/postprocessing/contact_zone.cc,
zone_edges.cc, pressure_recovery.cc): p0 is the largest nodal pressure on
the arc; a node's pressure at degree 1 its contact force (the multiplier)
divided by its lumped area (the integral of its shape function over the
arc), at degree 2 the recovered one, M p = F with the arc's mass matrix
(the lumped area of a quadratic triangle's vertex is zero); with the
integral contact the multiplier's nodal value. A node is in contact where
its force exceeds 1e-8 of the largest (with the integral contact, where
the multiplier exceeds 1 % of its largest). The contact half-width a is
the extent of the nodes in contact and of the zone's edge points, one
between each node in contact and each open node next to it, where p^2,
extrapolated linearly from the node in contact before it, vanishes: in 2D
along the arc, in 3D along x and along y (the smaller), the node before it
the neighbour in contact most nearly in line.

Prints a CSV row per cycle on stdout as the cycle ends: cycle, cells, dofs
(of the displacement), contact_nodes (in contact), iterations (Newton's),
time [s] (time.perf_counter from the first line of this script, imports and
Gmsh included, to the end of the cycle's error estimate), p0, a,
p0_error, a_error (relative, signed, against Hertz's closed form), force
(the contact force's normal resultant), max_penetration [mm].
"""
import time

START = time.perf_counter()

import argparse  # noqa: E402
import os  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402

import numpy as np  # noqa: E402
import getfem as gf  # noqa: E402

YOUNG, POISSON = 1000., 0.3
E_STAR = YOUNG / (1 - POISSON ** 2)
# Regions: the arc or sphere (contact), the flat top, the symmetry planes
# x = 0 and y = 0, the inner faces (the indicator's jumps).
CONTACT, TOP, SYMMETRY_X, SYMMETRY_Y, INNER = 1, 2, 3, 4, 5
# A node is in contact where its force exceeds this fraction of the
# largest (an open node's multiplier is zero to round-off, and may be
# positive).
ROUND_OFF = 1e-8
# With the integral contact, the multiplier's nodal values off the contact
# zone oscillate about zero by up to 0.5 % of p0 (P2 in 3D): a node is in
# contact where the multiplier exceeds this fraction of its largest value.
OSCILLATION = 1e-2
COLUMNS = ["cycle", "cells", "dofs", "contact_nodes", "iterations", "time",
           "p0", "a", "p0_error", "a_error", "force", "max_penetration"]


class Scene:
    """Geometry, load and Hertz's closed form of one scene."""

    def __init__(self, dimension):
        self.dim = dimension
        self.radius = 1.
        if dimension == 2:
            self.centre = np.array([0., 1.])
            force = 10.  # the whole cylinder's, per mm
            self.load = force / 2  # the half model's, on the top of length 1
            self.a = 2 * np.sqrt(force * self.radius / (np.pi * E_STAR))
            self.p0 = 2 * force / (np.pi * self.a)
        else:
            self.centre = np.array([0., 0., 1.])
            force = 1.5  # the whole ball's
            self.load = force / 4  # the quarter model's
            self.a = (3 * force * self.radius / (4 * E_STAR)) ** (1 / 3)
            self.p0 = 3 * force / (2 * np.pi * self.a ** 2)

    def geo(self, size, graded=None):
        """The Gmsh geometry, of uniform cell size `size`, or, if `graded`
        is given, of size `graded` within 1.2 a of the contact point,
        growing by 0.3 times the distance beyond, up to `size`."""
        if self.dim == 2:
            text = ("Point(1) = {0, 0, 0}; Point(2) = {1, 1, 0};\n"
                    "Point(3) = {0, 1, 0};\n"
                    "Circle(1) = {1, 3, 2}; Line(2) = {2, 3}; "
                    "Line(3) = {3, 1};\n"
                    "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\n"
                    "Physical Surface(1) = {1};\n")
        else:
            text = ('SetFactory("OpenCASCADE");\n'
                    "Sphere(1) = {0, 0, 1, 1, -Pi/2, 0, Pi/2};\n"
                    "Physical Volume(1) = {1};\n"
                    "Point(100) = {0, 0, 0};\n")
        text += "Mesh.MeshSizeFromCurvature = 0;\n"
        if graded is None:
            return text + "Mesh.MeshSizeMin = %g; Mesh.MeshSizeMax = %g;\n" % (
                size, size)
        return text + (
            "Field[1] = Distance; Field[1].PointsList = {%d};\n"
            "Field[2] = MathEval;\n"
            'Field[2].F = "min(%g, %g + 0.3 * max(0, F1 - %g))";\n'
            "Background Field = 2;\n"
            "Mesh.MeshSizeExtendFromBoundary = 0; "
            "Mesh.MeshSizeFromPoints = 0;\n" % (
                1 if self.dim == 2 else 100, size, graded, 1.2 * self.a))

    def on_arc(self, points):
        """Whether each point (column) is on the circle or sphere."""
        distance = np.linalg.norm(points - self.centre[:, None], axis=0)
        return np.abs(distance - self.radius) < 1e-6


def first_mesh(scene, size, graded=None):
    """Gmsh's mesh of the scene (Scene.geo), its cells curved (a geometric
    transformation of degree 2, the mid-edge nodes of the arc or sphere on
    it), and the regions of its boundary."""
    with tempfile.TemporaryDirectory(prefix="getfem-hertz-") as folder:
        geo = os.path.join(folder, "body.geo")
        msh = os.path.join(folder, "body.msh")
        with open(geo, "w") as out:
            out.write(scene.geo(size, graded))
        subprocess.run(["gmsh", "-%d" % scene.dim, "-order", "2",
                        "-format", "msh22", "-o", msh, geo], check=True,
                       stdout=subprocess.DEVNULL)
        mesh = gf.Mesh("import", "gmsh", msh)
    set_regions(mesh, scene)
    assert scene.on_arc(mesh.pts(mesh.pid_in_regions(CONTACT))).all()
    return mesh


def set_regions(mesh, scene):
    """The regions of the boundary, from the faces' positions: the planes'
    faces lie in them, the others on the arc or sphere. (GetFEM's
    refinement carries the regions over to the new faces, but in 3D it
    loses some, 12 % of the sphere's area by the fourth cycle.)"""
    for region in mesh.regions():
        mesh.delete_region(region)
    far, near = 10., 1e-9
    low, high = -far * np.ones(scene.dim), far * np.ones(scene.dim)
    planes = {SYMMETRY_X: 0, TOP: scene.dim - 1}
    if scene.dim == 3:
        planes[SYMMETRY_Y] = 1
    mesh.set_region(CONTACT, mesh.outer_faces())
    for region, axis in planes.items():
        position = 1. if region == TOP else 0.
        box_low, box_high = low.copy(), high.copy()
        box_low[axis], box_high[axis] = position - near, position + near
        mesh.set_region(region, mesh.outer_faces_in_box(box_low, box_high))
        mesh.region_subtract(CONTACT, region)


class Solver:
    """One cycle's GetFEM model on the current mesh."""

    def __init__(self, scene, mesh, degree, contact):
        self.scene, self.mesh, self.degree = scene, mesh, degree
        self.contact = contact
        dim = scene.dim
        self.mfu = gf.MeshFem(mesh, dim)
        self.mfu.set_classical_fem(degree)
        self.mfs = gf.MeshFem(mesh, 1)
        self.mfs.set_classical_fem(degree)
        # The stiffness on curved cells, two orders (2D) or one order (3D)
        # above exact on straight ones.
        simplex = "IM_TRIANGLE" if dim == 2 else "IM_TETRAHEDRON"
        order = 2 * degree + (2 if dim == 2 else 1)
        self.mim = gf.MeshIm(mesh, gf.Integ("%s(%d)" % (simplex, order)))
        self.model = model = gf.Model("real")
        model.add_fem_variable("u", self.mfu)
        lame = YOUNG * POISSON / ((1 + POISSON) * (1 - 2 * POISSON))
        shear = YOUNG / (2 * (1 + POISSON))
        model.add_initialized_data("lambda", [lame])
        model.add_initialized_data("mu", [shear])
        model.add_isotropic_linearized_elasticity_brick(
            self.mim, "u", "lambda", "mu")
        # The top's traction, of the load's resultant over the top as meshed.
        top = gf.asm("generic", self.mim, 0, "1", TOP)
        traction = np.zeros(dim)
        traction[-1] = -scene.load / top
        model.add_initialized_data("traction", traction)
        model.add_source_term_brick(self.mim, "u", "traction", TOP)
        for region in (SYMMETRY_X, SYMMETRY_Y)[:dim - 1]:
            model.add_normal_Dirichlet_condition_with_multipliers(
                self.mim, "u", degree, region)
        model.add_initialized_data("r", [YOUNG])
        obstacle = "xyz"[dim - 1]  # the signed distance to the plane
        contact_dofs = self.mfu.basic_dof_on_region(CONTACT)
        # The brick's multipliers: one per node of the region, in the order
        # of the nodes' first dofs.
        self.nodes = np.sort(contact_dofs)[::dim]
        if contact == "nodal":
            model.add_variable("lambda_n", len(self.nodes))
            model.add_nodal_contact_with_rigid_obstacle_brick(
                self.mim, "u", "lambda_n", "r", CONTACT, obstacle, 1)
        else:
            self.mfl = gf.MeshFem(mesh, 1)
            self.mfl.set_classical_fem(degree)
            model.add_filtered_fem_variable("lambda_n", self.mfl, CONTACT)
            model.add_initialized_fem_data(
                "obstacle", self.mfs, self.mfs.eval(obstacle))
            model.add_integral_contact_with_rigid_obstacle_brick(
                self.mim, "u", "lambda_n", "obstacle", "r", CONTACT, 1)

    def solve(self, initial, pressure=None):
        """Newton's method from the displacement `initial` and, if given,
        the contact pressure `pressure` (a field of the scalar mesh_fem);
        returns the number of iterations."""
        self.model.set_variable("u", initial)
        if pressure is not None:
            if self.contact == "nodal":
                mass = gf.asm_mass_matrix(self.mim, self.mfs, self.mfs,
                                          CONTACT)
                guess = -mass.mult(pressure)[self.nodes // self.scene.dim]
            else:
                guess = -pressure[self.mfl.basic_dof_on_region(CONTACT)]
            self.model.set_variable("lambda_n", guess)
        iterations, converged = self.model.solve(
            "max_res", 1e-9, "max_iter", 50, "lsolver", "mumps",
            *(["very noisy"] if os.environ.get("GETFEM_NOISY") else []))
        if not converged:
            sys.exit("getfem_hertz.py: Newton's method did not converge")
        return iterations

    def measure(self):
        """p0, a, the contact nodes, the normal contact force and the
        largest penetration; keeps the nodal pressures as a field of the
        scalar mesh_fem (`pressure`), the next cycle's first guess."""
        dim = self.scene.dim
        u = self.model.variable("u")
        multiplier = self.model.variable("lambda_n")
        if self.contact == "nodal":
            positions = self.mfu.basic_dof_nodes(self.nodes)
            scalar = self.nodes // dim
            assert np.allclose(self.mfs.basic_dof_nodes(scalar), positions)
            force = -multiplier  # GetFEM's multiplier is negative in contact
            mass = gf.asm_mass_matrix(self.mim, self.mfs, self.mfs, CONTACT)
            lumped = mass.mult(np.ones(self.mfs.nbdof()))[scalar]
            # The lumped area against the mass matrix's diagonal: 2 at the
            # nodes of linear triangles, 1.25 at those of quadratic lines,
            # 1.9 at the mid-edge nodes of quadratic triangles and zero (to
            # the curvature's terms) at their vertices.
            defined = lumped > 0.5 * mass_diagonal(mass)[scalar]
            nodal = np.zeros(len(force))
            nodal[defined] = force[defined] / lumped[defined]
            if self.degree == 1:
                pressure = nodal
            else:
                pressure = recovered_pressure(mass, scalar, force)
            in_contact = force > ROUND_OFF * force.max()
            total = force.sum()
            # The next cycle's guess: the lumped nodal pressure (the
            # recovered one over- and undershoots at the contact zone's
            # edge, and a guess of tension costs Newton steps), at the
            # vertices of quadratic triangles the recovered one, at least
            # zero.
            self.pressure = np.zeros(self.mfs.nbdof())
            self.pressure[scalar] = np.where(defined, nodal,
                                             np.maximum(pressure, 0.))
        else:
            dofs = self.mfl.basic_dof_on_region(CONTACT)
            positions = self.mfl.basic_dof_nodes(dofs)
            pressure = -multiplier
            in_contact = pressure > OSCILLATION * pressure.max()
            total = gf.asm("generic", self.mim, 0, "-lambda_n", CONTACT,
                           self.model)
            self.pressure = np.zeros(self.mfl.nbdof())
            self.pressure[dofs] = pressure
        gaps = self.mfu.basic_dof_nodes(self.nodes)[-1] + \
            u[self.nodes + dim - 1]
        penetration = max(0., -gaps.min())
        p0 = pressure.max()
        if dim == 2:
            a = half_width(positions[0], pressure, in_contact)
        else:
            if self.contact == "nodal":
                graph, indices = mass, scalar
            else:
                graph = gf.asm_mass_matrix(self.mim, self.mfl, self.mfl,
                                           CONTACT)
                indices = dofs
            a = zone_width(positions, pressure, in_contact, graph, indices)
        return p0, a, int(in_contact.sum()), total, penetration

    def indicators(self):
        """The Kelly-like indicator of each cell (eta_K^2) and the cells'
        ids."""
        mesh = self.mesh
        mesh.set_region(INNER, mesh.inner_faces())
        mfp0 = gf.MeshFem(mesh, 1)
        mfp0.set_classical_fem(0)
        jump = "(Grad_u - Interpolate(Grad_u, neighbor_element))"
        stress = "(lambda*Trace(%s)*Id(meshdim) + mu*(%s + (%s)'))" % (
            jump, jump, jump)
        expression = ("0.5*element_size*Norm_sqr(%s*Normal)*"
                      "(Test_psi + Interpolate(Test_psi, neighbor_element))"
                      % stress)
        eta = gf.asm("generic", self.mim, 1, expression, INNER, self.model,
                     "psi", 1, mfp0, np.zeros(mfp0.nbdof()))
        eta = eta[-mfp0.nbdof():]
        cells = mfp0.basic_dof_from_cvid()
        # One dof per cell: the dof of each cell, in the order of the ids.
        ids = np.asarray(mesh.cvid())
        values = np.array([eta[cells[0][cells[1][i]]]
                           for i in range(len(ids))])
        return ids, values


def mass_diagonal(mass):
    """The diagonal of the GetFEM matrix `mass` (Spmat.diag prints to
    stdout)."""
    pointers, rows = mass.csc_ind()
    columns = np.repeat(np.arange(len(pointers) - 1), np.diff(pointers))
    on = rows == columns
    diagonal = np.zeros(len(pointers) - 1)
    diagonal[columns[on]] = mass.csc_val()[on]
    return diagonal


def recovered_pressure(mass, nodes, force):
    """The pressure at `nodes` whose consistent nodal forces are `force`:
    M p = F with the arc's mass matrix restricted to them (as signorini
    recovers it at degree 2, source/postprocessing/pressure_recovery.cc;
    the lumped area of a vertex of a quadratic triangle is zero)."""
    import scipy.sparse
    import scipy.sparse.linalg
    matrix = scipy.sparse.csc_matrix(
        (mass.csc_val(), *mass.csc_ind()[::-1]), shape=tuple(mass.size()))
    return scipy.sparse.linalg.spsolve(matrix[nodes][:, nodes].tocsc(), force)


def half_width(x, pressure, in_contact):
    """The contact half-width as signorini measures it in 2D
    (source/postprocessing/zone_edges.cc): from the last node in contact
    towards the first open one along the arc (the nodes sorted by x), to
    where p^2, extrapolated from the last two nodes in contact, vanishes."""
    order = np.argsort(x)
    x, pressure, in_contact = x[order], pressure[order], in_contact[order]
    last = np.nonzero(in_contact)[0].max()
    low = x[in_contact].min()
    if last + 1 >= len(x) or last == 0 or not in_contact[last - 1]:
        return x[last] - low
    inner, inside, outside = x[last - 1], x[last], x[last + 1]
    v_inner, v_inside = pressure[last - 1], pressure[last]
    if not (v_inner > v_inside >= 0):
        return inside - low
    distance = v_inside ** 2 * (inside - inner) / \
        (v_inner ** 2 - v_inside ** 2)
    theta = min(1., distance / (outside - inside))
    return inside + theta * (outside - inside) - low


def zone_width(positions, pressure, in_contact, mass, nodes):
    """The contact radius in 3D as signorini measures it
    (source/postprocessing/zone_edges.cc, contact_zone.cc): the smaller of
    the extents along x and along y of the nodes in contact and of the
    zone's edge points, one between each node in contact and each open node
    next to it (sharing a face of the arc's mesh: the mass matrix's
    pattern), where p^2, extrapolated linearly from the node in contact
    before it on the line from the open node, vanishes. That node is the
    neighbour in contact most nearly in line (a triangle mesh has no lines
    of nodes)."""
    import scipy.sparse
    pattern = scipy.sparse.csc_matrix(
        (np.ones(len(mass.csc_val())), *mass.csc_ind()[::-1]),
        shape=tuple(mass.size()))[nodes][:, nodes].tocsr()
    points = [positions[:, i] for i in np.nonzero(in_contact)[0]]
    for i in np.nonzero(in_contact)[0]:
        around = pattern.indices[pattern.indptr[i]:pattern.indptr[i + 1]]
        inside = [j for j in around if j != i and in_contact[j]]
        for n in around:
            if in_contact[n]:
                continue
            outward = positions[:, n] - positions[:, i]
            best, behind = 0.5, None  # within 60 degrees of the line
            for j in inside:
                back = positions[:, i] - positions[:, j]
                alignment = back @ outward / np.linalg.norm(back) / \
                    np.linalg.norm(outward)
                if alignment > best:
                    best, behind = alignment, j
            points.append(square_root_edge(
                positions[:, behind] if behind is not None else None,
                pressure[behind] if behind is not None else 0.,
                positions[:, i], pressure[i], positions[:, n]))
    points = np.array(points).T
    return min(points[0].max() - points[0].min(),
               points[1].max() - points[1].min())


def square_root_edge(inner, v_inner, inside, v_inside, outside):
    """The point between `inside` and `outside` where p^2, linear through
    (inner, v_inner^2) and (inside, v_inside^2), vanishes; `inside` if
    there is no `inner` or p does not fall towards the edge."""
    if inner is None or not (v_inner > v_inside >= 0):
        return inside
    distance = v_inside ** 2 * np.linalg.norm(inside - inner) / \
        (v_inner ** 2 - v_inside ** 2)
    theta = min(1., distance / np.linalg.norm(outside - inside))
    return inside + theta * (outside - inside)


def refine(mesh, scene, ids, eta, fraction):
    """Bank-refines the `fraction` of the cells with the largest
    indicators (their closure cells too). New nodes lie on the parent
    cell's curved boundary: the first mesh's quadratic arc or sphere."""
    count = max(1, int(round(fraction * len(ids))))
    mesh.refine(ids[np.argsort(eta)[-count:]])
    mesh.optimize_structure()
    set_regions(mesh, scene)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene", choices=["2d", "3d"])
    parser.add_argument("--degree", type=int, choices=[1, 2], default=1)
    parser.add_argument("--contact", choices=["nodal", "integral"],
                        default="nodal")
    parser.add_argument("--cycles", type=int, default=8)
    parser.add_argument("--size", type=float, default=None,
                        help="the first mesh's cell size [mm] (default: "
                        "0.2 in 2D, 0.25 in 3D)")
    parser.add_argument("--graded", type=float, default=None,
                        help="the first mesh's cell size [mm] within 1.2 a "
                        "of the contact point (default: 0.05 in 2D, 0.02 "
                        "in 3D), growing with the distance beyond; 0: a "
                        "uniform first mesh")
    parser.add_argument("--fraction", type=float, default=None,
                        help="the fraction of the cells refined per cycle "
                        "(default: 0.3 in 2D, 0.15 in 3D)")
    args = parser.parse_args()
    gf.util("trace level", 0)
    gf.util("warning level", 0)
    scene = Scene(2 if args.scene == "2d" else 3)
    size = args.size or (0.2 if scene.dim == 2 else 0.25)
    # In 3D Bank's closure refines so many neighbours of the refined
    # tetrahedra that 30 % grows the mesh 4.5-fold a cycle; 15 % grows it
    # 3-fold, as signorini's 30 % of the hexahedra.
    fraction = args.fraction or (0.3 if scene.dim == 2 else 0.15)
    graded = (0.05 if scene.dim == 2 else 0.02) if args.graded is None \
        else args.graded
    mesh = first_mesh(scene, size, graded or None)
    print(",".join(COLUMNS), flush=True)
    solver = ids = eta = None
    for cycle in range(args.cycles):
        if solver is None:
            solver = Solver(scene, mesh, args.degree, args.contact)
            # A rigid descent by Hertz's approach: the nodes near the
            # contact point start inside the plane, in contact.
            initial = np.zeros(solver.mfu.nbdof())
            initial[scene.dim - 1::scene.dim] = \
                -scene.a ** 2 / (2 * scene.radius)
            iterations = solver.solve(initial)
        else:
            # The previous solution and pressure, on a copy of the mesh
            # before it is refined, interpolated onto the refined one.
            old_mesh = gf.Mesh("clone", mesh)
            old_u = gf.MeshFem(old_mesh, scene.dim)
            old_u.set_classical_fem(args.degree)
            old_p = gf.MeshFem(old_mesh, 1)
            old_p.set_classical_fem(args.degree)
            assert old_u.nbdof() == solver.mfu.nbdof()
            u, pressure = solver.model.variable("u"), solver.pressure
            refine(mesh, scene, ids, eta, fraction)
            solver = Solver(scene, mesh, args.degree, args.contact)
            iterations = solver.solve(
                gf.compute_interpolate_on(old_u, u, solver.mfu),
                gf.compute_interpolate_on(old_p, pressure, solver.mfs))
        p0, a, nodes, force, penetration = solver.measure()
        ids, eta = solver.indicators()
        row = [cycle, mesh.nbcvs(), solver.mfu.nbdof(), nodes, iterations,
               time.perf_counter() - START, p0, a, p0 / scene.p0 - 1,
               a / scene.a - 1, force, penetration]
        print(",".join("%.10g" % value for value in row), flush=True)


if __name__ == "__main__":
    main()
