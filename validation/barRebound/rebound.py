#!/usr/bin/python3
"""Bar rebound (doc/benchmarks.md 4): contact, separation, energy and the
end displacements on two meshes (issue 10, acceptance 2).

    ./rebound.py [--n 6 12] [--write 5e-6] [--no-run]

For each n, copies tutorials/barRebound to runs/n<n>/, sets its
controlDict's writeInterval to --write (default 5 us, the tutorial writes
every 10 us) and runs its './Allrun -n n' (n cells across the radius of
the quarter bar: 6 is the default, 1952 cells; 12 gives 15616), one case
at a time.  From the solidMonitor (one row per step; contactFaces(wall):
the faces in contact at some Runge-Kutta stage of the step):

  contact      t_c, the end of the first step with a face in contact, and
               that step's size dt; pass when 0 <= t_c - gap/v0 <= dt
               (gap/v0 = 0.004/150 = 26.67 us: the contact began inside
               the step);
  separation   t_s, the end of the last step with a face in contact;
               steps between t_c and t_s without a face in contact are
               counted (a bounce would show there);
  agreement    |t_s(coarse) - t_s(fine)| / t_s(fine); pass <= 5 %;
  energy       max_n (E_n - E_{n-1}) / E0 over the steps, E_{-1} = E0 =
               sum V |p|^2 / (2 rho0) of 0/lm (the total energy of the
               monitor); pass when <= 1e-10 (never increases);
  flight       after t_s: the number of steps and their time span, none
               with a face in contact, min p_y / |p_y(0)| (pass > 0: the
               bar moves away), and the height of the lowest point of the
               bar above the wall at the last written time.

End displacements (seed figure 7): u_y from pointD in the time folders at
two fixed point labels, the mesh points at the centre of the top face
(0, gap + L, 0) and of the bottom face (0, gap, 0) (both on the axis of
the quarter model; the labels and their distance to those positions are
reported), with u = 0 at t = 0.

Writes results.json, results.md and displacement.png (matplotlib).  Wall
times: touchFoam's ClockTime and the whole Allrun (mesh, pictures, the
tutorial's own plots), one core, one run at a time.  --no-run re-analyses
runs/.
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
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

TUTORIAL = "barRebound"
GAP = 0.004             # initial gap to the wall y = 0 [m]
LENGTH = 0.0324         # bar length [m]
V0 = 150.0              # impact speed [m/s]
CONTACT = "contactFaces(wall)"
LIMITS = {"separationAgreement": 0.05, "energyIncrease": 1e-10}
PROBES = {"top": (0.0, GAP + LENGTH, 0.0), "bottom": (0.0, GAP, 0.0)}


def case_dir(n):
    return os.path.join(HERE, "runs", "n%d" % n)


# -- runs ---------------------------------------------------------------------

def run_case(n, write):
    """Copy of the tutorial at runs/n<n>, writes every `write` s, its
    Allrun -n n; the wall time goes to runs/n<n>/wallTime.json."""
    case = case_dir(n)
    print("running %s -n %d in %s" % (TUTORIAL, n, case), flush=True)
    run.copy_case(run.tutorial_dir(TUTORIAL), case)
    run.foam_set(case, "system/controlDict", "writeInterval", write)
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
        json.dump({"Allrun_s": wall, "error": error, "writeInterval": write},
                  f, indent=1)
    print("  done in %.0f s" % wall, flush=True)


# -- measurements -------------------------------------------------------------

def probe_histories(case, mesh):
    """{name: {label, offset, t, uy}}: u_y of the mesh points at PROBES
    from pointD of every written time (0 at a time without pointD)."""
    times = run.time_dirs(case)
    out = {}
    for name, X in PROBES.items():
        d = np.linalg.norm(mesh.points - np.asarray(X), axis=1)
        out[name] = {"position": list(X), "label": int(d.argmin()),
                     "offset": float(d.min()), "t": [], "uy": []}
    for t in sorted(times):
        path = os.path.join(case, times[t], "pointD")
        u = read_field(path).internal(len(mesh.points)) \
            if os.path.exists(path) else None
        for probe in out.values():
            probe["t"].append(t)
            probe["uy"].append(0.0 if u is None
                               else float(u[probe["label"], 1]))
    return out


def contact_intervals(t, faces):
    """[[start, end, max faces]]: the runs of steps with a face in
    contact, start and end the ends of their first and last steps."""
    on = np.concatenate([[0], (faces > 0).astype(int), [0]])
    starts = np.nonzero(np.diff(on) == 1)[0]
    ends = np.nonzero(np.diff(on) == -1)[0] - 1
    return [[float(t[a]), float(t[b]), int(faces[a:b + 1].max())]
            for a, b in zip(starts, ends)]


def lowest_point(case, mesh):
    """(time, min current y of the mesh points) at the last written time."""
    folder = run.latest_time_dir(case)
    u = read_field(os.path.join(folder, "pointD")).internal(len(mesh.points))
    return float(os.path.basename(folder)), float((mesh.points + u)[:, 1]
                                                  .min())


def measure(case):
    mesh = PolyMesh(case)
    m = read_monitor(case)
    t, faces, py = m["Time"], m[CONTACT], m["py"]
    E0 = postprocess.initial_energy(case)
    E = np.concatenate([[E0], m["totalEnergy"]])
    dE = np.diff(E) / E0
    on = np.nonzero(faces > 0)[0]
    steps, clock = log_steps_and_clock(case)
    with open(os.path.join(case, "wallTime.json")) as f:
        wall = json.load(f)
    rise = dE > LIMITS["energyIncrease"]
    out = {"cells": mesh.n_cells, "wallFaces": mesh.patch("wall")["nFaces"],
           "steps": steps, "monitorRows": len(t),
           "endTime": float(t[-1]), "writeInterval": wall["writeInterval"],
           "touchFoamClockTime_s": clock, "AllrunWallTime_s": wall["Allrun_s"],
           "runError": wall["error"], "initialEnergy": E0,
           "maxEnergyChangePerStep_E0": float(dE.max()),
           "energyMaxTime": float(t[dE.argmax()]),
           "energyMaxFacesInContact": int(faces[dE.argmax()]),
           "energyRiseSteps": int(rise.sum()),
           "energyRiseTotal_E0": float(dE[rise].sum()),
           "energyRiseTimes": [float(t[rise].min()), float(t[rise].max())]
           if rise.any() else None,
           "endEnergy_E0": float(E[-1] / E0),
           "energyPass": bool(dE.max() <= LIMITS["energyIncrease"])}
    if len(on) == 0:
        out["contactPass"] = False
        return out
    first, last = int(on[0]), int(on[-1])
    dt = float(t[first] - (t[first - 1] if first > 0 else 0.0))
    t_gap = GAP / V0
    after = slice(last + 1, len(t))
    out.update({
        "gapOverV0": t_gap, "contactStart": float(t[first]),
        "contactStep_dt": dt,
        "contactStartMinusGapOverV0": float(t[first] - t_gap),
        "contactPass": bool(0.0 <= t[first] - t_gap <= dt * (1 + 1e-9)),
        "separation": float(t[last]),
        "stepsWithoutContactDuringContact": int(
            np.count_nonzero(faces[first:last + 1] == 0)),
        "contactIntervals": contact_intervals(t, faces),
        "maxFacesInContact": int(faces.max()),
        "stepsAfterSeparation": len(t) - 1 - last,
        "flightSpan": float(t[-1] - t[last]),
        "facesInContactAfterSeparation": int(faces[after].sum()),
        "minPyAfterSeparation_py0": float(py[after].min() / abs(py[0]))
        if last + 1 < len(t) else None,
    })
    out["lowestPointTime"], out["lowestPointHeight"] = lowest_point(case,
                                                                     mesh)
    out["flightPass"] = bool(out["stepsAfterSeparation"] > 0
                             and out["facesInContactAfterSeparation"] == 0
                             and out["minPyAfterSeparation_py0"] > 0)
    out["probes"] = probe_histories(case, mesh)
    return out


# -- output -------------------------------------------------------------------

def yes(flag):
    return {True: "yes", False: "NO", None: "-"}[flag]


def write_markdown(out, path):
    us = 1e6
    lines = [
        "# Bar rebound on two meshes: contact, separation, energy", "",
        "Generated by rebound.py (`./Allrun`) on %s, build %s.  Quarter "
        "bar, neo-Hookean, v0 = 150 m/s, gap 4 mm, CFL 0.3 (tutorial "
        "settings), writes every %.3g us.  Contact: end of the first step "
        "with a face in contact (pass: 0 <= t_c - gap/v0 <= dt of that "
        "step, gap/v0 = %.2f us); separation: end of the last step with a "
        "face in contact; contact intervals: the runs of steps with a face "
        "in contact (max faces of the %s on the wall patch); energy: max "
        "over the steps of (E_n - E_n-1)/E0, E0 the kinetic energy of 0/lm "
        "(pass <= 1e-10); flight: steps after the separation, faces in "
        "contact among them, min p_y/|p_y(0)| (pass > 0), lowest point "
        "above the wall at the end.  Wall: touchFoam ClockTime / whole "
        "Allrun (one core, shared machine)." % (
            out["date"], out["build"], us * out["writeInterval"],
            us * GAP / V0, " and ".join(
                "%d" % r["wallFaces"] for r in out["meshes"].values())), "",
        "| -n | cells | steps | contact [us] | dt [us] | t_c - gap/v0 [us] "
        "| pass | separation [us] | contact intervals [us] (max faces) "
        "| max dE/E0 per step | E_end/E0 | steps after (span us) "
        "| faces after | min p_y/|p_y0| | lowest point [mm] | wall [s] |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for n, r in out["meshes"].items():
        lines.append(
            "| %s | %d | %d | %.3f | %.3f | %+.3f | %s | %.2f | %s | %.2e "
            "| %.4f | %d (%.1f) | %d | %.3f | %.3f at %.0f us | %.0f / %.0f "
            "|%s" % (
                n, r["cells"], r["steps"], us * r["contactStart"],
                us * r["contactStep_dt"],
                us * r["contactStartMinusGapOverV0"], yes(r["contactPass"]),
                us * r["separation"], ", ".join(
                    "%.2f-%.2f (%d)" % (us * a, us * b, k)
                    for a, b, k in r["contactIntervals"]),
                r["maxEnergyChangePerStep_E0"], r["endEnergy_E0"],
                r["stepsAfterSeparation"], us * r["flightSpan"],
                r["facesInContactAfterSeparation"],
                r["minPyAfterSeparation_py0"], 1e3 * r["lowestPointHeight"],
                us * r["lowestPointTime"], r["touchFoamClockTime_s"],
                r["AllrunWallTime_s"],
                " run failed: %s" % r["runError"] if r["runError"] else ""))
    a = out["agreement"]
    lines += [
        "", "Separation times agree to %.2f %% of the finer mesh's (limit "
        "%.0f %%): %s; the end of the first contact interval to %.2f %%.  "
        "Energy never increases: %s.  After separation no face in contact "
        "and p_y > 0: %s." % (
            100 * a["separation"], 100 * LIMITS["separationAgreement"],
            yes(a["pass"]), 100 * a["firstSeparation"],
            yes(all(r["energyPass"] for r in out["meshes"].values())),
            yes(all(r["flightPass"] for r in out["meshes"].values())))]
    for n, r in out["meshes"].items():
        if r["energyRiseSteps"]:
            lines.append(
                "-n %s: the total energy grows in %d steps, %.2f-%.2f us, "
                "by %.2e E0 in all (largest step %.2e E0 at %.2f us, %d "
                "faces in contact)." % (
                    n, r["energyRiseSteps"], us * r["energyRiseTimes"][0],
                    us * r["energyRiseTimes"][1], r["energyRiseTotal_E0"],
                    r["maxEnergyChangePerStep_E0"], us * r["energyMaxTime"],
                    r["energyMaxFacesInContact"]))
    lines += [
        "", "End displacements (displacement.png): u_y of the mesh points "
        "at the centre of the top face (0, gap + L, 0) and of the bottom "
        "face (0, gap, 0), from pointD at the written times; largest "
        "difference between the meshes at the common times, relative to "
        "the largest |u_y| of the finer mesh: top %.1f %%, bottom %.1f %%."
        % (100 * a["topDisplacement"], 100 * a["bottomDisplacement"]),
    ]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def agreement(meshes):
    coarse, fine = meshes[0], meshes[-1]
    out = {"separation": abs(coarse["separation"] - fine["separation"])
           / fine["separation"]}
    ends = [r["contactIntervals"][0][1] for r in (coarse, fine)]
    out["firstSeparation"] = abs(ends[0] - ends[1]) / ends[1]
    out["pass"] = bool(out["separation"] <= LIMITS["separationAgreement"])
    for name in PROBES:
        a, b = coarse["probes"][name], fine["probes"][name]
        common = sorted(set(a["t"]) & set(b["t"]))
        ua = np.array([a["uy"][a["t"].index(t)] for t in common])
        ub = np.array([b["uy"][b["t"].index(t)] for t in common])
        out[name + "Displacement"] = float(np.abs(ua - ub).max()
                                           / np.abs(ub).max())
    return out


def plot(out, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: %s skipped" % os.path.basename(path))
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    styles = ["--", "-"]
    for (n, r), ls in zip(out["meshes"].items(), styles):
        for name, colour in (("top", "C0"), ("bottom", "C3")):
            p = r["probes"][name]
            ax.plot(1e6 * np.array(p["t"]), 1e3 * np.array(p["uy"]), ls,
                    color=colour, lw=1.3,
                    label="%s, %d cells (-n %s)" % (name, r["cells"], n))
        ax.axvline(1e6 * r["separation"], color="0.5", ls=ls, lw=0.8)
    ax.axvline(1e6 * GAP / V0, color="0.5", ls=":", lw=0.8)
    ax.set_xlabel("time [us]  (dotted: gap/v0; grey: separation)")
    ax.set_ylabel("vertical displacement u_y [mm]")
    ax.set_title("Bar rebound: centre of the top and of the bottom face")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print("wrote %s" % path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, nargs=2, default=[6, 12],
                        help="cells across the radius, coarse and fine")
    parser.add_argument("--write", type=float, default=5e-6,
                        help="writeInterval [s] of the copies")
    parser.add_argument("--no-run", action="store_true",
                        help="only post-process the existing runs")
    args = parser.parse_args()
    args.n = sorted(args.n)
    try:
        if not args.no_run:
            run.check_openfoam()
            for n in args.n:
                run_case(n, args.write)
        meshes = {str(n): measure(case_dir(n)) for n in args.n}
        first = next(iter(meshes.values()))
        out = {"date": time.strftime("%Y-%m-%d", time.localtime(
                   os.path.getmtime(os.path.join(case_dir(args.n[-1]),
                                                 "wallTime.json")))),
               "build": build_label(), "gap": GAP, "v0": V0,
               "length": LENGTH, "writeInterval": first["writeInterval"],
               "limits": LIMITS, "meshes": meshes,
               "agreement": agreement(list(meshes.values()))}
    except (run.RunError, OSError, ValueError, KeyError) as err:
        print("rebound: %s" % err, file=sys.stderr)
        return 1
    with open(os.path.join(HERE, "results.json"), "w") as f:
        json.dump(out, f, indent=1)
    write_markdown(out, os.path.join(HERE, "results.md"))
    plot(out, os.path.join(HERE, "displacement.png"))
    with open(os.path.join(HERE, "results.md")) as f:
        print(f.read())
    record_checks(out)
    return checks.status(HERE)


def record_checks(out):
    """The verdicts of results.md in checks.json (validation/Allrun)."""
    for n, r in out["meshes"].items():
        if "contactStartMinusGapOverV0" in r:
            checks.record(HERE, "n%s contact start t_c - gap/v0 [s]" % n,
                          r["contactStartMinusGapOverV0"],
                          "in [0, dt = %.3g]" % r["contactStep_dt"],
                          r["contactPass"])
        else:
            checks.record(HERE, "n%s contact" % n, "none", "a contact",
                          False)
        checks.record(HERE, "n%s max energy change per step / E0" % n,
                      r["maxEnergyChangePerStep_E0"],
                      "<= %g" % LIMITS["energyIncrease"], r["energyPass"])
        checks.record(HERE, "n%s flight: min p_y/|p_y(0)| after separation"
                      % n, r.get("minPyAfterSeparation_py0"), "> 0, no face "
                      "in contact", r.get("flightPass", False))
    a = out["agreement"]
    checks.record(HERE, "separation time |coarse - fine| / fine",
                  a["separation"], "<= %g" % LIMITS["separationAgreement"],
                  a["pass"], "between the two meshes of this run")


if __name__ == "__main__":
    sys.exit(main())
