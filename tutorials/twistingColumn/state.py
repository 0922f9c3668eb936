"""ParaView state of the twisting column: the body warped by the point
displacement pointD, coloured by the pressure, at 0.1 s
(the nearest written time).  From this folder, after ./Allrun:

    paraview --state=state.py

The case is opened through case.foam in the working folder (made here
when absent), so the state is independent of where the tutorial lives.
"""

import os

from paraview.simple import (  # ParaView's own module
    ColorBy, GetActiveViewOrCreate, GetAnimationScene,
    GetColorTransferFunction, OpenFOAMReader, Render, ResetCamera, Show,
    WarpByVector)

FIELD = "pressure"      # cell field shown
TIME = 0.1              # [s] the seed's figure 3
VIEW = (1, 0.6, 1.4)    # above the corner (+X, +Z)
UP = (0, 1, 0)
SCALE = 1.0

if not os.path.exists("case.foam"):
    open("case.foam", "w").close()
case = OpenFOAMReader(registrationName="case.foam", FileName="case.foam")
case.MeshRegions = ["internalMesh"]
case.CellArrays = [FIELD]
case.PointArrays = ["pointD"]
case.UpdatePipelineInformation()

scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
written = list(case.TimestepValues) or [0.0]
scene.AnimationTime = min(written, key=lambda t: abs(t - TIME))

body = WarpByVector(registrationName="deformed (pointD)", Input=case)
body.Vectors = ["POINTS", "pointD"]
body.ScaleFactor = SCALE

view = GetActiveViewOrCreate("RenderView")
display = Show(body, view)
ColorBy(display, ("CELLS", FIELD))
lut = GetColorTransferFunction(FIELD)
lut.ApplyPreset("Rainbow Uniform", True)
display.RescaleTransferFunctionToDataRange(False, True)
display.SetScalarBarVisibility(view, True)

view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraPosition = list(VIEW)
view.CameraViewUp = list(UP)
ResetCamera(view)
Render(view)
