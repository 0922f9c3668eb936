"""ParaView state of the swinging cube: the body warped by the point
displacement pointD (magnified 200 times), coloured by the speed |U|, at 4 ms
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

FIELD = "U"             # cell field shown
COMPONENT = "Magnitude"
TIME = 0.004            # [s] a quarter period: the speed at its peak, the stress at its node
VIEW = (1, 0.8, 1.2)    # above the corner (1, 1, 1)
UP = (0, 1, 0)
SCALE = 200.0           # magnified; pointD counts from the strained start u(X, 0)

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
ColorBy(display, ("CELLS", FIELD, COMPONENT))
lut = GetColorTransferFunction(FIELD)
lut.ApplyPreset("Rainbow Uniform", True)
display.RescaleTransferFunctionToDataRange(False, True)
display.SetScalarBarVisibility(view, True)

view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraPosition = list(VIEW)
view.CameraViewUp = list(UP)
ResetCamera(view)
Render(view)
