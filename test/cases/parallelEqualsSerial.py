#!/usr/bin/python3
"""A decomposed run gives the serial fields to round-off.

    /usr/bin/python3 test/cases/parallelEqualsSerial.py [--steps 50]

For swingingCube (8^3), twistingColumn (4 x 24 x 4), spinningCube (6^3) and unstructuredCube
(6 x 4^3 tets): run a fixed number of steps (controlDict 'maxSteps';
writeControl timeStep) in serial, then decomposed with metis on 2 and 4
ranks (4 > cores: --oversubscribe) and scotch on 2, plus 'simple' (2 1 2)
for the column so that the clamped base is cut between processors.
After reconstructPar every written field (lm U F P sigma sigmaEq pressure
J D pointD) must match the serial one:

    max|q_parallel - q_serial| / max(max|q_serial|, floor_q) <= 1e-12

(internal values, all components of a field together).  The floor is the
size q takes for an O(1) deformation, i.e. the scale at which round-off
of the state (F ~ 1, positions ~ body size) enters q: 1 for F and J,
lambda + 2 mu for P, sigma, sigmaEq and pressure, U_p for U, rho0 U_p for
lm and the body size for D and pointD.  Without it, sums taken in another order
(the global reductions of the angular momentum correction) make
last-digit differences in F that small-strain stresses magnify: on the
swinging cube (|F - I| ~ 3e-4) F agrees to 9e-16 but P only to 1.6e-12
of max|P|.  A decomposition error is O(1) on either scale.  Output is
written with 17 digits so that printing does not round the comparison.
Also checks that some decomposition splits the clamped base (column) or
the symmetry planes (cubes) between two or more processors.
Work folders: test/runs/parallelEqualsSerial/.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import (analytic, cases, foamfile, mesh, monitor,  # noqa: E402
                       run, testing)

NAME = "parallelEqualsSerial"
TOL = 1e-12
FIELDS = ["lm", "U", "F", "P", "sigma", "sigmaEq", "pressure", "J", "D",
          "pointD"]
# (tutorial, n, patch that some decomposition must split)
CASES = [("swingingCube", 8, "X0"), ("twistingColumn", 4, "base"),
         ("unstructuredCube", 4, "X0"), ("spinningCube", 6, "surface")]
DECOMPOSITIONS = [
    ("metis2", {"method": "metis", "numberOfSubdomains": 2}),
    ("metis4", {"method": "metis", "numberOfSubdomains": 4}),
    ("scotch2", {"method": "scotch", "numberOfSubdomains": 2}),
]
COLUMN_EXTRA = [
    ("simple212", {"method": "simple", "numberOfSubdomains": 4,
                   "simpleCoeffs": {"n": "(2 1 2)", "delta": 0.001}}),
]


def control(steps):
    # The solver picks dt from the CFL number, so stop on a step count.
    # endTime is only a bound in case maxSteps were ignored.
    c = cases.precise_output()
    c.update({"maxSteps": steps, "writeControl": "timeStep",
              "writeInterval": steps, "endTime": 100, "startFrom": "startTime",
              "startTime": 0})
    return c


def floors(case, m):
    """{field: difference scale of an O(1) deformation} (see above)."""
    mat = cases.material(case)
    lam, mu = analytic.lame(mat["E"], mat["nu"])
    Up = analytic.p_wave_speed(mat["E"], mat["nu"], mat["rho"])
    size = float(np.abs(m.points).max())
    return {"F": 1.0, "J": 1.0, "P": lam + 2 * mu, "sigma": lam + 2 * mu,
            "sigmaEq": lam + 2 * mu, "pressure": lam + 2 * mu, "U": Up,
            "lm": mat["rho"] * Up, "D": size, "pointD": size}


def compare(serial, parallel, m):
    """{field: (scaled difference, plain relative difference)} at the
    latest serial time."""
    tdir = run.latest_time_dir(serial)
    name = os.path.basename(tdir)
    pdir = os.path.join(parallel, name)
    if not os.path.isdir(pdir):
        # Same number of steps but another end time: the CFL step, which
        # depends on the state, differed, so the states differ
        raise AssertionError(
            "%s: serial run ended at t = %s, parallel (reconstructed) at %s: "
            "the time steps, so the states, differ (see log.touchFoam)"
            % (os.path.relpath(parallel, os.path.dirname(serial)), name,
               sorted(run.time_dirs(parallel).values())[-1]))
    diffs = {}
    floor = floors(serial, m)
    for field in FIELDS:
        path = os.path.join(tdir, field)
        if not os.path.exists(path):
            raise AssertionError("serial run did not write %s/%s"
                                 % (name, field))
        n = m.points.shape[0] if field == "pointD" else m.n_cells
        a = foamfile.read_field(path).internal(n)
        b = foamfile.read_field(os.path.join(pdir, field)).internal(n)
        diffs[field] = (testing.relative_max_difference(b, a, floor[field]),
                        testing.relative_max_difference(b, a))
    return diffs


def check_case(root, tutorial, n, cut_patch, steps):
    """Serial run, then every decomposition; returns the summary."""
    serial = cases.prepare(tutorial, os.path.join(root, tutorial, "serial"),
                           n=n, control=control(steps))
    run.run(["touchFoam"], serial, timeout=testing.RUN_TIMEOUT)
    nsteps = len(monitor.read_monitor(serial)["Time"])
    m = mesh.PolyMesh(serial)
    decomps = DECOMPOSITIONS + (
        COLUMN_EXTRA if tutorial == "twistingColumn" else [])
    worst, worst_plain, max_split = 0.0, 0.0, 0
    worst_plain_field = ""
    for label, decomp in decomps:
        case = cases.prepare(tutorial, os.path.join(root, tutorial, label),
                             n=n, control=control(steps))
        run.write_options(case, "system/decomposeOptions", decomp)
        run.run(["decomposePar", "-force"], case)
        nprocs = decomp["numberOfSubdomains"]
        max_split = max(max_split, mesh.split_count(case, nprocs, cut_patch))
        run.run_parallel(["touchFoam"], case, nprocs,
                         timeout=testing.RUN_TIMEOUT)
        run.run(["reconstructPar"], case)
        diffs = compare(serial, case, m)
        bad = {f: d for f, (d, _) in diffs.items() if d > TOL}
        if bad:
            raise AssertionError("%s %s differs from serial: %s" % (
                tutorial, label, ", ".join("%s %.2e" % fd
                                           for fd in sorted(bad.items()))))
        worst = max([worst] + [d for d, _ in diffs.values()])
        for field, (_, d) in diffs.items():
            if d > worst_plain:
                worst_plain, worst_plain_field = d, "%s %s" % (field, label)
    if max_split < 2:
        raise AssertionError("%s: no decomposition splits patch %s"
                             % (tutorial, cut_patch))
    return ("%s %d cells %d steps: max diff %.1e (plain %.1e in %s), %s on "
            "up to %d procs" % (tutorial, m.n_cells, nsteps, worst,
                                worst_plain, worst_plain_field,
                          cut_patch, max_split))


def body(steps):
    root = testing.work_dir(NAME)
    report, failures = [], []
    for tutorial, n, cut_patch in CASES:
        # Carry on after a failing case so that one run reports them all
        try:
            report.append(check_case(root, tutorial, n, cut_patch, steps))
        except (AssertionError, run.RunError) as err:
            failures.append(str(err).split("\n")[0])
    if failures:
        raise AssertionError("; ".join(failures + report))
    return "; ".join(report)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=50)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args.steps)))
