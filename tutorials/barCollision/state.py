"""ParaView state of the bar collision: the two bars warped by the point
displacement pointD (magnified 1000 times: the bars' ends move by at most
0.1 mm), coloured by the pressure, at 0.5 ms (the compressed zone half way
along the bars; the nearest written time).  From this folder, after
./Allrun:

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
TIME = 0.0005           # [s] the fronts half way along the bars
VIEW = (0.2, 0.3, 1)    # from the side, slightly above
UP = (0, 1, 0)
SCALE = 1000.0          # the displacement (at most 0.1 mm) is magnified

show_deformed(FIELD, TIME, VIEW, UP, SCALE)
