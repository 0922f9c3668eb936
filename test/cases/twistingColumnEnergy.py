#!/usr/bin/python3
"""Twisting column: energy never grows, no locking as nu -> 0.5.

    /usr/bin/python3 test/cases/twistingColumnEnergy.py [--n 8] [--end 0.3]

Runs tutorials/twistingColumn on n x 6n x n cells (default 8 x 48 x 8, the
size of issue 3's acceptance; about 2.5 minutes on one core)
for nu = 0.45 and nu = 0.495 to t = end (default 0.3 s), writing every
0.01 s.  Asserts, for both runs, that the total energy of the solidMonitor
never grows from one step to the next by more than 1e-12 of the initial
energy (E_0 = sum V |p|^2 / (2 rho0) of p = rho0 0/U), and that the mean twist of
the top face at t = 0.1 s (pointD, points at least 0.25 from the axis) is
the same for both nu within 10 % (|a - b| / max(|a|, |b|)): a locking
scheme would twist less as nu -> 0.5.  And the energy the scheme
dissipates by t = end falls with the mesh at least at order 1.5: nu =
0.45 once more on n/2 x 3n x n/2 cells, order log2(loss(n/2) / loss(n)),
loss = 1 - E(end)/E_0 (the compatible update's linear jump share
dissipated at first order: 1.24 on 4 -> 8 at the tutorial's settings,
the quadratic one 1.77).
Work folders: test/runs/twistingColumnEnergy/.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, postprocess, run, testing  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

NAME = "twistingColumnEnergy"
T_TWIST = 0.1


def column(root, nu, args, n=None):
    n = n or args.n
    control = cases.precise_output()
    control.update({"endTime": args.end, "writeInterval": 0.01})
    label = "nu%s" % nu if n == args.n else "nu%s_n%d" % (nu, n)
    case = cases.prepare("twistingColumn", os.path.join(root, label),
                         n=n, nu=nu, control=control)
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    E0 = postprocess.initial_energy(case)
    growth, _, samples = postprocess.energy_increase(case, reference=E0)
    twist = dict(postprocess.column_twist(case, t_end=T_TWIST))
    if not any(abs(t - T_TWIST) < 1e-9 for t in twist):
        raise AssertionError("nu %s: no write time at t = %g" % (nu, T_TWIST))
    angle = [a for t, a in twist.items() if abs(t - T_TWIST) < 1e-9][0]
    loss = 1 - read_monitor(case)["totalEnergy"][-1] / E0
    return {"growth": growth, "samples": samples, "twist": angle,
            "loss": loss}


def body(args):
    root = testing.work_dir(NAME)
    results = {nu: column(root, nu, args) for nu in (0.45, 0.495)}
    a, b = results[0.45]["twist"], results[0.495]["twist"]
    diff = abs(a - b) / max(abs(a), abs(b))
    coarse = column(root, 0.45, args, n=max(args.n // 2, 1))
    order = math.log(coarse["loss"] / results[0.45]["loss"]) / math.log(
        args.n / max(args.n // 2, 1))
    summary = ("%dx%dx%d to t=%g: max energy growth/E0 %.1e (nu 0.45), "
               "%.1e (nu 0.495); twist at t=0.1 %.4f / %.4f rad, diff %.1f %%"
               % (args.n, 6 * args.n, args.n, args.end,
                  results[0.45]["growth"], results[0.495]["growth"], a, b,
                  100 * diff)
               + "; dissipated by t=%g: %.4f E0 (n %d), %.4f E0 (n %d), "
               "order %.2f" % (args.end, coarse["loss"], max(args.n // 2, 1),
                               results[0.45]["loss"], args.n, order))
    if coarse["growth"] > args.energy_tol:
        raise AssertionError("coarse mesh: total energy grew by %.2e E0 in a "
                             "step (%s)" % (coarse["growth"], summary))
    for nu, r in results.items():
        if r["growth"] > args.energy_tol:
            raise AssertionError("nu %s: total energy grew by %.2e E0 in a "
                                 "step (%s)" % (nu, r["growth"], summary))
    if diff > args.twist_tol:
        raise AssertionError("twist angles differ by %.1f %% (%s)"
                             % (100 * diff, summary))
    if not order >= args.loss_order:
        raise AssertionError("the dissipated energy falls at order %.2f < "
                             "%g (%s)" % (order, args.loss_order, summary))
    return summary


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, default=8)
    parser.add_argument("--end", type=float, default=0.3)
    parser.add_argument("--energy-tol", type=float, default=1e-12)
    parser.add_argument("--twist-tol", type=float, default=0.1)
    parser.add_argument("--loss-order", type=float, default=1.5)
    args = parser.parse_args()
    if args.end < T_TWIST:
        parser.error("--end must be at least %g" % T_TWIST)
    sys.exit(testing.run_test(NAME, lambda: body(args)))
