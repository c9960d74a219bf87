# An axisymmetric run's output on one process and on two: the axisymmetric
# patch test (a solid cylinder under a uniform radial traction s = 1 MPa) for
# two Kelly cycles. Every VTU, PVTU and PVD file opens in ParaView's readers
# and holds the axisymmetric fields (check_vtk.py); the stresses of the last
# cycle are uniform, sigma_rr = sigma_hoop = 1, sigma_zz = sigma_rz = 0, von
# Mises 1, also on the axis, where the hoop strain is du_r/dr; and the two
# runs' statistics agree (energy_error, the square root of a round-off
# difference here, apart).
source "$TESTS/common.bash"
for name in serial parallel; do
  {
    echo "include $TESTS/../axisymmetric_patch_test.prm"
    echo "subsection Mesh refinement"
    echo "  set Number of cycles = 2"
    echo "end"
    echo "subsection Output"
    echo "  set Directory = $name"
    echo "end"
  } > $name.prm
done
run "$SIGNORINI" serial.prm
run mpirun -np 2 "$SIGNORINI" parallel.prm
/usr/bin/python3 "$TESTS/check_vtk.py" serial parallel 2>&1
/usr/bin/python3 - 2>&1 <<'PY'
from paraview import simple, servermanager
reader = simple.PVDReader(FileName="serial/solution.pvd")
reader.UpdatePipeline(reader.TimestepValues[-1])
data = servermanager.Fetch(reader)
if data.IsA("vtkMultiBlockDataSet"):
    data = data.GetBlock(0)
points = data.GetPointData()
exact = {"stress_rr": 1., "stress_hoop": 1., "stress_zz": 0.,
         "stress_rz": 0., "von_mises": 1.}
for name, value in exact.items():
    low, high = points.GetArray(name).GetRange()
    worst = max(abs(low - value), abs(high - value))
    print("%s from %.3f to %.3f: %s" % (name, round(low, 3) + 0., round(high, 3) + 0.,
          "uniform" if worst < 1e-12 else "FAILED (%.1e)" % worst))
axis = [i for i in range(data.GetNumberOfPoints())
        if abs(data.GetPoint(i)[0]) < 1e-12]
hoop = points.GetArray("stress_hoop")
print("%d points on the axis, stress_hoop there %s" % (len(axis), "1" if all(
    abs(hoop.GetValue(i) - 1.) < 1e-12 for i in axis) else "FAILED"))
PY
/usr/bin/python3 - 2>&1 <<'PY'
import csv
serial = list(csv.DictReader(open("serial/statistics.csv")))
parallel = list(csv.DictReader(open("parallel/statistics.csv")))
worst = max(abs(float(a[k]) - float(b[k]))
            for a, b in zip(serial, parallel) for k in a
            if k != "energy_error")
print("statistics of one and two processes: %d and %d rows, largest "
      "difference %s" % (len(serial), len(parallel),
                        "below 1e-12" if worst < 1e-12 else "%.1e" % worst))
PY
