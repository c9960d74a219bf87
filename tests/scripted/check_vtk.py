"""Opens every VTU, PVTU and PVD file under the folders given with
ParaView's readers and prints, per file, its size and fields, checking that
the solution files hold every field the README's Output section names with
its number of components, and no NaN.

Run with Debian's python3 (package python3-paraview):
    /usr/bin/python3 check_vtk.py FOLDER...
    /usr/bin/python3 check_vtk.py --same FOLDER OTHER
The second form checks that the solution VTU files of the two folders hold
the same points and arrays, value for value (the same run written with
another compression).
"""
import math
import pathlib
import sys

from paraview import simple, servermanager

# The README's Output section: name -> number of components (VTK stores
# vectors with three components, also in 2D).
FIELDS_2D = {"displacement": 3, "von_mises": 1, "stress_xx": 1,
             "stress_yy": 1, "stress_zz": 1, "stress_xy": 1,
             "contact_pressure": 1, "active_set": 1, "gap": 1,
             "kelly_indicator": 1, "mpi_rank": 1}
FIELDS_3D = dict(FIELDS_2D, stress_xz=1, stress_yz=1)
# An axisymmetric model's stresses are named by its axes r, z and the hoop.
FIELDS_AXISYMMETRIC = {
    name: n for name, n in FIELDS_2D.items() if not name.startswith("stress")}
FIELDS_AXISYMMETRIC.update(stress_rr=1, stress_zz=1, stress_hoop=1,
                           stress_rz=1)


def open_file(path):
    if path.suffix == ".pvd":
        reader = simple.PVDReader(FileName=str(path))
        times = list(reader.TimestepValues or [0.])
        reader.UpdatePipeline(times[-1])
        return reader, len(times)
    if path.suffix == ".pvtu":
        reader = simple.XMLPartitionedUnstructuredGridReader(
            FileName=[str(path)])
    else:
        reader = simple.XMLUnstructuredGridReader(FileName=[str(path)])
    reader.UpdatePipeline()
    return reader, 1


def check(path):
    reader, steps = open_file(path)
    data = servermanager.Fetch(reader)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    points, cells = data.GetNumberOfPoints(), data.GetNumberOfCells()
    arrays = data.GetPointData()
    fields = {arrays.GetArrayName(i): arrays.GetArray(i)
              for i in range(arrays.GetNumberOfArrays())}
    problems = []
    if points == 0 or cells == 0:
        problems.append("empty")
    if path.name != "obstacle.vtu":
        bounds = data.GetBounds()
        dim = 3 if bounds[5] - bounds[4] > 0 else 2
        expected = FIELDS_3D if dim == 3 else FIELDS_2D
        if "stress_hoop" in fields:
            expected = FIELDS_AXISYMMETRIC
        for name, components in expected.items():
            if name not in fields:
                problems.append("no field " + name)
            elif fields[name].GetNumberOfComponents() != components:
                problems.append("%s has %d components" % (
                    name, fields[name].GetNumberOfComponents()))
    for name, array in fields.items():
        for c in range(array.GetNumberOfComponents()):
            low, high = array.GetRange(c)
            if not (math.isfinite(low) and math.isfinite(high)):
                problems.append(name + " not finite")
    shown = ", ".join("%s(%d)" % (n, fields[n].GetNumberOfComponents())
                      for n in sorted(fields))
    print("%s: %s, %d steps, %d points, %d cells, fields %s" % (
        path, "OK" if not problems else "FAIL " + "; ".join(problems),
        steps, points, cells, shown or "none"))
    return not problems


def same(folder, other):
    """Whether each solution-*.vtu of folder has the points and arrays of
    the file of that name in other."""
    names = sorted(p.name for p in pathlib.Path(folder).glob("solution-*.vtu"))
    for name in names:
        a, b = (servermanager.Fetch(open_file(pathlib.Path(f) / name)[0])
                for f in (folder, other))
        pairs = [(a.GetPoints().GetData(), b.GetPoints().GetData())]
        pa, pb = a.GetPointData(), b.GetPointData()
        for i in range(pa.GetNumberOfArrays()):
            pairs.append((pa.GetArray(i),
                          pb.GetArray(pa.GetArrayName(i))))
        for x, y in pairs:
            if (y is None or x.GetNumberOfValues() != y.GetNumberOfValues()
                    or any(x.GetValue(k) != y.GetValue(k)
                           for k in range(x.GetNumberOfValues()))):
                print("%s/%s and %s/%s differ" % (folder, name, other, name))
                return False
    print("%s and %s: %d solution files, the same points and arrays" % (
        folder, other, len(names)))
    return len(names) > 0


if sys.argv[1] == "--same":
    sys.exit(0 if same(sys.argv[2], sys.argv[3]) else 1)

ok = True
for folder in sys.argv[1:]:
    for path in sorted(pathlib.Path(folder).rglob("*")):
        if path.suffix in (".vtu", ".pvtu", ".pvd") and not (
                path.suffix == ".vtu" and path.stem.count(".") == 1
                and path.stem.split(".")[1].isdigit()):
            ok = check(path) and ok
print("all files open and hold their fields" if ok else "FAILED")
