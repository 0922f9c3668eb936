#!/usr/bin/python3
"""The upwindings' losses per cell and per point add up to the energy lost.

    /usr/bin/python3 test/cases/upwindLosses.py [--omega 1] [--n 8]

The diagnostic of the compatible update (DebugSwitches { compatible 1; },
compatibleLosses.C) writes the energy each cell lost to the momentum
upwinding (upwindLoss) and each point to the point upwinding
(pointUpwindLoss); validation/twistingColumn/losses.py sums them over the
regions of the twisting column (FINDINGS.md, "Where the energy goes").
This test runs tutorials/twistingColumn (linear, RK3, CFL 0.8) on
n x 6n x n cells to 0.1 s, twice: in the linear regime (initial spin
Omega = 1 rad/s instead of 105) and at the tutorial's spin, and checks
the tallies against the energy the solidMonitor measures from the state
(about 25 s).  Asserted:
  - no cell and no point gains energy from the upwindings (every tally
    >= -1e-12 E0);
  - linear regime: the tallies add up to the monitored loss 1 - E/E0 within
    2 % (measured 2026-12-05 on n = 8: 0.000857 of 0.000862, 0.6 % short,
    the step's own share: the tally takes each step's first stage);
  - tutorial spin: they account for 80 % to 100 % of it (measured 87.6 %
    on n = 8, 93.7 % on 12, 96.0 % on 16 with losses.py's writes: the rest is the RK3 step's,
    converging at order 2.9).
Perturbation that makes it fail (2026-12-05): --omega 105 for the linear
run (87.6 %, not within 2 %).
Work folders: test/runs/upwindLosses/.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, monitor, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

NAME = "upwindLosses"
T_END = 0.1
LINEAR_TOL = 0.02
SHARE_BAND = (0.80, 1.0)
NEGATIVE_FLOOR = -1e-12


def losses(root, label, n, Omega):
    """(1 - E/E0, cell tallies / E0, point tallies / E0) of one run."""
    case = cases.prepare("twistingColumn", os.path.join(root, label), n=n,
                         control={"endTime": T_END, "writeInterval": T_END})
    if Omega is not None:
        cases.initialise_twisting_column(case, Omega=Omega)
    run.foam_set(case, "system/controlDict", "DebugSwitches",
                 "{ compatible 1; }")
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    E = monitor.read_monitor(case)["totalEnergy"]
    m = PolyMesh(case)
    tdir = run.time_dir(case, T_END)
    cell = np.asarray(read_field(os.path.join(tdir, "upwindLoss"))
                      .internal(m.n_cells), float) / E[0]
    point = np.asarray(read_field(os.path.join(tdir, "pointUpwindLoss"))
                       .internal(len(m.points)), float) / E[0]
    return 1 - E[-1] / E[0], cell, point


def body(args):
    root = testing.work_dir(NAME)
    lines, failures = [], []
    for label, Omega, band in (
            ("linear", args.omega, (1 - LINEAR_TOL, 1 + LINEAR_TOL)),
            ("tutorial", None, SHARE_BAND)):
        lost, cell, point = losses(root, label, args.n, Omega)
        share = (cell.sum() + point.sum()) / lost
        lines.append("%s: lost %.3g E0, tallied %.3g (cells %.3g, points"
                     " %.3g), %.1f %%" % (label, lost, cell.sum() + point.sum(),
                                          cell.sum(), point.sum(),
                                          100 * share))
        lowest = min(cell.min(), point.min())
        if lowest < NEGATIVE_FLOOR:
            failures.append("%s: a tally gains energy (%.3g E0)"
                            % (label, lowest))
        if not band[0] <= share <= band[1]:
            failures.append("%s: tallies %.1f %% of the loss, not in"
                            " [%g, %g] %%" % (label, 100 * share,
                                              100 * band[0], 100 * band[1]))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--omega", type=float, default=1.0,
                        help="initial spin of the linear run [rad/s]")
    parser.add_argument("--n", type=int, default=8)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
