#!/usr/bin/python3
"""Twisting column (doc/benchmarks.md section 2): energy and locking.

    ./twist.py [--n 8] [--nu 0.45 0.495] [--end 0.3] [--no-run]

Runs a copy of tutorials/twistingColumn on n x 6n x n cells (default
8 x 48 x 8) for each nu, in runs/nu<nu>/, to t = end (default 0.3 s),
writing every 0.01 s, and reports

  (a) energy: max over successive solidMonitor samples of
      (E_{n+1} - E_n) / E_0, E_0 = sum V |p|^2 / (2 rho0) of 0/lm; the
      total energy must never grow: pass when <= 1e-10;
  (b) twist: mean rotation about +Y of the top-face points (pointD, points
      at least 0.25 from the axis) at t = 0.1 s, unwrapped through the
      0.01 s writes; pass when the values for the two nu differ by less
      than 10 % of the larger (a locking scheme twists less as nu -> 0.5).

A run that stops early (e.g. a floating-point exception) is reported with
what it wrote.  Writes results.json (and twist.png when matplotlib is
available).
"""

import argparse
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

from touchfoam import cases, checks, postprocess, run  # noqa: E402

T_TWIST = 0.1
ENERGY_TOL = 1e-10
TWIST_TOL = 0.1


def case_dir(nu):
    return os.path.join(HERE, "runs", "nu%s" % nu)


def run_all(args):
    """Run every nu; {nu: error message} of the runs that failed."""
    failed = {}
    for nu in args.nu:
        print("running nu = %s in %s" % (nu, case_dir(nu)), flush=True)
        control = cases.precise_output()
        control.update({"endTime": args.end, "writeInterval": 0.01})
        cases.prepare("twistingColumn", case_dir(nu), n=args.n, nu=nu,
                      control=control)
        try:
            run.run(["touchFoam"], case_dir(nu))
        except run.RunError as err:
            # Keep going: the part that ran is still analysed and reported
            print(err, file=sys.stderr)
            failed[str(nu)] = str(err).split("\n")[0]
    return failed


def analyse(args, failed):
    out = {"mesh": [args.n, 6 * args.n, args.n], "endTime": args.end,
           "energyTolerance": ENERGY_TOL, "twistTolerance": TWIST_TOL,
           "twistTime": T_TWIST, "runs": {}}
    for nu in args.nu:
        case = case_dir(nu)
        E0 = postprocess.initial_energy(case)
        growth, _, samples = postprocess.energy_increase(case, reference=E0)
        history = postprocess.column_twist(case)
        at = [a for t, a in history if abs(t - T_TWIST) < 1e-9]
        out["runs"][str(nu)] = {
            "runError": failed.get(str(nu)),
            "lastTime": history[-1][0],
            "initialEnergy": E0,
            "monitorSamples": samples,
            "maxEnergyIncreaseRelative": growth,
            "energyPass": bool(growth <= ENERGY_TOL
                               and str(nu) not in failed),
            "twistAt0.1": at[0] if at else None,
            "twistHistory": history,
        }
    twists = [r["twistAt0.1"] for r in out["runs"].values()]
    if len(twists) >= 2:
        if None in twists:
            out["twistRelativeDifference"] = None
            out["twistPass"] = False
        else:
            diff = (max(twists) - min(twists)) / max(abs(t) for t in twists)
            out["twistRelativeDifference"] = diff
            out["twistPass"] = bool(diff < TWIST_TOL)
    out["pass"] = bool(all(r["energyPass"] for r in out["runs"].values())
                       and out.get("twistPass", True))
    return out


def plot(out, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: %s skipped" % os.path.basename(path))
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    for nu, r in out["runs"].items():
        t, a = zip(*r["twistHistory"])
        ax.plot(t, a, "o-", ms=3, label="nu = %s" % nu)
    ax.axvline(T_TWIST, color="k", lw=0.5)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("mean top-face twist [rad]")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print("wrote %s" % path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, default=8)
    parser.add_argument("--nu", type=float, nargs="+", default=[0.45, 0.495])
    parser.add_argument("--end", type=float, default=0.3)
    parser.add_argument("--no-run", action="store_true",
                        help="only post-process the existing runs")
    args = parser.parse_args()
    if args.end < T_TWIST:
        parser.error("--end must be at least %g" % T_TWIST)
    try:
        failed = {}
        if not args.no_run:
            run.check_openfoam()
            failed = run_all(args)
        out = analyse(args, failed)
    except (run.RunError, OSError, ValueError) as err:
        print("twist: %s" % err, file=sys.stderr)
        return 1
    with open(os.path.join(HERE, "results.json"), "w") as f:
        json.dump(out, f, indent=2)
    plot(out, os.path.join(HERE, "twist.png"))
    for nu, r in out["runs"].items():
        print("nu %-6s to t = %-6g max energy increase/E0 %.2e  twist(0.1) %s"
              "%s" % (nu, r["lastTime"], r["maxEnergyIncreaseRelative"],
                      "-" if r["twistAt0.1"] is None
                      else "%.4f rad" % r["twistAt0.1"],
                      "  (run failed)" if r["runError"] else ""))
    if out.get("twistRelativeDifference") is not None:
        print("twist difference %.1f %%"
              % (100 * out["twistRelativeDifference"]))
    for nu, r in out["runs"].items():
        checks.record(HERE, "nu %s max energy increase / E0" % nu,
                      r["maxEnergyIncreaseRelative"], "<= %g" % ENERGY_TOL,
                      r["energyPass"], "run failed: %s" % r["runError"]
                      if r["runError"] else "")
    if "twistPass" in out:
        checks.record(HERE, "twist(0.1 s) relative difference between nu",
                      out["twistRelativeDifference"], "< %g" % TWIST_TOL,
                      out["twistPass"])
    print("%s: results.json" % ("PASS" if out["pass"] else "FAIL"))
    return 0 if out["pass"] and not checks.status(HERE) else 1


if __name__ == "__main__":
    sys.exit(main())
