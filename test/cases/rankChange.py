#!/usr/bin/python3
"""A run moves from 2 to 3 ranks mid-way and ends on the serial result to
round-off; a parallel restart from the processor folders and a second
identical parallel run are byte-identical.

    /usr/bin/python3 test/cases/rankChange.py [--steps 40]

The twisting column at 2 x 12 x 2 cells (its tutorial: RK3, angular
momentum preservation, whose global sums make the parallel result differ
from the serial one in the last digits) and the bar rebound at -n 3 (240
cells, the end reaches the rigid wall after 26.7 us), N =
--steps steps a half (maxSteps; writeControl timeStep every N steps, the
tutorials' writePrecision 12: the state is written with 17 digits):

  serial    2N steps straight;
  par2      decomposePar (metis, 2 ranks), 2N steps on 2 ranks, twice
            (par2, par2again);
  restart2  N steps on 2 ranks, then N more from the processor folders
            (startFrom latestTime), on 2 ranks;
  change    N steps on 2 ranks, reconstructPar, decomposePar -force
            -latestTime on 3 ranks, N more steps on 3 ranks,
            reconstructPar.
Asserted:
  - par2again's processor folders are byte-identical to par2's, every
    file of every time (a parallel run is reproducible);
  - restart2's processor folders at the end are byte-identical to par2's
    (lm, F, D, pointD, U);
  - change's reconstructed end (lm, F, D, pointD) matches serial as
    closely as the run on 2 ranks throughout does (par2, the parallel
    round-off of the global sums and of the processor faces):
        e = max|q - q_serial| / max(max|q_serial|, floor_q),
        e_change <= max(1e-12, 2 e_par2)
    with the floors of parallelEqualsSerial (rho0 U_p for lm, 1 for F,
    the body's size for D and pointD), and the 3-rank decomposition is
    used (3 processor folders, each holding the end time).
reconstructPar and decomposePar write the fields at the controlDict's
writePrecision, not at touchFoam's 17 digits for the state: the test
sets writePrecision 17 while they run.  At the tutorials' 12 the rank
change rounds the state (measured at --steps 40: the twisting column's
lm 3.4e-11 from serial against 1.8e-13 on 2 ranks throughout).
Work folders: test/runs/rankChange/.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, foamfile, run, testing  # noqa: E402

NAME = "rankChange"
TOLERANCE = 1e-12
STATE = ("lm", "F", "D", "pointD")


def prepare(root, label, tutorial, n, steps, nprocs=None):
    case = cases.prepare(tutorial, os.path.join(root, label), n=n,
                         control={"maxSteps": steps, "endTime": 1,
                                  "writeControl": "timeStep",
                                  "writeInterval": steps,
                                  "writePrecision": 12})
    if nprocs:
        run.write_options(case, "system/decomposeOptions",
                          {"numberOfSubdomains": nprocs, "method": "metis"})
    return case


def files(folder):
    out = {}
    for top, _, names in os.walk(folder):
        for name in names:
            path = os.path.join(top, name)
            with open(path, "rb") as f:
                out[os.path.relpath(path, folder)] = f.read()
    return out


def processor_times(case):
    out = {}
    for proc in sorted(d for d in os.listdir(case)
                       if d.startswith("processor")):
        for name in run.time_dirs(os.path.join(case, proc)).values():
            if name != "0":
                out[os.path.join(proc, name)] = files(
                    os.path.join(case, proc, name))
    return out


def floors(case):
    mat = cases.material(case)
    E, nu, rho = mat["E"], mat["nu"], mat["rho"]
    Up = np.sqrt(E*(1 - nu)/((1 + nu)*(1 - 2*nu))/rho)
    from touchfoam.mesh import PolyMesh
    points = PolyMesh(case).points
    size = float((points.max(axis=0) - points.min(axis=0)).max())
    return {"lm": rho*Up, "F": 1.0, "D": size, "pointD": size}


def one(root, tutorial, n, steps, failures, lines):
    tag = tutorial + "-"
    serial = prepare(root, tag + "serial", tutorial, n, 2*steps)
    run.run(["touchFoam"], serial, timeout=testing.RUN_TIMEOUT)
    end = os.path.basename(run.latest_time_dir(serial))

    runs = {}
    for label in ("par2", "par2again"):
        case = prepare(root, tag + label, tutorial, n, 2*steps, 2)
        run.run(["decomposePar", "-force"], case)
        run.run_parallel(["touchFoam"], case, 2,
                         timeout=testing.RUN_TIMEOUT)
        runs[label] = processor_times(case)
        if label == "par2":
            par2 = case
    a, b = runs["par2"], runs["par2again"]
    same = sum(1 for t in a for f in a[t] if b.get(t, {}).get(f) == a[t][f])
    total = sum(len(a[t]) for t in a)
    if same != total or set(a) != set(b):
        failures.append("%s: a second 2-rank run wrote %d of %d files "
                        "differently" % (tutorial, total - same, total))

    restart = prepare(root, tag + "restart2", tutorial, n, steps, 2)
    run.run(["decomposePar", "-force"], restart)
    run.run_parallel(["touchFoam"], restart, 2, timeout=testing.RUN_TIMEOUT)
    run.run_parallel(["touchFoam"], restart, 2, name="touchFoam.2",
                     timeout=testing.RUN_TIMEOUT)
    c = processor_times(restart)
    differ = [(t, f) for t in a if t.endswith(os.sep + end)
              for f in ("lm", "F", "D", "pointD", "U")
              if c.get(t, {}).get(f) != a[t].get(f)]
    if differ or not any(t.endswith(os.sep + end) for t in c):
        failures.append("%s: the 2-rank restart differs from the straight "
                        "2-rank run at %s: %s" % (tutorial, end, differ[:4]))

    change = prepare(root, tag + "change", tutorial, n, steps, 2)
    run.run(["decomposePar", "-force"], change)
    run.run_parallel(["touchFoam"], change, 2, timeout=testing.RUN_TIMEOUT)
    # reconstructPar and decomposePar write at writePrecision: 17 digits
    # for them, so that the state keeps its doubles (the tutorials' 12
    # lose them: see the docstring)
    run.foam_set(change, "system/controlDict", "writePrecision", 17)
    run.run(["reconstructPar", "-latestTime"], change)
    run.write_options(change, "system/decomposeOptions",
                      {"numberOfSubdomains": 3, "method": "metis"})
    run.run(["decomposePar", "-force", "-latestTime"], change,
            name="decomposePar.3")
    run.foam_set(change, "system/controlDict", "writePrecision", 12)
    run.run_parallel(["touchFoam"], change, 3, name="touchFoam.3",
                     timeout=testing.RUN_TIMEOUT)
    procs = sorted(d for d in os.listdir(change) if d.startswith("processor"))
    if len(procs) != 3 or not all(
            os.path.isdir(os.path.join(change, p, end)) for p in procs):
        failures.append("%s: the 3-rank part did not reach %s on 3 "
                        "processors (%s)" % (tutorial, end, procs))
        return
    for case in (change, par2):
        run.foam_set(case, "system/controlDict", "writePrecision", 17)
        run.run(["reconstructPar", "-latestTime"], case,
                name="reconstructPar.end")
    floor = floors(serial)
    diffs = []
    for field in STATE:
        s = np.asarray(foamfile.read_field(
            os.path.join(serial, end, field)).internal(), float)
        scale = max(np.abs(s).max(), floor[field])
        d = {}
        for label, case in (("change", change), ("par2", par2)):
            p = np.asarray(foamfile.read_field(
                os.path.join(case, end, field)).internal(), float)
            d[label] = np.abs(p - s).max()/scale
        diffs.append("%s %.1e (2 ranks throughout %.1e)"
                     % (field, d["change"], d["par2"]))
        if not d["change"] <= max(TOLERANCE, 2*d["par2"]):
            failures.append("%s: 2 -> 3 ranks, %s at %s differs from serial "
                            "by %.2e, 2 ranks throughout by %.2e"
                            % (tutorial, field, end, d["change"], d["par2"]))
    lines.append("%s: 2 -> 3 ranks at step %d vs serial at step %d: %s; "
                 "second 2-rank run identical in %d of %d files; 2-rank "
                 "restart identical at the end"
                 % (tutorial, steps, 2*steps, ", ".join(diffs), same, total))


def body(steps):
    root = testing.work_dir(NAME)
    failures, lines = [], []
    one(root, "twistingColumn", 2, steps, failures, lines)
    one(root, "barRebound", 3, steps, failures, lines)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=40)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args.steps)))
