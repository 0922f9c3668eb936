"""Pictures and plots of the impact tutorials (taylorImpact, barRebound,
ringImpact, torusImpact).

Pictures, in ParaView's pvbatch (the tutorials' render.py, run in the case
as 'xvfb-run -a pvbatch render.py'):

    render_deformed   the deformed shape (the mesh warped by pointD) coloured
                      by cell fields, one PNG per field and time, with the
                      rigid wall drawn and one colour range per field for
                      all the times: the 1st to 99th percentile of the
                      cell values, so that a few extreme cells do not hide
                      the body

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


def render_deformed(fields, times, time_unit, view, up=(0, 1, 0),
                    wall=None, case=".", size=(900, 900), titles=None,
                    percentiles=(1, 99)):
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
            focus = np.mean(np.reshape(body.GetDataInformation()
                                       .GetBounds(), (3, 2)), axis=1)
            view_.CameraFocalPoint = list(focus)
            view_.CameraPosition = list(focus + np.asarray(view, float))
            view_.CameraViewUp = list(up)
            view_.ResetCamera()
            name = "%s_%s.png" % (
                field, time_label(t, time_unit).replace(" ", ""))
            pv.SaveScreenshot(os.path.join(case, name), view_,
                              ImageResolution=list(size))
            written_files.append(name)
            print("render: wrote %s (%s in [%.4g, %.4g], percentiles %s)"
                  % (name, field, lo, hi, percentiles))
    return written_files


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
