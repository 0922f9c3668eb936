"""ParaView state of the swinging cube: the body warped by the point
displacement pointD (magnified 200 times), coloured by the speed |U|, at 4 ms
(the nearest written time).  From this folder, after ./Allrun:

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

FIELD = "U"             # cell field shown
COMPONENT = "Magnitude"
TIME = 0.004            # [s] a quarter period: the speed at its peak, the stress at its node
VIEW = (1, 0.8, 1.2)    # above the corner (1, 1, 1)
UP = (0, 1, 0)
SCALE = 200.0           # magnified; pointD counts from the strained start u(X, 0)

show_deformed(FIELD, TIME, VIEW, UP, SCALE, COMPONENT)
