"""ParaView state of the projectile impact: the ball and the plate warped
by the point displacement pointD, coloured by the equivalent plastic
strain, at 60 us (the end: the dent left in the plate).  From this
folder, after ./Allrun:

    paraview --state=state.py

The case is opened through case.foam in the working folder (made
when absent), so the state is independent of where the tutorial lives;
the showing is bin/tools/paraviewState.py's (etc/bashrc sourced).
"""

import os
import sys

if "TOUCH_PROJECT_DIR" not in os.environ:
    sys.exit("state.py: TOUCH_PROJECT_DIR is not set: source touchFoam's"
             " etc/bashrc before starting ParaView")
sys.path.insert(0, os.path.join(os.environ["TOUCH_PROJECT_DIR"], "bin",
                                "tools"))
from paraviewState import show_deformed  # noqa: E402

FIELD = "sigmaEq"       # cell field shown
TIME = 1.5e-5           # [s] while the ball is pressed in
VIEW = (-1, 0.3, -1)    # the symmetric planes: the section under the impact
UP = (0, 1, 0)
SCALE = 1.0

show_deformed(FIELD, TIME, VIEW, UP, SCALE)
