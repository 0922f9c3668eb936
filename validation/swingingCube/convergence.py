#!/usr/bin/python3
"""Mesh convergence of the swinging cube (doc/benchmarks.md section 1).

    ./convergence.py [--meshes 4 8 16 32]
                     [--schemes firstOrder linear limitedLinear]
                     [--limiter BarthJespersen] [--no-run]

For each reconstruction and each N, runs a copy of tutorials/swingingCube
on N^3 cells (h = 1/N) to t = 0.004 s in runs/<scheme>_N<N>/, then
compares v and the normal stresses P_xx, P_yy, P_zz with the closed-form
solution (bin/python/touchfoam/analytic.py) in the volume-weighted L2 norm

    e_L2(q) = sqrt( sum_e V_e (q_e - q_exact(X_e, t))^2 )

(the domain volume is 1), also given relative to max_e |q_exact| and to
the amplitude of q over all times.  Observed orders log(e_1/e_2)/log(2)
between successive meshes; pass flags on the finest pair: >= 1.8 for
linear and limitedLinear; for firstOrder within [0.7, 1.4] for the
velocities and >= 0.7 for the stresses (at t = 0.004 s cos(w t) = 1.4e-3:
the stresses sit at a node of the oscillation, where the first-order
damping error vanishes and only the smaller phase error remains).
Writes results.json, results.md (with the published TOUCH errors next to
ours) and convergence.png when matplotlib is available.
--no-run post-processes the existing runs only.
"""

import argparse
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

from touchfoam import analytic, cases, checks, postprocess, run  # noqa: E402

T_END = 0.004
# scheme -> component kind (v or P) -> accepted order on the finest pair
EXPECTED = {
    "linear": {"U": {"min": 1.8, "max": None}, "P": {"min": 1.8, "max": None}},
    "limitedLinear": {"U": {"min": 1.8, "max": None},
                      "P": {"min": 1.8, "max": None}},
    "firstOrder": {"U": {"min": 0.7, "max": 1.4},
                   "P": {"min": 0.7, "max": None}},
}
# Published TOUCH L2 errors [fig] (doc/benchmarks.md 1); normalisation unstated
REFERENCE = {
    "h": [0.25, 0.125, 0.0625, 0.03125],
    "velocity": [2.2e-5, 4.8e-6, 1.0e-6, 1.8e-7],
    "stress": [2.1e-5, 4.7e-6, 9.7e-7, 2.1e-7],
}


def run_all(args):
    for scheme in args.schemes:
        for n in args.meshes:
            case = os.path.join(HERE, "runs", "%s_N%d" % (scheme, n))
            print("running %s N=%d in %s" % (scheme, n, case), flush=True)
            cases.prepare("swingingCube", case, n=n,
                          touch={"reconstruction": scheme,
                                 "limiter": args.limiter},
                          control={"writePrecision": 17, "endTime": T_END})
            run.run(["touchFoam"], case)


def analyse(args):
    h = [1.0 / n for n in args.meshes]
    results = {"time": T_END, "norm": postprocess.NORM,
               "meshes": args.meshes, "h": h, "limiter": args.limiter,
               "reference": REFERENCE, "schemes": {}}
    all_pass = True
    for scheme in args.schemes:
        errs = [postprocess.swinging_cube_errors(
            os.path.join(HERE, "runs", "%s_N%d" % (scheme, n)), T_END)
            for n in args.meshes]
        per_comp = {}
        for comp, (field, _) in postprocess.SWINGING_COMPONENTS.items():
            exp = EXPECTED[scheme][field]
            e = [x[comp]["L2"] for x in errs]
            orders = postprocess.observed_orders(h, e)
            last = orders[-1] if orders else None
            ok = last is not None and last >= exp["min"] and (
                exp["max"] is None or last <= exp["max"])
            all_pass &= ok
            checks.record(HERE, "%s %s: observed L2 order (finest pair)"
                          % (scheme, comp), last, ">= %g" % exp["min"]
                          if exp["max"] is None else "[%g, %g]"
                          % (exp["min"], exp["max"]), ok,
                          "meshes %s" % " ".join(map(str, args.meshes)))
            per_comp[comp] = {
                "L2": e,
                "relMax": [x[comp]["relMax"] for x in errs],
                "relAmplitude": [x[comp]["relAmplitude"] for x in errs],
                "orders": orders,
                "expected": "order between h=1/%d and h=1/%d %s" % (
                    args.meshes[-2], args.meshes[-1],
                    ">= %g" % exp["min"] if exp["max"] is None
                    else "in [%g, %g]" % (exp["min"], exp["max"]))
                if len(args.meshes) > 1 else "needs two meshes",
                "pass": bool(ok),
            }
        results["schemes"][scheme] = per_comp
    results["pass"] = bool(all_pass)
    return results


def amplitudes():
    """Velocity and stress amplitudes of the tutorial's cube."""
    mat = cases.material(run.tutorial_dir("swingingCube"))
    sol = analytic.SwingingCube(E=mat["E"], nu=mat["nu"], rho=mat["rho"])
    return sol.velocity_amplitude(), sol.stress_amplitude()


def write_markdown(results, path):
    comps = list(postprocess.SWINGING_COMPONENTS)
    ref = dict(zip(REFERENCE["h"], zip(REFERENCE["velocity"],
                                       REFERENCE["stress"])))
    lines = [
        "# Swinging cube: L2 errors at t = %g s" % results["time"], "",
        "Generated by convergence.py.  Norm: %s." % results["norm"], "",
        "Published TOUCH values [fig] are read off a figure and their "
        "normalisation is not stated (doc/benchmarks.md 1).", "",
        "| scheme | h | " + " | ".join(comps) +
        " | published v | published P |",
        "|---|---|" + "---|" * (len(comps) + 2),
    ]
    for scheme, data in results["schemes"].items():
        for i, h in enumerate(results["h"]):
            pub = ref.get(h, ("-", "-"))
            lines.append("| %s | %g | " % (scheme, h) + " | ".join(
                "%.2e" % data[c]["L2"][i] for c in comps) + " | %s | %s |"
                % tuple(("%.1e" % x) if x != "-" else x for x in pub))
    lines += ["", "The same errors relative to the amplitude of each "
              "quantity (U0 w = %.4g m/s, (3 lambda + 2 mu) pi/2 U0 = %.4g "
              "Pa):" % amplitudes(), "",
              "| scheme | h | " + " | ".join(comps) + " |",
              "|---|---|" + "---|" * len(comps)]
    for scheme, data in results["schemes"].items():
        for i, h in enumerate(results["h"]):
            lines.append("| %s | %g | " % (scheme, h) + " | ".join(
                "%.2e" % data[c]["relAmplitude"][i] for c in comps) + " |")
    lines += ["", "Observed orders between successive meshes:", "",
              "| scheme | component | orders | expected | pass |",
              "|---|---|---|---|---|"]
    for scheme, data in results["schemes"].items():
        for c in comps:
            lines.append("| %s | %s | %s | %s | %s |" % (
                scheme, c, " ".join("%.2f" % o if o is not None else "-"
                                    for o in data[c]["orders"]),
                data[c]["expected"], "yes" if data[c]["pass"] else "NO"))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def plot(results, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: %s skipped" % os.path.basename(path))
        return
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    h = results["h"]
    for ax, group, ref in ((axes[0], ("vx", "vy", "vz"), "velocity"),
                           (axes[1], ("Pxx", "Pyy", "Pzz"), "stress")):
        for scheme, data in results["schemes"].items():
            for c in group:
                ax.loglog(h, data[c]["L2"], "o-", label="%s %s" % (scheme, c))
        ax.loglog(REFERENCE["h"], REFERENCE[ref], "k--",
                  label="published TOUCH [fig]")
        ax.loglog(h, [results["schemes"][next(iter(results["schemes"]))][
            group[0]]["L2"][-1] * (x / h[-1]) ** 2 for x in h], "k:",
            label="slope 2")
        ax.set_xlabel("h")
        ax.set_ylabel("L2 error")
        ax.set_title(ref)
        ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print("wrote %s" % path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--meshes", type=int, nargs="+",
                        default=[4, 8, 16, 32])
    parser.add_argument("--schemes", nargs="+", choices=list(EXPECTED),
                        default=["firstOrder", "linear", "limitedLinear"])
    parser.add_argument("--limiter", default="BarthJespersen",
                        choices=["BarthJespersen", "Venkatakrishnan"])
    parser.add_argument("--no-run", action="store_true",
                        help="only post-process the existing runs")
    args = parser.parse_args()
    args.meshes = sorted(args.meshes)
    try:
        if not args.no_run:
            run.check_openfoam()
            run_all(args)
        results = analyse(args)
    except (run.RunError, OSError, ValueError) as err:
        print("convergence: %s" % err, file=sys.stderr)
        return 1
    with open(os.path.join(HERE, "results.json"), "w") as f:
        json.dump(results, f, indent=2)
    write_markdown(results, os.path.join(HERE, "results.md"))
    plot(results, os.path.join(HERE, "convergence.png"))
    for scheme, data in results["schemes"].items():
        print("%-14s %s" % (scheme, "  ".join(
            "%s %s" % (c, "%.2f" % d["orders"][-1] if d["orders"] and
                       d["orders"][-1] is not None else "-")
            for c, d in data.items())))
    print("%s: results.json, results.md" % ("PASS" if results["pass"]
                                            else "FAIL"))
    return 0 if results["pass"] else 1


if __name__ == "__main__":
    sys.exit(main())
