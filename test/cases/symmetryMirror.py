#!/usr/bin/python3
"""With symmetricPlanes mirror, a symmetric plane computes what the whole
body computes.

    /usr/bin/python3 test/cases/symmetryMirror.py

The Taylor bar at -n 3 (the tutorial: a quarter between the symmetric
planes x = 0 and z = 0, plastic, on the rigid wall, limitedLinear, nodal
pressure averaging, the point upwinding) and the whole bar made from the
same mesh by mirrorMesh across both planes (4 x 240 cells), both to 5 us,
with `symmetricPlanes mirror;` in TOUCH.  The whole bar's solution is
mirror-symmetric, so the quarter must give its values in the quarter's
cells, to round-off: the reconstruction, the limiter, the point map and
its transpose and the point upwinding treat a symmetric plane's faces as
interior faces to the cell's reflection.  The default, oneSided, is run
too and its difference reported (not asserted: it is the known defect the
option removes).

Asserted: lm, F, epsilonP (cells) and pointD (points), the quarter's
against the whole bar's at the same reference positions, differ by at most
1e-10 of each field's largest value.  One-sided, F differs by 2e-5 after
the first step, and at 80 us the quarter's foot radius is 6.685 mm against
the whole bar's 6.596.

Work folders: test/runs/symmetryMirror/.
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.postprocess import PolyMesh  # noqa: E402

NAME = "symmetryMirror"
N = 3
T_END = 5e-6
TOLERANCE = 1e-10
CELL_FIELDS = ("lm", "F", "epsilonP")
MIRROR_DICT = """FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      mirrorMeshDict;
}
planeType       pointAndNormal;
pointAndNormalDict
{
    point       (0 0 0);
    normal      %s;
}
planeTolerance  1e-6;
"""


def positions_index(reference, positions, scale):
    """For each row of positions, the row of reference at the same place."""
    def key(x):
        return tuple(np.round(np.asarray(x) / scale * 1e6).astype(np.int64))
    table = {key(x): i for i, x in enumerate(reference)}
    try:
        return np.array([table[key(x)] for x in positions])
    except KeyError as e:
        raise AssertionError("no whole-bar cell or point at %s" % (e,))


def differences(quarter, whole):
    """The fields' largest differences, relative to each field's largest
    value, and the quarter's peak plastic strain and the cell counts."""
    mq, mw = PolyMesh(quarter), PolyMesh(whole)
    if mw.n_cells != 4 * mq.n_cells:
        raise AssertionError("whole bar has %d cells, not 4 x %d"
                             % (mw.n_cells, mq.n_cells))
    scale = float(np.abs(mq.points).max())
    cells = positions_index(mw.cell_centres, mq.cell_centres, scale)
    points = positions_index(mw.points, mq.points, scale)

    tq = run.time_dir(quarter, T_END)
    tw = run.time_dir(whole, T_END)
    out = {}
    for field in CELL_FIELDS:
        a = read_field(os.path.join(tq, field)).internal(mq.n_cells)
        b = read_field(os.path.join(tw, field)).internal(mw.n_cells)
        out[field] = testing.relative_max_difference(
            np.asarray(a), np.asarray(b)[cells])
    a = read_field(os.path.join(tq, "pointD")).internal(len(mq.points))
    b = read_field(os.path.join(tw, "pointD")).internal(len(mw.points))
    out["pointD"] = testing.relative_max_difference(
        np.asarray(a), np.asarray(b)[points])
    peak = float(np.asarray(read_field(os.path.join(tq, "epsilonP"))
                            .internal(mq.n_cells)).max())
    return out, peak, mq.n_cells, mw.n_cells


def body():
    root = testing.work_dir(NAME)
    control = dict(cases.precise_output(),
                   endTime=T_END, writeInterval=T_END)
    mirror = {"symmetricPlanes": "mirror"}
    quarter = cases.prepare("taylorImpact", os.path.join(root, "quarter"),
                            n=N, control=control, touch=mirror)
    one_sided = cases.prepare("taylorImpact",
                              os.path.join(root, "oneSided"),
                              n=N, control=control)
    whole = cases.prepare("taylorImpact", os.path.join(root, "whole"),
                          n=N, control=control, touch=mirror,
                          initialise=False)
    for normal in ("(-1 0 0)", "(0 0 -1)"):
        with open(os.path.join(whole, "system", "mirrorMeshDict"), "w") as f:
            f.write(MIRROR_DICT % normal)
        run.run(["mirrorMesh", "-overwrite"], whole,
                name="mirrorMesh" + normal.replace(" ", ""))
    cases.set_initial_state(whole)

    for case in (quarter, one_sided, whole):
        run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)

    found, peak, nq, nw = differences(quarter, whole)
    default, _, _, _ = differences(one_sided, whole)
    lines = ["mirror: quarter (%d cells) against the whole bar (%d) at %g s: "
             % (nq, nw, T_END)
             + ", ".join("%s %.2e" % kv for kv in found.items())
             + " of the field's largest value (tolerance %.0e); peak "
             "epsilonP %.3f" % (TOLERANCE, peak),
             "oneSided (the default, reported): "
             + ", ".join("%s %.2e" % kv for kv in default.items())]
    failures = []
    for field, d in found.items():
        if not d <= TOLERANCE:
            failures.append("%s differs by %.3e > %.0e" % (field, d, TOLERANCE))
    if not peak > 0.1:
        failures.append("peak epsilonP %.3f: the bar has not yielded, the "
                        "case does not test the plastic state" % peak)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
