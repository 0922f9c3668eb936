"""The tutorials' ParaView states: a case opened through case.foam in the
working folder (made when absent), warped by the point displacement pointD
and coloured by one cell field at the written time nearest the one asked
for.  Each tutorial's state.py names its field, time and view and calls
show_deformed; `paraview --state=state.py` (or pvbatch) runs it from the
case folder, in a shell where etc/bashrc set TOUCH_PROJECT_DIR.
"""

import os

from paraview.simple import (  # ParaView's own module
    ColorBy, GetActiveViewOrCreate, GetAnimationScene,
    GetColorTransferFunction, OpenFOAMReader, Render, ResetCamera, Show,
    WarpByVector)


def show_deformed(field, time, view_direction, up=(0, 1, 0), scale=1.0,
                  component=None):
    """Open ./case.foam, show it warped by pointD (times scale) and
    coloured by the cell field (its component, e.g. 'Magnitude'), at the
    written time nearest time, seen along -view_direction."""
    if not os.path.exists("case.foam"):
        open("case.foam", "w").close()
    case = OpenFOAMReader(registrationName="case.foam", FileName="case.foam")
    case.MeshRegions = ["internalMesh"]
    case.CellArrays = [field]
    case.PointArrays = ["pointD"]
    case.UpdatePipelineInformation()

    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    written = list(case.TimestepValues) or [0.0]
    scene.AnimationTime = min(written, key=lambda t: abs(t - time))

    body = WarpByVector(registrationName="deformed (pointD)", Input=case)
    body.Vectors = ["POINTS", "pointD"]
    body.ScaleFactor = scale

    view = GetActiveViewOrCreate("RenderView")
    display = Show(body, view)
    if component:
        ColorBy(display, ("CELLS", field, component))
    else:
        ColorBy(display, ("CELLS", field))
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset("Rainbow Uniform", True)
    display.RescaleTransferFunctionToDataRange(False, True)
    display.SetScalarBarVisibility(view, True)

    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraPosition = list(view_direction)
    view.CameraViewUp = list(up)
    ResetCamera(view)
    Render(view)
    return view
