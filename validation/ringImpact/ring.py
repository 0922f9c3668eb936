#!/usr/bin/python3
"""Ring impact (doc/benchmarks.md 5): linear and angular momentum on two
meshes (issue 10, acceptance 3).

    ./ring.py [--n 96 384] [--end-time T] [--no-run]

For each n, copies tutorials/ringImpact to runs/n<n>/ and runs its
'./Allrun -n n' (n cells around the ring, round(n/22) across it: 96 is the
default, 384 cells; 384 gives 6528; the seed's mesh study has 420 and
6400), to the tutorial's 0.18 s, writes every 5 ms, one case at a time.
The ring is a one-cell slab of thickness T = 0.01 m between symmetric
planes (the tutorial's choice), centred on the origin, so the monitor's
angular momentum (about the origin) is the one about the ring's initial
centre.  From the solidMonitor (one row per step), per metre of thickness
(divided by T, as the tutorial's plot.py):

  p_y          p_y(0) from 0/lm (sum V p over the cells), the last p_y,
               the first step with p_y > 0 (reversal: p_y(0) < 0 and the
               last p_y > 0), and the contact interval (first and last
               step with a face in contact);
  p_x, p_z     max over the steps of |p_x|, |p_z| / |p_y(0)| (pass
               < 1e-8);
  L            max over the steps of |L_x|, |L_y|, |L_z| /
               (|p_y(0)| R_outer), R_outer = 0.04 (pass < 1e-8), and when
               the largest occurs;
  energy       max over the steps of (E_n - E_n-1) / E0 (information);
  end of       the contact duration (last minus first step in contact),
  contact      the rebound velocity v_y / v0 = p_y / |p_y(0)| and the
               total energy / E0 at the first step after the last one in
               contact (the ring free again).

With three meshes (each with twice the cells around the ring of the one
before) the three end-of-contact quantities are extrapolated
(Richardson: observed order p = log2((f1 - f2)/(f2 - f3)), converged
value f3 + (f3 - f2)/(2^p - 1)); where the differences change sign the
finest value is given with |f3 - f2| as its uncertainty.  These are the
references of test/cases/ringReference.py (validation/ringImpact/
FINDINGS.md 5).  --end-time T stops the runs at T (the contact ends
before 0.045 s; the seed's figure 9 ends at 0.04 s) instead of the
tutorial's 0.18 s.

Writes results.json, results.md and momentum.png (matplotlib: p and L per
metre on both meshes, as seed figure 9, and their normalised magnitudes
on a log scale).  Wall times: touchFoam's ClockTime and the whole Allrun
(mesh, pictures, the tutorial's own plots), one core, one run at a time.
--no-run re-analyses runs/.
"""

import argparse
import json
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

from touchfoam.provenance import log_steps_and_clock, build_label  # noqa: E402
from touchfoam import checks, postprocess, run  # noqa: E402
from touchfoam.figures import slab_thickness  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

TUTORIAL = "ringImpact"
R_OUTER = 0.04          # outer radius [m]
CONTACT = "contactFaces(wall)"
LIMIT = 1e-8            # |p_x|, |p_z| / |p_y(0)| and |L_i| / (|p_y(0)| R)


def case_dir(n):
    return os.path.join(HERE, "runs", "n%d" % n)


# -- runs ---------------------------------------------------------------------

def run_case(n, end_time=None):
    """Copy of the tutorial at runs/n<n>, its Allrun -n n; the wall time
    goes to runs/n<n>/wallTime.json."""
    case = case_dir(n)
    print("running %s -n %d in %s" % (TUTORIAL, n, case), flush=True)
    run.copy_case(run.tutorial_dir(TUTORIAL), case)
    if end_time is not None:
        run.foam_set(case, "system/controlDict", "endTime", end_time)
    start = time.time()
    error = None
    try:
        run.run(["./Allrun", "-n", str(n)], case, "Allrun",
                env={"TOUCH_N": ""})
    except run.RunError as err:
        print(err, file=sys.stderr)
        error = str(err).split("\n")[0]
    wall = time.time() - start
    with open(os.path.join(case, "wallTime.json"), "w") as f:
        json.dump({"Allrun_s": wall, "error": error}, f, indent=1)
    print("  done in %.0f s" % wall, flush=True)


# -- measurements -------------------------------------------------------------

def measure(case):
    mesh = PolyMesh(case)
    m = read_monitor(case)
    T = slab_thickness(case, axis=2)
    t, faces = m["Time"], m[CONTACT]
    p, L = m["p"] / T, m["L"] / T
    p0, L0 = (v / T for v in postprocess.initial_momenta(case))
    py0 = abs(p0[1])
    E0 = postprocess.initial_energy(case)
    dE = np.diff(np.concatenate([[E0], m["totalEnergy"]])) / E0
    on = np.nonzero(faces > 0)[0]
    up = np.nonzero(p[:, 1] > 0)[0]
    Lrel = np.abs(L).max(axis=0) / (py0 * R_OUTER)
    steps, clock = log_steps_and_clock(case)
    with open(os.path.join(case, "wallTime.json")) as f:
        wall = json.load(f)
    out = {
        "cells": mesh.n_cells, "thickness": T, "steps": steps,
        "monitorRows": len(t), "endTime": float(t[-1]),
        "touchFoamClockTime_s": clock, "AllrunWallTime_s": wall["Allrun_s"],
        "runError": wall["error"],
        "py0_perMetre": float(p0[1]), "L0_perMetre": L0.tolist(),
        "pyEnd_py0": float(p[-1, 1] / py0),
        "pyMax_py0": float(p[:, 1].max() / py0),
        "pyFirstPositive": float(t[up[0]]) if len(up) else None,
        "pyReverses": bool(p0[1] < 0 and p[-1, 1] > 0),
        "contactStart": float(t[on[0]]) if len(on) else None,
        "contactEnd": float(t[on[-1]]) if len(on) else None,
        "maxFacesInContact": int(faces.max()),
        "maxPx_py0": float(np.abs(p[:, 0]).max() / py0),
        "maxPz_py0": float(np.abs(p[:, 2]).max() / py0),
        "maxL_py0R": Lrel.tolist(),
        "maxLTime": [float(t[np.abs(L[:, i]).argmax()]) for i in range(3)],
        "maxEnergyChangePerStep_E0": float(dE.max()),
        "endEnergy_E0": float(m["totalEnergy"][-1] / E0),
    }
    # The ring free again: the first step after the last one in contact
    if len(on) and on[-1] + 1 < len(t):
        free = on[-1] + 1
        out["contactDuration"] = float(t[on[-1]] - t[on[0]])
        out["reboundVelocity_v0"] = float(p[free, 1] / py0)
        out["energyEndOfContact_E0"] = float(m["totalEnergy"][free] / E0)
    out["linearPass"] = bool(max(out["maxPx_py0"], out["maxPz_py0"]) < LIMIT)
    out["angularPass"] = bool(Lrel.max() < LIMIT)
    # The histories for the plot (not in results.json: every step)
    out["_history"] = (t, p, L, py0)
    return out


# -- output -------------------------------------------------------------------

def yes(flag):
    return {True: "yes", False: "NO", None: "-"}[flag]


def write_markdown(out, path):
    ms = 1e3
    lines = [
        "# Ring impact on %d meshes: linear and angular momentum, end of "
        "contact" % len(out["meshes"]), "",
        "Generated by ring.py (`./Allrun`) on %s, build %s.  Rubber ring "
        "Ri = 0.03, Ro = 0.04 m, one-cell slab T = %.3g m between symmetric "
        "planes (plane strain), neo-Hookean, v0 = -0.59 m/s, to %.3g s "
        "(tutorial settings, writes every 5 ms).  Momenta per metre of "
        "thickness; p_y(0) = sum V p of 0/lm; maxima over every step of "
        "the solidMonitor; L about the origin, the ring's initial centre; "
        "bound %.0e for p_x, p_z (/|p_y(0)|) and every L component "
        "(/|p_y(0)| R_outer, R_outer = %.2f m).  Wall: touchFoam "
        "ClockTime / whole Allrun (one core, shared machine)." % (
            out["date"], out["build"], out["thickness"], out["endTime"],
            LIMIT, R_OUTER), "",
        "| -n | cells | steps | p_y(0) [kg/s per m] | contact [ms] "
        "| p_y > 0 from [ms] | p_y end / |p_y(0)| | reverses "
        "| max |p_x| | max |p_z| | max |L_x| | max |L_y| | max |L_z| "
        "| pass p / L | max dE/E0 per step | wall [s] |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for n, r in out["meshes"].items():
        lines.append(
            "| %s | %d | %d | %.5g | %.2f - %.2f | %.2f | %.4f | %s | %.1e "
            "| %.1e | %.1e | %.1e | %.1e | %s / %s | %.1e | %.0f / %.0f |%s"
            % (n, r["cells"], r["steps"], r["py0_perMetre"],
               ms * r["contactStart"], ms * r["contactEnd"],
               ms * r["pyFirstPositive"], r["pyEnd_py0"],
               yes(r["pyReverses"]), r["maxPx_py0"], r["maxPz_py0"],
               r["maxL_py0R"][0], r["maxL_py0R"][1], r["maxL_py0R"][2],
               yes(r["linearPass"]), yes(r["angularPass"]),
               r["maxEnergyChangePerStep_E0"], r["touchFoamClockTime_s"],
               r["AllrunWallTime_s"],
               " run failed: %s" % r["runError"] if r["runError"] else ""))
    lines += ["", "p_x, p_z relative to |p_y(0)|; L relative to |p_y(0)| "
              "R_outer; the largest |L_z| at %s ms."
              % ", ".join("%.2f (-n %s)" % (ms * r["maxLTime"][2], n)
                          for n, r in out["meshes"].items())]
    ends = [(n, r) for n, r in out["meshes"].items()
            if "contactDuration" in r]
    if ends:
        lines += ["", "End of contact (the first step after the last one "
                  "in contact):", "",
                  "| -n | cells | contact duration [ms] | v_y / v0 "
                  "| E / E0 |", "|---|---|---|---|---|"]
        lines += ["| %s | %d | %.4f | %.4f | %.4f |"
                  % (n, r["cells"], ms * r["contactDuration"],
                     r["reboundVelocity_v0"], r["energyEndOfContact_E0"])
                  for n, r in ends]
    for key, rich in out.get("richardson", {}).items():
        lines.append("")
        lines.append("Richardson, %s: %s" % (key, rich["text"]))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


END_OF_CONTACT = ("contactDuration", "reboundVelocity_v0",
                  "energyEndOfContact_E0")


def richardson(f1, f2, f3):
    """Converged value from three meshes refined by 2: (value,
    uncertainty, observed order or None, how)."""
    d1, d2 = f1 - f2, f2 - f3
    if d1 * d2 > 0 and abs(d2) < abs(d1):
        p = float(np.log2(d1 / d2))
        value = f3 + (f3 - f2) / (2 ** p - 1)
        return value, abs(value - f3), p, \
            "order %.2f, converged %.5g (finest %.5g)" % (p, value, f3)
    return f3, abs(d2), None, \
        "differences %.3g, %.3g do not fall monotonically: the finest " \
        "value %.5g, uncertainty |f3 - f2| = %.2g" % (d1, d2, f3, abs(d2))


def plot(meshes, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: %s skipped" % os.path.basename(path))
        return
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 9))
    styles = [":", "--", "-"][-len(meshes):]
    for (n, r), ls in zip(meshes.items(), styles):
        t, p, L, py0 = r["_history"]
        label = "%d cells" % r["cells"]
        for i, c in enumerate("xyz"):
            axes[0].plot(1e3 * t, p[:, i], ls, color="C%d" % i, lw=1.2,
                         label="p_%s, %s" % (c, label))
            axes[1].plot(1e3 * t, L[:, i], ls, color="C%d" % i, lw=1.2,
                         label="L_%s, %s" % (c, label))
        tiny = 1e-300           # exact zeros on the log scale
        for i, (y, name) in enumerate((
                (np.abs(p[:, 0]) / py0, "|p_x| / |p_y(0)|"),
                (np.abs(p[:, 2]) / py0, "|p_z| / |p_y(0)|"),
                (np.linalg.norm(L, axis=1) / (py0 * R_OUTER),
                 "|L| / (|p_y(0)| R_outer)"))):
            axes[2].semilogy(1e3 * t, np.maximum(y, tiny), ls,
                             color="C%d" % (i + 3), lw=1.0,
                             label="%s, %s" % (name, label))
    axes[2].axhline(LIMIT, color="k", lw=0.8, ls=":", label="bound 1e-8")
    axes[2].set_ylim(1e-20, 1e-6)
    axes[0].set_ylabel("linear momentum [kg/s per m]")
    axes[1].set_ylabel("angular momentum\nabout the initial centre "
                       "[kg m/s per m]")
    axes[2].set_ylabel("relative magnitude")
    axes[2].set_xlabel("time [ms]")
    for ax in axes:
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7, ncol=2)
    fig.suptitle("Ring impact: momenta per metre of thickness")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print("wrote %s" % path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[96, 384],
                        help="cells around the ring (multiples of 4); three "
                        "meshes refined by 2 give the Richardson "
                        "extrapolation of the end of contact")
    parser.add_argument("--end-time", type=float,
                        help="stop the runs at this time (default: the "
                        "tutorial's 0.18 s)")
    parser.add_argument("--no-run", action="store_true",
                        help="only post-process the existing runs")
    args = parser.parse_args()
    args.n = sorted(args.n)
    try:
        if not args.no_run:
            run.check_openfoam()
            for n in args.n:
                run_case(n, args.end_time)
        meshes = {str(n): measure(case_dir(n)) for n in args.n}
        first = next(iter(meshes.values()))
        out = {"date": time.strftime("%Y-%m-%d", time.localtime(
                   os.path.getmtime(os.path.join(case_dir(args.n[-1]),
                                                 "wallTime.json")))),
               "build": build_label(), "R_outer": R_OUTER, "limit": LIMIT,
               "thickness": first["thickness"], "endTime": first["endTime"],
               "meshes": {n: {k: v for k, v in r.items()
                              if not k.startswith("_")}
                          for n, r in meshes.items()}}
        rs = list(out["meshes"].values())
        if len(rs) == 3 and all(k in r for r in rs for k in END_OF_CONTACT):
            out["richardson"] = {}
            for key in END_OF_CONTACT:
                value, err, order, text = richardson(*[r[key] for r in rs])
                out["richardson"][key] = {"value": value, "uncertainty": err,
                                          "order": order, "text": text}
    except (run.RunError, OSError, ValueError, KeyError) as err:
        print("ring: %s" % err, file=sys.stderr)
        return 1
    with open(os.path.join(HERE, "results.json"), "w") as f:
        json.dump(out, f, indent=1)
    write_markdown(out, os.path.join(HERE, "results.md"))
    plot(meshes, os.path.join(HERE, "momentum.png"))
    with open(os.path.join(HERE, "results.md")) as f:
        print(f.read())
    record_checks(out)
    return checks.status(HERE)


def record_checks(out):
    """The verdicts of results.md in checks.json (validation/Allrun)."""
    for n, r in out["meshes"].items():
        checks.record(HERE, "n%s max |p_x|, |p_z| / |p_y(0)|" % n,
                      max(r["maxPx_py0"], r["maxPz_py0"]), "< %g" % LIMIT,
                      r["linearPass"])
        checks.record(HERE, "n%s max |L_i| / (|p_y(0)| R_outer)" % n,
                      max(r["maxL_py0R"]), "< %g" % LIMIT, r["angularPass"])
        checks.record(HERE, "n%s p_y reverses (the ring rebounds)" % n,
                      r["pyEnd_py0"], "p_y end > 0 > p_y(0)",
                      r["pyReverses"], "p_y end / |p_y(0)|")


if __name__ == "__main__":
    sys.exit(main())
