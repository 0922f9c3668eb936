#!/usr/bin/python3
"""The sliding block with each F update, with and without angular momentum
preservation, on N = 4 and 8 (tutorials/slidingBlock; FINDINGS.md).

    . etc/bashrc; /usr/bin/python3 validation/slidingBlock/study.py [N ...]

Per run: the mean deceleration v0/t_stop against mu g, the distance
against v0^2/(2 mu g), the largest speed 0.02 s after the stop, the
longest time with no face in contact (the block off the wall), and the
largest energy change in a step over the initial kinetic energy.
Work folders: validation/slidingBlock/runs/ (ignored).
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "test", "cases"))

import numpy as np  # noqa: E402

import slidingBlock as case  # noqa: E402
from touchfoam import run, sliding  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

VARIANTS = [("plain", "on"), ("plain", "off"),
            ("constrained", "off"), ("constrained", "on"),
            ("compatible", "off"), ("compatible", "on")]


def one(root, n, update, am):
    case.N = n
    name = "N%d_%s_am%s" % (n, update, am)
    c = case.make_case(root, name, 0.45)
    run.foam_set(c, "system/fvSolution", "TOUCH/FUpdate", update)
    run.foam_set(c, "system/fvSolution",
                 "TOUCH/angularMomentumPreservation", am)
    try:
        run.run(["touchFoam"], c)
    except run.RunError:
        # Friction with FUpdate compatible is refused since it was
        # measured (FINDINGS.md, commit 371e08c)
        print("%2d  %-10s %-3s  refused" % (n, update, am), flush=True)
        return
    M = case.mass_of(c)
    s = sliding.slide(c, M, np.array([case.V0, 0, 0]), case.MU_K, case.G)
    mon = read_monitor(c)
    t, free = mon["Time"], mon["contactFaces(bottom)"] == 0
    off, longest, start = 0.0, 0.0, None
    for ti, fi in zip(t, free):
        if fi and start is None:
            start = ti
        if not fi and start is not None:
            longest, start = max(longest, ti - start), None
    E = mon["totalEnergy"]
    growth = np.max(np.diff(E)) / (0.5 * M * case.V0 ** 2)
    fmt = lambda x, f: "-" if x is None else f % x  # noqa: E731
    print("%2d  %-10s %-3s  %9s  %9s  %8s  %8.4f  %+.1e"
          % (n, update, am,
             fmt(s["deceleration"] and 100 * (s["deceleration"]
                                               / s["deceleration_ref"] - 1),
                 "%+.2f %%"),
             "%+.2f %%" % (100 * (s["distance"] / s["distance_ref"] - 1)),
             fmt(s["rest_speed"], "%.1e"), longest, growth), flush=True)


def main(argv):
    sizes = [int(a) for a in argv[1:]] or [4, 8]
    root = os.path.join(HERE, "runs")
    os.makedirs(root, exist_ok=True)
    print(" N  update     AM   decel-mu g  distance   at rest   off [s]   "
          "dE/K0 max")
    for n in sizes:
        for update, am in VARIANTS:
            one(root, n, update, am)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
