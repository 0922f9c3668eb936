"""Render the deformed shape of a touchFoam case, coloured by pressure.

    xvfb-run -a pvbatch renderDeformed.py [time ...]        (in the case)

Reads case.foam with ParaView's OpenFOAM reader, warps the mesh by the point
displacement pointD and writes deformed_<time>.png for each time asked for
(default: every time written).
"""

import sys

from paraview.simple import (  # pvbatch provides paraview
    OpenFOAMReader, WarpByVector, GetActiveViewOrCreate, Show, ColorBy,
    GetColorTransferFunction, SaveScreenshot, ResetCamera)

reader = OpenFOAMReader(FileName="case.foam")
reader.MeshRegions = ["internalMesh"]
reader.CellArrays = ["pressure"]
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
wanted = [float(t) for t in sys.argv[1:]] or times

warp = WarpByVector(Input=reader)
warp.Vectors = ["POINTS", "pointD"]

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [700, 1000]
view.OrientationAxesVisibility = 1
display = Show(warp, view)
ColorBy(display, ("CELLS", "pressure"))
display.SetScalarBarVisibility(view, True)

for wanted_time in wanted:
    # The written time nearest to the one asked for
    time = min(times, key=lambda t: abs(t - wanted_time))
    view.ViewTime = time
    warp.UpdatePipeline(time)
    lo, hi = warp.CellData["pressure"].GetRange()
    bound = max(abs(lo), abs(hi)) or 1
    GetColorTransferFunction("pressure").RescaleTransferFunction(-bound, bound)
    view.CameraPosition = [9, 5, 9]
    view.CameraFocalPoint = [0, 3, 0]
    view.CameraViewUp = [0, 1, 0]
    ResetCamera()
    SaveScreenshot("deformed_%g.png" % time, view)
    print("wrote deformed_%g.png" % time)
