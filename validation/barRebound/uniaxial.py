#!/usr/bin/python3
"""Where a bar bouncing off a rigid wall loses its energy (uniaxial strain).

    /usr/bin/python3 validation/barRebound/uniaxial.py [options] [-- label]

A copy of tutorials/elasticImpact (a bar of length L = 1 on N x 1 x 1
cubic cells, symmetricPlane sides, linear elastic, c_p = 1000 m/s) flying
at -v0 = -0.1 m/s onto a frictionless rigidWall at x = -gap, the gap set so
that contact starts at t_c = L/(2 c_p).  1D theory: a compressive front
of stress rho c_p v0 runs to the free end (arrival), comes back as a
release front (release), and the bar leaves the wall at t_c + 2 L/c_p
with +v0, unstressed, keeping all of its energy; the wall's stress is
rho c_p v0 throughout the contact.  The bar's response to the impact is
the same at any E, rho, L and v0 in the linear range (everything scales),
so E/E0 depends on N, the scheme and the CFL number only.

Per run, from the solidMonitor (one row per step) and the fields written
every L/(2 c_p):
    E(arrival)/E0    total energy at t_c + L/c_p (the compressive front
                     at the free end)
    E(sep)/E0        at the first step after t_c with no face in contact
    E(end)/E0        at t_c + 2.5 L/c_p (0.5 L/c_p of free flight)
    v_out/v0         p_x/(M v0) at the end
    wall             mean contact stress over the middle 80 % of the
                     contact, / rho c_p v0, and the largest deviation of a
                     step's from it (ringing)
    front            overshoot and precursor of sigma_xx, / rho c_p v0, at
                     t_c + L/(2 c_p) (compressive front at L/2) and at
                     t_c + 3 L/(2 c_p) (release front at L/2):
                     bin/python/touchfoam/impact.py front_metrics

Options: -n N (several allowed), --limiter, --reconstruction, --scheme
(RK2 | RK3), --cfl, --update (FUpdate), --touch key=value (any other TOUCH
entry), --material E,nu,rho,v0 (another material and speed: the issue's
bar is --material 1e7,0.3,1000,1 with L = 1 instead of 0.1, the same
response).  Work folders: validation/barRebound/runs/uniaxial/<label>_N<n>
(git-ignored).  Prints one line per run, and with --json appends the
results to the given file.
"""

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, impact, monitor, run  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def wall_entry(gap):
    return ("{ type rigidWall; point (%r 0 0); normal (1 0 0); "
            "velocity (0 0 0); }" % -gap)


def bounce(root, label, n, touch, material=None):
    """Run one bounce; its measures as a dict."""
    case = os.path.join(root, "%s_N%d" % (label, n))
    v0 = impact.V0
    cases.prepare("elasticImpact", case, n=n, touch=touch,
                  control={"writePrecision": 17,
                           "functions/solidMonitor/writePrecision": 17})
    if material:
        E, nu, rho, v0 = material
        run.write_options(case, "constant/materialOptions",
                          {"E": E, "nu": nu, "rho": rho})
        run.foam_set(case, "0/U", "internalField",
                     "uniform (%r 0 0)" % -v0)
    mat = cases.material(case)
    sol = impact.ElasticImpact(mat["E"], mat["nu"], mat["rho"], v0)
    cp, L = sol.cp, 1.0
    half = 0.5 * L / cp
    gap = v0 * half
    tc = half
    end = tc + 2.5 * L / cp
    run.foam_set(case, "0/U", "boundaryField/wall", wall_entry(gap))
    for key, value in (("endTime", end), ("writeInterval", half)):
        run.foam_set(case, "system/controlDict", key, value)
    run.run(["touchFoam"], case, timeout=1800)

    m = monitor.read_monitor(case)
    t, E, c = m["Time"], m["totalEnergy"], m["contactFaces(wall)"]
    E0 = E[0]
    on = np.nonzero(c > 0)[0]
    first = on[0]
    off = np.nonzero((c == 0) & (np.arange(len(t)) > first))[0]
    sep = off[0] if len(off) else len(t) - 1
    arrival = np.searchsorted(t, tc + L / cp)
    # Contact stress: the monitor's wall force over the face area h^2
    area = (L / n) ** 2
    stress = m["wallForce(wall)"] / area / sol.jump
    t0, t1 = t[first], t[sep]
    mid = (t > t0 + 0.1 * (t1 - t0)) & (t < t1 - 0.1 * (t1 - t0))
    plateau = float(stress[mid].mean())
    ringing = float(np.abs(stress[mid] - plateau).max())
    Mv0 = -m["px"][0]
    out = {"label": label, "n": n, "touch": touch, "steps": len(t),
           "EArrival": float(E[arrival] / E0), "ESep": float(E[sep] / E0),
           "EEnd": float(E[-1] / E0), "vOut": float(m["px"][-1] / Mv0),
           "tSep": float((t[sep] - tc) * cp / (2 * L)),
           "wall": plateau, "ringing": ringing,
           "energyRise": float(max(0.0, np.diff(E).max()) / E0)}
    # Fronts at L/2: the compressive one and the release one
    mesh = PolyMesh(case)
    x = mesh.cell_centres[:, 0]
    h = L / n
    for key, t_w, sign in (("compression", tc + half, 1.0),
                           ("release", tc + 3 * half, -1.0)):
        tdir = run.time_dir(case, t_w, tol=1e-3 * t_w)
        s = read_field(os.path.join(tdir, "sigma")).internal(mesh.n_cells)
        sxx = s[:, 0]
        if sign < 0:
            # The release front: compressed behind (wall side) -> the
            # compressive front's picture after sigma -> -jump - sigma
            # seen from the free end: mirror the bar
            xs, ss = L - x, -sol.jump - sxx
        else:
            xs, ss = x, sxx
        fm = impact.front_metrics(xs, ss, 0.5 * L, sol.jump, h)
        out[key] = {k: fm[k] for k in ("plateau", "offset", "overshoot",
                                       "precursor")}
    return out


def line(r):
    return ("%-28s N %4d  E arrival %.4f  sep %.4f  end %.4f  v_out %.4f  "
            "t_sep %+.3f  wall %.4f ring %.4f  comp os %.4f pre %.4f  "
            "rel os %.4f pre %.4f  rise %.1e" % (
                r["label"], r["n"], r["EArrival"], r["ESep"], r["EEnd"],
                r["vOut"], r["tSep"] - 1, r["wall"], r["ringing"],
                r["compression"]["overshoot"], r["compression"]["precursor"],
                r["release"]["overshoot"], r["release"]["precursor"],
                r["energyRise"]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-n", type=int, nargs="+", default=[50])
    parser.add_argument("--limiter")
    parser.add_argument("--reconstruction")
    parser.add_argument("--scheme")
    parser.add_argument("--cfl", type=float)
    parser.add_argument("--update")
    parser.add_argument("--touch", nargs="*", default=[],
                        help="other TOUCH entries as key=value")
    parser.add_argument("--material",
                        help="E,nu,rho,v0 (default: the tutorial's)")
    parser.add_argument("--label", default=None)
    parser.add_argument("--json", help="append the results to this file")
    args = parser.parse_args()

    touch = {}
    for key, value in (("limiter", args.limiter),
                       ("reconstruction", args.reconstruction),
                       ("timeScheme", args.scheme), ("CFL", args.cfl),
                       ("FUpdate", args.update)):
        if value is not None:
            touch[key] = value
    for kv in args.touch:
        key, value = kv.split("=", 1)
        touch[key] = value
    label = args.label or ("_".join("%s%s" % (k, v) for k, v in
                                    sorted(touch.items())) or "default")
    material = ([float(v) for v in args.material.split(",")]
                if args.material else None)
    root = os.path.join(HERE, "runs", "uniaxial")
    results = []
    for n in args.n:
        r = bounce(root, label, n, touch, material)
        print(line(r), flush=True)
        results.append(r)
    if args.json:
        old = []
        if os.path.exists(args.json):
            with open(args.json) as f:
                old = json.load(f)
        with open(args.json, "w") as f:
            json.dump(old + results, f, indent=1)


if __name__ == "__main__":
    main()
