#!/usr/bin/python3
"""Histories of the sphere impact: the contact force of the whole ball
(four times the quarter model's) per step beside the Hertz impact's F(t)
(m* delta'' = -4/3 E* sqrt(R*) delta^(3/2), touchfoam.hertz), the faces in
contact, and the energy (from the solidMonitor).  Run in the case by
Allrun; writes histories.png.
"""

import os

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures, hertz
from touchfoam.contact import options

case = os.path.dirname(os.path.abspath(__file__))
o = options(case)
ref = hertz.case_closed_form(case)
t, F, faces = hertz.force_history(case)
tH, FH = hertz.force_curve(ref, o["V1"] + o.get("V2", 0.0))
data = figures.monitor(case)
print("peak contact force %.5g N (Hertz %.5g N)" % (F.max(), ref["F"]))

figures.plot_panels(
    [
        ("contact force [N]", [(t, F, "touchFoam (4 x quarter)"),
                               (tH, FH, "Hertz")]),
        ("faces in contact", [(t, faces, "quarter model")]),
        figures.energy_panel(data),
    ],
    "histories.png", "us", title="Sphere impact (Hertz), variant %s"
    % o["variant"], case=case)
