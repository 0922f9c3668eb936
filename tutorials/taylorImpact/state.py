"""ParaView state of the Taylor impact: the body warped by the point
displacement pointD, coloured by the equivalent plastic strain, at 80 us
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

FIELD = "epsilonP"      # cell field shown
TIME = 8e-05            # [s] the bar at rest on the wall (the seed's figure 5)
VIEW = (-1, 0.3, -1)    # facing the quarter bar's cut planes
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
