#!/usr/bin/python3
"""The twisting column's converged twist at 0.1 s, from both codes.

    /usr/bin/python3 validation/twistingColumn/reference.py touchFoam N [RANKS] [--nu NU]
    /usr/bin/python3 validation/twistingColumn/reference.py ccx N ELEMENT
    /usr/bin/python3 validation/twistingColumn/reference.py analyse

The comparisons (validation/calculix, validation/accuracyVsCost, the
tutorial's README, the tests) measure errors against one converged twist,
so it is established here from two independent discretisations that
approach it from opposite sides: touchFoam at the tutorial's setting
(linear, RK3, CFL 0.8) from below, CalculiX 2.20 C3D8R and C3D8 from above.

touchFoam N   the tutorial on N x 6N x N, written every 0.01 s; twist by
              postprocess.column_twist (unwrapped through the writes);
              --nu NU another Poisson's ratio (runs touchFoam_nu<NU>_n<N>):
              the same scheme's convergence towards a nearly incompressible
              limit, the locking check of issue 35 (not in the band)
ccx N EL      CalculiX on the same grid (validation/calculix/decks.py),
              one explicit step to 0.1 s; twist at the end, each point's
              angle on the branch nearest the last touchFoam estimate
              (valid while errors are below 180 deg)
analyse       each code's (and element's) finest three meshes in the
              ratio 2: observed order p = log2((T1 - T2) / (T2 - T3)),
              Richardson T* = T3 + (T3 - T2) / (2^p - 1), the finest
              triplet's; with two meshes only, the order of the other
              element is borrowed.  The band is the span of the codes'
              extrapolations, each widened by its uncertainty (the spread
              of its triplets' extrapolations; half the shift |T* - T3|
              when its order is borrowed); writes reference.json.  Runs at
              another nu are analysed alike and reported under 'otherNu'
              with each run's largest energy growth in a step (/ E0).
              Printed and recorded beside them ('finestFits'): the fit
              T = T* - C n^-p through every three of the four finest
              meshes, any ratios (fit_three): the order on the finest
              meshes, where the coarse ones are short of the asymptotic
              range.

The twist is the mean rotation about +Y of the top-face points at least
0.25 m from the axis (both codes the same points and formula).  Runs go
to runs/reference/<code>_n<N>/ (git-ignored) with a run.json each (twist,
wall and CPU time, load); they run under nice, so their times are a guide
only.  FINDINGS.md, "The converged twist".
"""
import json
import math
import os
import resource
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))
# The project's copy of the CalculiX tools, also from a quick copy of
# this study under validationQuick/
sys.path.insert(0, os.path.join(HERE, "..", "..", "validation", "calculix"))

from touchfoam import (analytic, cases, monitor, postprocess,  # noqa
                       provenance, run)
import decks  # noqa: E402

import numpy as np  # noqa: E402

T_END = 0.1
NU = 0.45
RMIN = 0.25
#: branch of the CalculiX angles: the converged twist as known before
#: (issue 35); any value within 180 deg of the truth gives the same result
BRANCH = 332.2
RUNS = os.path.join(HERE, "runs", "reference")
ONE_THREAD = {"OMP_NUM_THREADS": "1", "CCX_NPROC_STIFFNESS": "1",
              "CCX_NPROC_RESULTS": "1", "CCX_NPROC_EQUATION_SOLVER": "1"}


def timed(cmd, folder, name, env=None):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    load = list(os.getloadavg())
    run.run(cmd, folder, name, env=env, timeout=20000)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return {"wall": time.perf_counter() - start,
            "cpu": (after.ru_utime - before.ru_utime)
            + (after.ru_stime - before.ru_stime),
            "load": load + list(os.getloadavg())}


def save(folder, info):
    info.update({"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
                 "build": provenance.build_label()})
    with open(os.path.join(folder, "run.json"), "w") as f:
        json.dump(info, f, indent=1)
    print("%s: twist %.3f deg, wall %.0f s, cpu %.0f s"
          % (folder, info["twist"], info["wall"], info["cpu"]), flush=True)


def run_touch(n, ranks=1, nu=NU):
    folder = os.path.join(RUNS, "touchFoam_n%d" % n if nu == NU
                          else "touchFoam_nu%g_n%d" % (nu, n))
    cases.prepare("twistingColumn", folder, n=n, nu=nu,
                  control={"endTime": T_END, "writeInterval": 0.01})
    if ranks > 1:
        run.foam_set(folder, "system/decomposeParDict", "numberOfSubdomains",
                     ranks)
        run.run(["decomposePar", "-force"], folder)
        info = timed(run.mpirun(ranks, ["touchFoam"]), folder,
                     "touchFoam")
        run.run(["reconstructPar"], folder)
    else:
        info = timed(["touchFoam"], folder, "touchFoam")
    info["ranks"] = ranks
    info["twist"] = math.degrees(postprocess.column_twist(folder)[-1][1])
    energy = monitor.read_monitor(folder)["totalEnergy"]
    info["energyKept"] = energy[-1] / energy[0]
    info["largestGrowth"] = max(0.0, float(np.max(np.diff(energy)))) \
        / energy[0]
    info.update(code="touchFoam" if nu == NU else "touchFoam nu %g" % nu,
                n=n, nu=nu)
    save(folder, info)


def ccx_top_twist(folder, job, branch_deg):
    """Mean twist [deg] of the top face at the last NTOP print."""
    import ccx
    nodes, _, _ = ccx.read_inp(os.path.join(folder, job + ".inp"))
    block = ccx.last_block(ccx.read_dat(os.path.join(folder, job + ".dat")),
                           "displacements", "NTOP")
    if abs(block["time"] - T_END) > 1e-6 * T_END:
        raise ValueError("%s: last print at t = %g" % (job, block["time"]))
    rows = np.array(block["rows"])
    X = np.array([nodes[int(i)] for i in rows[:, 0]])
    keep = np.hypot(X[:, 0], X[:, 2]) >= RMIN
    theta = analytic.twist_angle(X[keep], rows[keep, 1:4])
    ref = math.radians(branch_deg)
    theta = ref + np.angle(np.exp(1j * (theta - ref)))
    return math.degrees(float(theta.mean()))


def run_ccx(n, element):
    folder = os.path.join(RUNS, "ccx-%s_n%d" % (element, n))
    os.makedirs(folder, exist_ok=True)
    job = "column"
    decks.column_deck(os.path.join(folder, job + ".inp"), n, element, NU,
                      T_END)
    info = timed(["ccx", "-i", job], folder, "ccx", env=ONE_THREAD)
    info["twist"] = ccx_top_twist(folder, job, BRANCH)
    info.update(code="CalculiX " + element, n=n)
    save(folder, info)


def triplets(values):
    """Every (n, 2n, 4n) of the measured meshes, finest last, with its
    observed order p = log2((T1 - T2) / (T2 - T3)) and Richardson
    extrapolation T3 + (T3 - T2) / (2^p - 1) (None where the differences
    change sign)."""
    out = []
    for n in sorted(values):
        if 2 * n in values and 4 * n in values:
            t1, t2, t3 = values[n], values[2 * n], values[4 * n]
            if (t1 - t2) * (t2 - t3) > 0:
                p = math.log2((t1 - t2) / (t2 - t3))
                out.append((n, p, t3 + (t3 - t2) / (2 ** p - 1)))
            else:
                out.append((n, None, None))
    return out


def fit_three(meshes, twists):
    """(order p, extrapolation T*) of T(n) = T* - C n^-p through three
    meshes n1 < n2 < n3 of any ratios: p solves
    (n1^-p - n2^-p) / (n2^-p - n3^-p) = (T2 - T1) / (T3 - T2), whose left
    side rises with p (bisection on 0.05 < p < 10); (None, None) where the
    differences change sign or p leaves that range.  For n, 2n, 4n it is
    the ratio-2 formula of triplets()."""
    (n1, n2, n3), (t1, t2, t3) = meshes, twists
    if (t2 - t1) * (t3 - t2) <= 0:
        return None, None
    r = (t2 - t1) / (t3 - t2)

    def excess(p):
        return (n1 ** -p - n2 ** -p) / (n2 ** -p - n3 ** -p) - r

    low, high = 0.05, 10.0
    if excess(low) > 0 or excess(high) < 0:
        return None, None
    for _ in range(200):
        mid = 0.5 * (low + high)
        if excess(mid) < 0:
            low = mid
        else:
            high = mid
    p = 0.5 * (low + high)
    c = (t2 - t1) / (n1 ** -p - n2 ** -p)
    return p, t3 + c * n3 ** -p


def finest_fits(values, count=4):
    """Every three of the finest `count` meshes, [n1, n2, n3, p, T*],
    finest last (fit_three; None where it has none)."""
    ns = sorted(values)[-count:]
    out = []
    for i in range(len(ns)):
        for j in range(i + 1, len(ns)):
            for k in range(j + 1, len(ns)):
                m = (ns[i], ns[j], ns[k])
                p, ext = fit_three(m, [values[n] for n in m])
                out.append(list(m) + [p, ext])
    out.sort(key=lambda f: (f[2], f[1], f[0]))
    return out


def richardson(values, borrowed_order=None):
    """(order, extrapolation, its uncertainty, own order?) from {n:
    twist}: the finest triplet in the ratio 2 (uncertainty: the largest
    difference from the other triplets' extrapolations), or, with only a
    pair, the borrowed order (uncertainty: half the shift it makes)."""
    found = [t for t in triplets(values) if t[1] is not None]
    if found:
        spread = max(abs(t[2] - found[-1][2]) for t in found)
        return found[-1][1], found[-1][2], spread, True
    ns = sorted(values)
    if len(ns) >= 2 and borrowed_order and ns[-1] == 2 * ns[-2]:
        t2, t3 = values[ns[-2]], values[ns[-1]]
        shift = (t3 - t2) / (2 ** borrowed_order - 1)
        return borrowed_order, t3 + shift, abs(shift) / 2, False
    return None, None, None, False


def recorded():
    """The runs reference.json already holds, {code: {n: info}}: the runs/
    folders are not kept in git, so a new run adds to the record (and a
    rerun of the same code and mesh replaces its entry) instead of
    starting it again."""
    path = os.path.join(HERE, "reference.json")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        old = json.load(f)
    found = {}
    for group in ("codes", "otherNu"):
        for code, entry in old.get(group, {}).items():
            for n, twist in entry["twist"].items():
                info = {"twist": twist, "wall": entry["wall"][n],
                        "nu": entry.get("nu", NU)}
                growth = entry.get("largestGrowth", {}).get(n)
                if growth is not None:
                    info["largestGrowth"] = growth
                found.setdefault(code, {})[int(n)] = info
    return found


def analyse():
    found = recorded()
    for name in sorted(os.listdir(RUNS)):
        path = os.path.join(RUNS, name, "run.json")
        if os.path.exists(path):
            with open(path) as f:
                info = json.load(f)
            found.setdefault(info["code"], {})[info["n"]] = info
    result = {"codes": {}, "otherNu": {}}
    orders = {}
    for code, runs in sorted(found.items()):
        twists = {n: r["twist"] for n, r in runs.items()}
        p, ext, half, own = richardson(twists)
        other = any(r.get("nu", NU) != NU for r in runs.values())
        if not other:
            orders[code] = p
        group = result["otherNu" if other else "codes"]
        group[code] = {"twist": twists, "order": p,
                       "nu": next(iter(runs.values())).get("nu", NU),
                                 "triplets": triplets(twists),
                                 "finestFits": finest_fits(twists),
                                 "extrapolation": ext, "uncertainty": half,
                                 "ownOrder": own,
                                 "wall": {n: r["wall"]
                                          for n, r in runs.items()},
                                 "largestGrowth": {
                                     n: r.get("largestGrowth")
                                     for n, r in runs.items()}}
    for code, entry in result["codes"].items():
        if entry["extrapolation"] is None:
            others = [o for c, o in orders.items() if c != code and o
                      and c.startswith(code.split()[0])]
            p, ext, half, own = richardson(entry["twist"],
                                           others[0] if others else None)
            entry.update(order=p, extrapolation=ext, uncertainty=half,
                         ownOrder=own)
    ends = [(e["extrapolation"] - e["uncertainty"],
             e["extrapolation"] + e["uncertainty"])
            for e in result["codes"].values() if e["extrapolation"]]
    if ends:
        low, high = min(a for a, b in ends), max(b for a, b in ends)
        result["band"] = [low, high]
        result["reference"] = 0.5 * (low + high)
    with open(os.path.join(HERE, "reference.json"), "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
    for code, e in list(result["codes"].items()) \
            + list(result["otherNu"].items()):
        print("%-18s %s  order %s  extrapolated %s" % (
            code, " ".join("n%d %.2f" % (n, t)
                           for n, t in sorted(e["twist"].items())),
            "%.2f%s" % (e["order"], "" if e["ownOrder"] else " (borrowed)")
            if e["order"] else "-",
            "%.2f +- %.2f" % (e["extrapolation"], e["uncertainty"])
            if e["extrapolation"] else "-"))
        for n, p, t in e["triplets"]:
            print("    %d / %d / %d: order %s, extrapolated %s" % (
                n, 2 * n, 4 * n, "%.2f" % p if p else "-",
                "%.2f" % t if t else "-"))
        if len(e["twist"]) >= 4:
            for n1, n2, n3, p, t in e["finestFits"]:
                print("    fit %d / %d / %d: order %s, extrapolated %s" % (
                    n1, n2, n3, "%.2f" % p if p else "-",
                    "%.2f" % t if t else "-"))
    if ends:
        print("band %.2f - %.2f, middle %.2f" % (low, high,
                                                 result["reference"]))


def main():
    what = sys.argv[1] if len(sys.argv) > 1 else ""
    args = sys.argv[2:]
    nu = NU
    if "--nu" in args:
        at = args.index("--nu")
        nu = float(args[at + 1])
        del args[at:at + 2]
    if what == "touchFoam" and len(args) in (1, 2):
        run_touch(int(args[0]), int(args[1]) if len(args) == 2 else 1, nu)
    elif what == "ccx" and len(sys.argv) == 4:
        run_ccx(int(sys.argv[2]), sys.argv[3])
    elif what == "analyse":
        analyse()
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
