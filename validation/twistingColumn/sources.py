#!/usr/bin/python3
"""One twisting column run to t = 0.1 s: its twist and the energy kept.

    /usr/bin/python3 validation/twistingColumn/sources.py N LABEL [KEY=VALUE ...] [freeBase]

A copy of tutorials/twistingColumn (N x 6N x N, its settings: linear,
RK3, CFL 0.8, compatible) in runs/sources/LABEL_nN (git-ignored), with the
given TOUCH entries (a model's own entries go to its Coeffs
sub-dictionary: cases.set_touch), written every 0.01 s; the word freeBase
among them makes the base traction-free (a free body: the twist then
turns the whole column).  Prints the mean
twist of the top-face points at least 0.25 m from the axis at 0.1 s
(postprocess.column_twist), E(0.1 s)/E0 from the solidMonitor and the
solver's wall time.  FINDINGS.md, "Sources of the error".
"""
import math
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, monitor, postprocess, run  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    n, label = int(sys.argv[1]), sys.argv[2]
    args = sys.argv[3:]
    freeBase = "freeBase" in args
    touch = dict(kv.split("=", 1) for kv in args if kv != "freeBase")
    case = os.path.join(HERE, "runs", "sources", "%s_n%d" % (label, n))
    cases.prepare("twistingColumn", case, n=n, touch=touch,
                  control={"endTime": 0.1, "writeInterval": 0.01})
    if freeBase:
        run.foam_set(case, "0/U", "boundaryField/base",
                     "{ type traction; value uniform (0 0 0); }")
    start = time.time()
    run.run(["touchFoam"], case, timeout=3000)
    wall = time.time() - start
    twist = math.degrees(postprocess.column_twist(case)[-1][1])
    E = monitor.read_monitor(case)["totalEnergy"]
    print("%-20s n %d twist %.2f deg  E(0.1)/E0 %.4f  wall %.0f s"
          % (label, n, twist, E[-1] / E[0], wall), flush=True)


if __name__ == "__main__":
    main()
