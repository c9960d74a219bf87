"""Renders a scene's final cycle: the body warped by its displacement (true
scale), coloured by the von Mises stress with a legend in MPa, over the
obstacle, with a caption. 2D scenes much longer than high are drawn with a
vertical exaggeration (body and obstacle alike, so contact stays contact),
stated in the caption. Axisymmetric scenes (Material/Plane state in the
run's parameters.prm) are revolved through three quarters of a turn about
their axis, body and obstacle; a body much larger than its contact zone (a
half-space) is shown near it.

    pvpython render.py OUTPUT_DIRECTORY IMAGE.png TITLE

Run by scripts/render (headless, on an Xvfb X server).
"""
import math
import sys

from paraview import simple

directory, image, title = sys.argv[1:4]
WIDTH, HEIGHT = 800, 400


def plane_state(directory):
    """Material/Plane state of the run in @p directory, from the parameters
    it wrote (every entry, includes resolved)."""
    section = []
    try:
        lines = open(directory + "/parameters.prm").read().splitlines()
    except OSError:
        return ""
    for line in lines:
        words = line.split()
        if words[:1] == ["subsection"]:
            section.append(" ".join(words[1:]))
        elif words == ["end"] and section:
            section.pop()
        elif section == ["Material"] and line.strip().startswith(
                "set Plane state") and "=" in line:
            return line.split("=", 1)[1].strip()
    return ""


def last_row(directory):
    """The last row of the run's statistics.csv as a dict of floats."""
    try:
        rows = open(directory + "/statistics.csv").read().split()
        return dict(zip(rows[0].split(","), map(float, rows[-1].split(","))))
    except (OSError, IndexError, ValueError):
        return {}


def keep_side(source, origin, normal):
    """The part of @p source on the side of the plane that @p normal points
    to."""
    clip = simple.Clip(Input=source, ClipType="Plane")
    clip.ClipType.Origin = origin
    clip.ClipType.Normal = normal
    try:
        clip.Invert = 0
    except AttributeError:
        pass
    return clip


def revolve(source, capping):
    """@p source, a 2D (r, z) = (x, y) data set, turned so that its axis is z
    and swept through 270 degrees about it."""
    # The solution files repeat each vertex per cell: merged, only the
    # outline is swept.
    turned = simple.Transform(
        Input=simple.ExtractSurface(Input=simple.CleantoGrid(Input=source)))
    turned.Transform.Rotate = [90, 0, 0]
    swept = simple.RotationalExtrusion(Input=turned)
    swept.Resolution = 54
    swept.Angle = 270
    swept.Capping = capping
    return swept


def white_view():
    """A render view of the picture's size, white, without axes."""
    view = simple.CreateView("RenderView")
    view.ViewSize = [WIDTH, HEIGHT]
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.OrientationAxesVisibility = 0
    return view


def show_caption(view, text):
    """@p text in black in the view's upper left corner."""
    label = simple.Show(simple.Text(Text=text), view)
    label.Color = [0, 0, 0]
    label.FontSize = 14
    label.WindowLocation = "Upper Left Corner"
    label.Justification = "Left"


def stress_colours(body, view, pairs):
    """Colours body by the von Mises stress, with the scale ending where only
    1 % of the measure is more stressed; pairs: (stress, measure) per cell,
    sorted."""
    simple.ColorBy(body, ("POINTS", "von_mises"))
    lut = simple.GetColorTransferFunction("von_mises")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    total, running, top = sum(m for _, m in pairs), 0., pairs[-1][0]
    for value, measure in pairs:
        running += measure
        if running >= 0.99 * total:
            top = value
            break
    lut.RescaleTransferFunction(pairs[0][0], top)
    lut.AutomaticRescaleRangeMode = "Never"
    bar = simple.GetScalarBar(lut, view)
    bar.Title = "von Mises stress [MPa]"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize = bar.LabelFontSize = 14
    bar.RangeLabelFormat = "%.3g"
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Horizontal"
    bar.Position = [0.55, 0.04]
    bar.ScalarBarLength = 0.4
    body.SetScalarBarVisibility(view, True)


def render_revolved(reader, n_cycles, time):
    """The axisymmetric scene's body and obstacle revolved, seen from the
    obstacle's side of the contact plane into the missing quarter."""
    data = simple.servermanager.Fetch(reader)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    bounds = data.GetBounds()
    n_cells = data.GetNumberOfCells()
    # A half-space (a body over 40 times its contact radius) is shown near
    # its contact zone: within four contact radii of the axis and the
    # contact plane, at the body's bottom or top, where its active nodes
    # are (an obstacle below it or a punch from above).
    radius = last_row(directory).get("contact_width", 0.)
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2])
    window = size
    if radius > 0 and size > 40 * radius:
        window = 4 * radius
    active = data.GetPointData().GetArray("active_set")
    heights = [data.GetPoint(i)[1] for i in range(data.GetNumberOfPoints())
               if active is not None and active.GetValue(i) > 0.5]
    from_above = bool(heights) and (
        sum(heights) / len(heights) > (bounds[2] + bounds[3]) / 2)
    side = -1 if from_above else 1
    contact_plane = bounds[3] if from_above else bounds[2]
    near = lambda source: keep_side(
        keep_side(source, [window, 0, 0], [-1, 0, 0]),
        [0, contact_plane + side * window, 0], [0, -side, 0])

    section = simple.WarpByVector(Input=reader,
                                  Vectors=["POINTS", "displacement"],
                                  ScaleFactor=1.0)
    if window < size:
        section = near(section)
    body_3d = revolve(section, 1)
    if window < size:
        # obstacle.vtu samples the obstacle over the whole body, too coarsely
        # for the window: the obstacle is drawn where the body touches it,
        # the active part of the deformed boundary, a little outside.
        edges = simple.FeatureEdges(Input=simple.ExtractSurface(
            Input=simple.CleantoGrid(Input=section)))
        edges.BoundaryEdges = 1
        edges.FeatureEdges = edges.NonManifoldEdges = edges.ManifoldEdges = 0
        touching = simple.Threshold(Input=edges,
                                    Scalars=["POINTS", "active_set"])
        touching.LowerThreshold, touching.UpperThreshold = 0.5, 1.5
        touching.AllScalars = 1
        obstacle = simple.Transform(Input=touching)
        obstacle.Transform.Translate = [0, -side * 0.01 * window, 0]
    else:
        obstacle = simple.XMLUnstructuredGridReader(
            FileName=[directory + "/obstacle.vtu"])
        obstacle = keep_side(keep_side(obstacle, [0, 0, 0], [1, 0, 0]),
                             [1.1 * bounds[1], 0, 0], [-1, 0, 0])
    ground_3d = revolve(obstacle, 0)

    view = white_view()
    body = simple.Show(body_3d, view)
    # The colour range ends where 1 % of the revolved body's volume (of the
    # part shown), cell areas times 2 pi r, is more stressed.
    shown = reader if window >= size else near(reader)
    cells = simple.CellSize(Input=simple.PointDatatoCellData(Input=shown))
    centres = simple.CellCenters(Input=cells)
    cells.UpdatePipeline(time)
    centres.UpdatePipeline(time)
    cell_data = simple.servermanager.Fetch(cells)
    centre_data = simple.servermanager.Fetch(centres)
    if cell_data.IsA("vtkMultiBlockDataSet"):
        cell_data = cell_data.GetBlock(0)
        centre_data = centre_data.GetBlock(0)
    stress = cell_data.GetCellData().GetArray("von_mises")
    area = cell_data.GetCellData().GetArray("Area")
    pairs = sorted((stress.GetValue(i),
                    area.GetValue(i) * abs(centre_data.GetPoint(i)[0]))
                   for i in range(stress.GetNumberOfTuples()))
    stress_colours(body, view, pairs)
    ground = simple.Show(ground_3d, view)
    if window < size:
        ground.AmbientColor = ground.DiffuseColor = [0.75, 0.75, 0.75]
    else:
        ground.AmbientColor = ground.DiffuseColor = [0.35, 0.35, 0.35]
        ground.Opacity = 0.5

    caption = ("%s: cycle %d, %d cells, revolved through 270 degrees; "
               "displacement to scale" % (title, n_cycles - 1, n_cells))
    caption_2 = ("colour scale ends where 1 %% of the body is more stressed "
                 "(max %.3g MPa)" % pairs[-1][0])
    if window < size:
        caption_2 += "; %.3g mm around the contact" % window
    show_caption(view, caption + "\n" + caption_2)

    # From the obstacle's side of the contact plane, into the missing
    # quarter (between 270 and 360 degrees), through the half-transparent
    # obstacle.
    simple.Render(view)
    body_3d.UpdatePipeline(time)
    box = simple.servermanager.Fetch(body_3d).GetBounds()
    centre = [0.5 * (box[2 * i] + box[2 * i + 1]) for i in range(3)]
    extent = math.sqrt(sum((box[2 * i + 1] - box[2 * i]) ** 2
                           for i in range(3)))
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0] + 1.2 * extent, centre[1] - 1.2 * extent,
                           centre[2] - side * 0.8 * extent]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera(*box)
    view.GetActiveCamera().Dolly(1.5)
    simple.Render(view)
    simple.SaveScreenshot(image, view, ImageResolution=[WIDTH, HEIGHT],
                          CompressionLevel=9)
    print("wrote %s (%s)" % (image, caption))


reader = simple.PVDReader(FileName=directory + "/solution.pvd")
times = list(reader.TimestepValues) or [0.]
n_cycles = len(times)
simple.GetAnimationScene().AnimationTime = times[-1]
reader.UpdatePipeline(times[-1])


def render_plain(reader, n_cycles, times):
    """A 2D (plane) or 3D scene's body over its obstacle."""
    data = simple.servermanager.Fetch(reader)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    bounds = data.GetBounds()
    dim = 3 if bounds[5] - bounds[4] > 1e-12 else 2
    n_cells = data.GetNumberOfCells()

    warp = simple.WarpByVector(Input=reader, Vectors=["POINTS", "displacement"],
                               ScaleFactor=1.0)
    obstacle = simple.XMLUnstructuredGridReader(
        FileName=[directory + "/obstacle.vtu"])
    if dim == 3:
        # An obstacle height may drop far away outside its support (e.g. -1000
        # off the indenter): only the part near the body is drawn.
        depth = bounds[5] - bounds[4]
        obstacle = simple.Clip(Input=obstacle, ClipType="Plane")
        obstacle.ClipType.Origin = [0, 0, bounds[4] - 0.5 * depth]
        obstacle.ClipType.Normal = [0, 0, 1]
        try:
            obstacle.Invert = 0
        except AttributeError:
            pass

    # Vertical exaggeration of long, flat 2D bodies: at least a quarter as high
    # as wide on screen.
    width, height = bounds[1] - bounds[0], bounds[3] - bounds[2]
    exaggeration = 1
    if dim == 2 and height > 0:
        exaggeration = max(1, min(5, int(round(0.25 * width / height))))
    scale = [1.0, float(exaggeration), 1.0]

    view = white_view()

    body = simple.Show(warp, view)
    body.Scale = scale
    # Stress concentrations at corners and contact edges would take the whole
    # colour range: it ends where only 1 % of the body's area (volume) is more
    # stressed.
    cells = simple.CellSize(Input=simple.PointDatatoCellData(Input=reader))
    cells.UpdatePipeline(times[-1])
    cell_data = simple.servermanager.Fetch(cells)
    if cell_data.IsA("vtkMultiBlockDataSet"):
        cell_data = cell_data.GetBlock(0)
    stress = cell_data.GetCellData().GetArray("von_mises")
    size = cell_data.GetCellData().GetArray("Volume" if dim == 3 else "Area")
    pairs = sorted((stress.GetValue(i), size.GetValue(i))
                   for i in range(stress.GetNumberOfTuples()))
    stress_colours(body, view, pairs)

    ground = simple.Show(obstacle, view)
    ground.Scale = scale
    ground.AmbientColor = ground.DiffuseColor = [0.35, 0.35, 0.35]
    if dim == 2:
        ground.SetRepresentationType("Wireframe")
        ground.LineWidth = 4
    else:
        ground.Opacity = 0.5

    caption = "%s: cycle %d, %d cells; displacement to scale" % (
        title, n_cycles - 1, n_cells)
    caption_2 = ("colour scale ends where 1 %% of the body is more stressed "
                 "(max %.3g MPa)" % pairs[-1][0])
    if exaggeration > 1:
        caption += ", vertical scale x%d" % exaggeration
    show_caption(view, caption + "\n" + caption_2)

    # The camera frames the body and a little of the obstacle around it (after
    # the first render, which resets the camera).
    simple.Render(view)
    view.CameraParallelProjection = 1
    cx, cy = 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3])
    if dim == 2:
        view.CameraPosition = [cx, cy * exaggeration, 10 * width]
        view.CameraFocalPoint = [cx, cy * exaggeration, 0]
        view.CameraViewUp = [0, 1, 0]
        # Room for the caption above and the legend below.
        half_height = 0.5 * height * exaggeration
        parallel_scale = max(2.0 * half_height, 0.56 * width * HEIGHT / WIDTH)
        view.CameraParallelScale = parallel_scale
        focus = cy * exaggeration - 0.15 * parallel_scale
        view.CameraFocalPoint = [cx, focus, 0]
        view.CameraPosition = [cx, focus, 10 * width]
    else:
        cz = 0.5 * (bounds[4] + bounds[5])
        size = math.sqrt(sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2
                             for i in range(3)))
        # From below the contact face, through the half-transparent obstacle,
        # framing the body alone.
        view.CameraFocalPoint = [cx, cy, cz]
        view.CameraPosition = [cx + 0.8 * size, cy - 1.6 * size, cz - 0.7 * size]
        view.CameraViewUp = [0, 0, 1]
        view.ResetCamera(*bounds)
    simple.Render(view)
    simple.SaveScreenshot(image, view, ImageResolution=[WIDTH, HEIGHT],
                          CompressionLevel=9)
    print("wrote %s (%s)" % (image, caption))


if plane_state(directory) == "axisymmetric":
    render_revolved(reader, n_cycles, times[-1])
else:
    render_plain(reader, n_cycles, times)
