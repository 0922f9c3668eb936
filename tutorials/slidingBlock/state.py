"""ParaView state of the sliding block: the body warped by the point
displacement pointD, coloured by the pressure (its weight on the wall and
the friction's tilt of it), at 0.15 s, while it slides (the nearest
written time).  From this folder, after ./Allrun:

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

FIELD = "pressure"      # cell field shown
TIME = 0.15             # [s] sliding, half way to the stop
VIEW = (0, 0, 1)        # along z, the plane of the slab
UP = (0, 1, 0)
SCALE = 1.0

show_deformed(FIELD, TIME, VIEW, UP, SCALE)
