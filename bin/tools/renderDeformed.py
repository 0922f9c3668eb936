"""Render the deformed shape of a touchFoam case, coloured by pressure.

    xvfb-run -a pvbatch renderDeformed.py        (in the case folder)

Reads case.foam with ParaView's OpenFOAM reader, warps the point
displacement pointU onto the mesh and writes deformed_<time>.png for the
last time written.
"""

from paraview.simple import (  # noqa: F401 (pvbatch provides paraview)
    OpenFOAMReader, WarpByVector, GetActiveViewOrCreate, Show, ColorBy,
    GetAnimationScene, SaveScreenshot, ResetCamera)

reader = OpenFOAMReader(FileName="case.foam")
reader.MeshRegions = ["internalMesh"]
reader.CellArrays = ["pressure", "J"]
reader.PointArrays = ["pointU"]
reader.UpdatePipelineInformation()
times = reader.TimestepValues
last = times[-1] if times else 0

warp = WarpByVector(Input=reader)
warp.Vectors = ["POINTS", "pointU"]

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [800, 1000]
view.ViewTime = last
display = Show(warp, view)
ColorBy(display, ("CELLS", "pressure"))
display.RescaleTransferFunctionToDataRange(True)
display.SetScalarBarVisibility(view, True)
view.CameraPosition = [8, 6, 8]
view.CameraFocalPoint = [0, 3, 0]
view.CameraViewUp = [0, 1, 0]
ResetCamera()
SaveScreenshot("deformed_%g.png" % last, view)
