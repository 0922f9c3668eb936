"""Pictures and plots of the tutorials (taylorImpact, barRebound,
ringImpact, torusImpact; pictures of twistingColumn too).

Pictures, in ParaView's pvbatch (the tutorials' render.py, run in the case
as 'xvfb-run -a pvbatch render.py'):

    render_deformed   the deformed shape (the mesh warped by pointD) coloured
                      by cell fields, one PNG per field and time, with the
                      rigid wall drawn, one colour range per field for
                      all the times (the 1st to 99th percentile of the
                      cell values, so that a few extreme cells do not hide
                      the body) and one camera for all the times (the
                      body's size and motion compare between pictures);
                      optionally the contact state of a rigidWall patch
                      seen from behind the wall, one PNG per time

    picture_colours   what a picture shows, for the tests: its size, the
                      share of its pixels in colour (neither white, grey
                      nor black) and those pixels' hues, in twelve bins

Plots, with matplotlib (the tutorials' plot.py):

    plot_panels       time series in stacked panels, one PNG
    monitor           the solidMonitor columns ({name: array}, 'Time' in s)
    point_history     displacement of the mesh points nearest to given
                      reference points, at the written times
    point_positions   current positions of all the mesh points at the
                      written times
    cell_extremes     min and max of a cell field at the written times
    slab_thickness    extent of the mesh along one axis (the ring's slab)

Only numpy is needed to import this module; ParaView and matplotlib are
imported by the functions that use them.
"""

import os

import numpy as np

from .foamfile import read_field
from .mesh import PolyMesh
from .monitor import read_monitor
from .run import time_dirs

#: time units for labels and file names: name -> seconds per unit
TIME_UNITS = {"s": 1.0, "ms": 1e-3, "us": 1e-6}


def time_label(t, unit):
    """'30 us' for t = 3e-5 s and unit 'us' (at most 4 significant digits)."""
    return "%.4g %s" % (t / TIME_UNITS[unit], unit)


# -- pictures (pvbatch) --------------------------------------------------------

def _cell_values(proxy, field):
    """All values of a cell array of a (multi-block) proxy, as numpy."""
    from paraview import servermanager
    from vtk.numpy_interface import dataset_adapter as dsa

    data = dsa.WrapDataObject(servermanager.Fetch(proxy))
    array = data.CellData[field]
    if hasattr(array, "Arrays"):
        parts = [np.asarray(a) for a in array.Arrays if a is not None]
        return np.concatenate(parts) if parts else np.zeros(0)
    return np.asarray(array)


def _frame(view_, bounds, direction, up, size, parallel=False):
    """Point the camera of view_ along -direction at the box bounds
    (xmin, xmax, ymin, ymax, zmin, zmax).  In perspective 5 % further
    than the distance that fits the box's bounding sphere in the view angle
    (ParaView's ResetCamera, for the visible props; here the wall slab is
    left out); in parallel projection with the box's extent across the view
    filling 90 % of the picture (its depth along the view does not count:
    a footprint seen from behind the wall fills the picture however far
    the body moved along the normal)."""
    box = np.reshape(bounds, (3, 2))
    centre = box.mean(axis=1)
    radius = 0.5 * np.linalg.norm(box[:, 1] - box[:, 0])
    direction = np.asarray(direction, float)
    direction = direction / np.linalg.norm(direction)
    up = np.asarray(up, float)
    up = up - np.dot(up, direction) * direction
    up = up / np.linalg.norm(up)
    angle = np.radians(view_.CameraViewAngle)
    distance = 1.05 * radius / np.sin(0.5 * angle)
    view_.CameraParallelProjection = int(parallel)
    if parallel:
        corners = np.array([[x, y, z] for x in box[0] for y in box[1]
                            for z in box[2]]) - centre
        right = np.cross(direction, up)
        height = np.ptp(corners @ up)
        width = np.ptp(corners @ right)
        aspect = float(size[0]) / size[1]
        view_.CameraParallelScale = 0.5 * max(height, width / aspect) / 0.9
    view_.CameraFocalPoint = list(centre)
    view_.CameraPosition = list(centre + distance * direction)
    view_.CameraViewUp = list(up)
    view_.CenterOfRotation = list(centre)


def _union_bounds(proxy, times):
    """Bounds of proxy's output over the times."""
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    for t in times:
        proxy.UpdatePipeline(t)
        b = np.reshape(proxy.GetDataInformation().GetBounds(), (3, 2))
        lo, hi = np.minimum(lo, b[:, 0]), np.maximum(hi, b[:, 1])
    return np.column_stack((lo, hi)).ravel()


def render_deformed(fields, times, time_unit, view, up=(0, 1, 0),
                    wall=None, case=".", size=(900, 900), titles=None,
                    percentiles=(1, 99), contact=None, scale=1.0,
                    parallel=False):
    """PNG pictures <field>_<time>.png of the deformed body.

    fields       cell fields to colour by ('pressure', 'epsilonP', ...);
                 one not written by the case is skipped with a message
    times        times [s]; the nearest written time is shown
    time_unit    's', 'ms' or 'us' for the labels and file names
    view         direction from the body towards the camera
    up           the camera's up direction
    wall         (point, normal, half width): the rigid wall, drawn as a
                 thin grey square slab under the plane (a normal along a
                 coordinate axis), or None
    titles       {field: colour bar title}
    percentiles  the colour range of a field: these percentiles of its cell
                 values over all the times shown
    scale        magnification of pointD (small deformations made visible)
    parallel     parallel projection (a long thin body fills the picture)
    contact      (patch, view, up) of a rigidWall patch, or None: pictures
                 contact_<time>.png of that patch, warped by pointD, its
                 faces in contact (the field contact = 1) red and the
                 others blue, seen along view (from behind the wall:
                 the footprint on it)
    """
    from paraview import simple as pv

    titles = titles or {}
    foam = os.path.join(case, "case.foam")
    if not os.path.exists(foam):
        open(foam, "w").close()
    reader = pv.OpenFOAMReader(FileName=foam)
    reader.MeshRegions = ["internalMesh"]
    reader.UpdatePipelineInformation()
    available = set(reader.GetProperty("CellArrayInfo")[::2])
    shown = [f for f in fields if f in available]
    for f in fields:
        if f not in available:
            print("render: no cell field '%s' in the case, skipped" % f)
    if not shown:
        return []
    reader.CellArrays = shown
    reader.PointArrays = ["pointD"]
    written = list(reader.TimestepValues)
    chosen = [min(written, key=lambda w: abs(w - t)) for t in times]

    body = pv.WarpByVector(Input=reader)
    body.Vectors = ["POINTS", "pointD"]
    body.ScaleFactor = float(scale)

    view_ = pv.CreateView("RenderView")
    view_.ViewSize = list(size)
    view_.Background = [1, 1, 1]
    view_.OrientationAxesVisibility = 1
    try:
        view_.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    display = pv.Show(body, view_)

    if wall is not None:
        # A thin grey slab under the wall plane (visible edge-on too)
        point, normal, half = (np.asarray(wall[0], float),
                               np.asarray(wall[1], float), float(wall[2]))
        normal = normal / np.linalg.norm(normal)
        axis = int(np.argmax(np.abs(normal)))
        lengths = [2 * half] * 3
        lengths[axis] = 0.03 * half
        centre = point - 0.5 * lengths[axis] * normal
        slab = pv.Box(XLength=lengths[0], YLength=lengths[1],
                      ZLength=lengths[2], Center=list(centre))
        wall_display = pv.Show(slab, view_)
        wall_display.DiffuseColor = [0.6, 0.6, 0.6]
        wall_display.AmbientColor = [0.6, 0.6, 0.6]

    label = pv.Text()
    label_display = pv.Show(label, view_)
    label_display.WindowLocation = "Upper Left Corner"
    label_display.FontSize = 14
    label_display.Color = [0, 0, 0]

    # One camera for all the times: the body's size and motion compare
    bounds = _union_bounds(body, chosen)

    written_files = []
    for field in shown:
        # One range for all the times shown, from the bulk of the values
        values = []
        for t in chosen:
            body.UpdatePipeline(t)
            values.append(_cell_values(body, field))
        values = np.concatenate(values)
        lo, hi = np.percentile(values, percentiles)
        if not hi > lo:
            lo, hi = lo - 1.0, hi + 1.0
        display.SetScalarBarVisibility(view_, False)     # the last field's
        pv.ColorBy(display, ("CELLS", field))
        lut = pv.GetColorTransferFunction(field)
        lut.ApplyPreset("Rainbow Uniform", True)
        lut.RescaleTransferFunction(float(lo), float(hi))
        lut.AutomaticRescaleRangeMode = "Never"
        display.SetScalarBarVisibility(view_, True)
        bar = pv.GetScalarBar(lut, view_)
        bar.Title = titles.get(field, field)
        bar.ComponentTitle = ""
        bar.TitleColor = [0, 0, 0]
        bar.LabelColor = [0, 0, 0]
        bar.RangeLabelFormat = "%-#.3g"

        for t in chosen:
            view_.ViewTime = t
            body.UpdatePipeline(t)
            label.Text = "t = %s" % time_label(t, time_unit)
            _frame(view_, bounds, view, up, size, parallel)
            name = "%s_%s.png" % (
                field, time_label(t, time_unit).replace(" ", ""))
            pv.SaveScreenshot(os.path.join(case, name), view_,
                              ImageResolution=list(size))
            written_files.append(name)
            print("render: wrote %s (%s in [%.4g, %.4g], percentiles %s)"
                  % (name, field, lo, hi, percentiles))

    if contact is not None:
        pv.Hide(body, view_)
        if wall is not None:
            pv.Hide(slab, view_)
        written_files += _render_contact(pv, foam, contact, chosen,
                                         time_unit, view_, label, case,
                                         size)
    return written_files


def _render_contact(pv, foam, contact, chosen, time_unit, view_, label,
                    case, size):
    """contact_<time>.png: the rigidWall patch coloured by contact (see
    render_deformed)."""
    patch, direction, up = contact
    reader = pv.OpenFOAMReader(FileName=foam)
    reader.UpdatePipelineInformation()
    regions = reader.GetProperty("PatchArrayInfo")[::2]
    if "patch/" + patch not in regions:
        print("render: no patch '%s' in the case (patches: %s), contact "
              "skipped" % (patch, " ".join(r for r in regions
                                          if r.startswith("patch/"))))
        return []
    if "contact" not in reader.GetProperty("CellArrayInfo")[::2]:
        print("render: no field 'contact' in the case (no rigidWall "
              "patch), contact skipped")
        return []
    reader.MeshRegions = ["patch/" + patch]
    reader.CellArrays = ["contact"]
    reader.PointArrays = ["pointD"]
    surface = pv.WarpByVector(Input=reader)
    surface.Vectors = ["POINTS", "pointD"]
    display = pv.Show(surface, view_)
    pv.ColorBy(display, ("CELLS", "contact"))
    lut = pv.GetColorTransferFunction("contact")
    # Two colours: 0 (free) blue, 1 (in contact) red
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = ["0", "free", "1", "in contact"]
    lut.IndexedColors = [0.23, 0.30, 0.75, 0.71, 0.02, 0.15]
    display.SetScalarBarVisibility(view_, True)
    bar = pv.GetScalarBar(lut, view_)
    bar.Title = "contact on patch %s" % patch
    bar.ComponentTitle = ""
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]

    bounds = _union_bounds(surface, chosen)
    written = []
    for t in chosen:
        view_.ViewTime = t
        surface.UpdatePipeline(t)
        faces = _cell_values(surface, "contact")
        label.Text = "t = %s: %d of %d faces of %s in contact" % (
            time_label(t, time_unit), int(np.sum(faces > 0.5)), len(faces),
            patch)
        _frame(view_, bounds, direction, up, size, parallel=True)
        name = "contact_%s.png" % time_label(t, time_unit).replace(" ", "")
        pv.SaveScreenshot(os.path.join(case, name), view_,
                          ImageResolution=list(size))
        written.append(name)
        print("render: wrote %s (%d of %d faces of patch %s in contact)"
              % (name, int(np.sum(faces > 0.5)), len(faces), patch))
    return written


def picture_colours(path, margins=(0.05, 0.2)):
    """{'size': (width, height), 'coloured': share, 'hues': [12 shares]}
    of a PNG (read with VTK, so in pvbatch or pvpython).

    The colour bar and the time label are left out: the top margins[0] of
    the height and the right margins[1] of the width.  A pixel is in
    colour when its largest and smallest channels differ by more than 60
    of 255 (the white background, the grey wall and the black text are
    not); its hue (0 red, 1/3 green, 2/3 blue) falls in one of twelve
    bins, each bin's share of the picture given."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    rgb = vtk_to_numpy(scalars).reshape(height, width, -1)[:, :, :3]
    rgb = rgb[::-1].astype(float) / 255                 # top row first
    rgb = rgb[int(margins[0] * height):, :int((1 - margins[1]) * width)]
    hi, lo = rgb.max(axis=2), rgb.min(axis=2)
    chroma = hi - lo
    coloured = chroma > 60.0 / 255
    r, g, b = (rgb[:, :, i][coloured] for i in range(3))
    c, m = chroma[coloured], hi[coloured]
    hue = np.where(m == r, ((g - b) / c) % 6,
                   np.where(m == g, (b - r) / c + 2, (r - g) / c + 4)) / 6
    bins = np.histogram(hue, bins=12, range=(0, 1))[0]
    total = float(rgb.shape[0] * rgb.shape[1])
    return {"size": (width, height), "coloured": coloured.sum() / total,
            "hues": list(bins / total)}


# -- data for the plots --------------------------------------------------------

def monitor(case="."):
    """The solidMonitor columns: {name: array} (see touchfoam.monitor)."""
    return read_monitor(case)


def _written(case):
    """(times, folder names) of the written times after 0, sorted; 0 first
    when it holds the fields."""
    dirs = time_dirs(case)
    return sorted(dirs), [dirs[t] for t in sorted(dirs)]


def point_history(case, X0):
    """Displacement of the mesh points nearest to the reference points X0
    at the written times: (times, u), u of shape (times, points, 3); a time
    without pointD (the initial one) counts as undeformed."""
    m = PolyMesh(case)
    X0 = np.atleast_2d(np.asarray(X0, float))
    nearest = [int(np.argmin(np.sum((m.points - x) ** 2, axis=1)))
               for x in X0]
    times, names = _written(case)
    u = []
    for name in names:
        path = os.path.join(case, name, "pointD")
        if os.path.exists(path) or os.path.exists(path + ".gz"):
            u.append(read_field(path).internal(len(m.points))[nearest])
        else:
            u.append(np.zeros((len(nearest), 3)))
    return np.array(times), np.array(u)


def point_positions(case):
    """(times, mesh, positions): the current point positions X + pointD
    at each written time (X at a time without pointD)."""
    m = PolyMesh(case)
    times, names = _written(case)
    positions = []
    for name in names:
        path = os.path.join(case, name, "pointD")
        if os.path.exists(path) or os.path.exists(path + ".gz"):
            positions.append(m.points + read_field(path).internal(
                len(m.points)))
        else:
            positions.append(m.points.copy())
    return np.array(times), m, positions


def cell_extremes(case, field):
    """(times, min, max) of a cell field at the written times that have
    it."""
    m = PolyMesh(case)
    times, lo, hi = [], [], []
    for t, name in zip(*_written(case)):
        path = os.path.join(case, name, field)
        if os.path.exists(path) or os.path.exists(path + ".gz"):
            values = read_field(path).internal(m.n_cells)
            times.append(t)
            lo.append(values.min())
            hi.append(values.max())
    return np.array(times), np.array(lo), np.array(hi)


def slab_thickness(case, axis=2):
    """Extent of the mesh along axis (0, 1, 2)."""
    points = PolyMesh(case).points[:, axis]
    return float(points.max() - points.min())


# -- plots (matplotlib) -------------------------------------------------------

def plot_panels(panels, out, time_unit, title=None, case="."):
    """Stacked time-series panels in one PNG.

    panels  list of (y label, curves) or (y label, curves, bands);
            curves a list of (t [s], y, label), bands of (low, high, label)
            (a shaded range of y, e.g. a literature value); a panel with no
            curves is left out
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = [p for p in panels if p[1]]
    fig, axes = plt.subplots(len(panels), 1, sharex=True,
                             figsize=(7, 2.4 * len(panels) + 0.6),
                             squeeze=False)
    scale = 1.0 / TIME_UNITS[time_unit]
    for ax, panel in zip(axes[:, 0], panels):
        ylabel, curves = panel[0], panel[1]
        for t, y, label in curves:
            style = "o-" if len(t) < 60 else "-"
            ax.plot(np.asarray(t) * scale, y, style, ms=3, lw=1.2,
                    label=label)
        for low, high, label in (panel[2] if len(panel) > 2 else []):
            ax.axhspan(low, high, color="0.5", alpha=0.3, lw=0, label=label)
        ax.set_ylabel(ylabel)
        ax.grid(True, lw=0.3)
        if len(curves) + (len(panel[2]) if len(panel) > 2 else 0) > 1 \
                or curves[0][2]:
            ax.legend(fontsize=8, loc="best")
    axes[-1, 0].set_xlabel("time [%s]" % time_unit)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    path = os.path.join(case, out)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print("plot: wrote %s" % out)
    return path


def contact_panels(data):
    """Panels of the contact faces and the wall force of every rigidWall
    patch the monitor reports (none without)."""
    t = data["Time"]
    faces = [(t, data[k], k[len("contactFaces("):-1])
             for k in data if k.startswith("contactFaces(")]
    forces = [(t, data[k], k[len("wallForce("):-1])
              for k in data if k.startswith("wallForce(")]
    return [("faces in contact", faces), ("wall force [N]", forces)]


def energy_panel(data):
    t = data["Time"]
    return ("energy [J]", [(t, data["kineticEnergy"], "kinetic"),
                           (t, data["strainEnergy"], "stored"),
                           (t, data["totalEnergy"], "total")])


def swinging_cube_plot(case, title):
    """histories.png of a swinging-cube run (hexahedra or tetrahedra): the
    L2 errors of v and P at the written times against the closed form, and
    the kinetic energy per step against the closed form's
    E sin^2(omega t) (the energy swings between strain and motion; a phase
    or amplitude error shows at once)."""
    from .analytic import SwingingCube
    from .cases import material
    from .postprocess import swinging_cube_errors

    mat = material(case)
    sol = SwingingCube(E=mat["E"], nu=mat["nu"], rho=mat["rho"])
    data = monitor(case)
    t = data["Time"]
    E = data["totalEnergy"]
    times = [w for w in _written(case)[0] if w > 0]
    ev, eP = [], []
    for w in times:
        e = swinging_cube_errors(case, t=w)
        ev.append(max(e[c]["relAmplitude"] for c in ("vx", "vy", "vz")))
        eP.append(max(e[c]["relAmplitude"] for c in ("Pxx", "Pyy", "Pzz")))
    dense = np.linspace(0.0, float(t.max()), 200)
    kinetic = E[0] * np.sin(sol.omega * dense) ** 2
    return plot_panels(
        [
            ("kinetic energy [J]",
             [(t, data["kineticEnergy"], "touchFoam"),
              (dense, kinetic, "closed form E sin^2(omega t)")]),
            ("L2 error / amplitude",
             [(times, ev, "velocity"), (times, eP, "first Piola stress")]),
            energy_panel(data),
        ],
        "histories.png", "ms", title=title, case=case)


def swinging_cube_pictures(case="."):
    """sigmaEq_<t>ms.png of a swinging-cube run (hexahedra or tetrahedra):
    von Mises stress on the cube warped by pointD magnified 200 times
    (pointD counts from the strained start, so the shape is u(t) - u(0))
    at 1, 2 and 3 ms, seen from above the corner (1, 1, 1)."""
    return render_deformed(
        fields=["sigmaEq"],
        titles={"sigmaEq": "von Mises stress [Pa]"},
        times=[0.001, 0.002, 0.003],
        time_unit="ms",
        view=(1, 0.8, 1.2),
        size=(800, 800),
        scale=200.0,
        case=case,
    )
