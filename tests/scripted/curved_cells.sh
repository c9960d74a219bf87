# Q2's cells as ParaView reads them (Debian's python3 with python3-paraview):
# the quarter ball of prm/hertz_sphere.prm from one initial refinement,
# written as VTK Lagrange hexahedra of order 2, holds the quarter ball's
# volume pi/6 = 0.5236 to 2 % (ParaView integrates each cell on a linear
# subdivision through its 27 points); the same mesh of Q1 cells, a polyhedron
# through the vertices, holds 7 % less, and a hexahedron read with its
# points in the wrong order holds 23 % less. The 2D quarter disk of
# prm/hertz_cylinder.prm likewise, from one initial refinement: pi/4 =
# 0.7854 to 1 %. And P2's: the quarter ball of prm/hertz_sphere_p2.prm's
# first mesh (Gmsh's tetrahedra of prm/quarter_ball.geo), written as VTK
# Lagrange tetrahedra of order 2, holds pi/6 to 1 %, where its P1 cells
# hold less.
source "$TESTS/common.bash"
# one NAME SCENE [GEOMETRY LINES...]: one cycle of prm/SCENE.prm with the
# Geometry entries given, written to NAME/.
one() {
  local name=$1 scene=$2
  shift 2
  {
    echo "include $PRM/$scene.prm"
    echo "subsection Geometry"
    for line in "$@"; do echo "  set $line"; done
    echo "end"
    echo "subsection Mesh refinement"
    echo "  set Number of cycles = 1"
    echo "end"
    echo "subsection Output"
    echo "  set Directory = $name"
    echo "end"
  } > $name.prm
  run "$SIGNORINI" $name.prm
}
for degree in 1 2; do
  one ball$degree hertz_sphere "Initial refinement = 1" \
    "Element degree = $degree"
done
one disk2 hertz_cylinder "Initial refinement = 1" "Element degree = 2"
for degree in 1 2; do
  one tetrahedra$degree hertz_sphere "Type = gmsh" \
    "Mesh file = $PRM/quarter_ball.geo" "Initial refinement = 0" \
    "Element degree = $degree"
done
/usr/bin/python3 - <<'PYTHON' 2>&1
import math
from paraview import simple, servermanager
def measure(path):
    reader = simple.XMLUnstructuredGridReader(FileName=[path])
    integral = simple.IntegrateVariables(Input=reader)
    integral.UpdatePipeline()
    data = servermanager.Fetch(integral).GetCellData()
    array = data.GetArray("Volume") or data.GetArray("Area")
    return array.GetValue(0)
ball = math.pi / 6
for name, exact, bound in (("ball1", ball, None), ("ball2", ball, 0.02),
                           ("disk2", math.pi / 4, 0.01),
                           ("tetrahedra1", ball, None),
                           ("tetrahedra2", ball, 0.01)):
    value = measure(name + "/solution-00.vtu")
    error = abs(value / exact - 1)
    verdict = "" if bound is None else (
        ": within %g: %s" % (bound, "yes" if error < bound else "NO"))
    print("%s: %.4f of %.4f, %.1f %% off%s" % (name, value, exact,
                                              100 * error, verdict))
PYTHON
