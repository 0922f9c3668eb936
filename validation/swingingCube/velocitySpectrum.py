#!/usr/bin/python3
"""Where the swinging cube's velocity error sits in wavenumber space.

    ./velocitySpectrum.py [--n 16] [--variants quadratic linear] [--no-run]

Runs tutorials/swingingCube on N^3 cells to t = 0.004 s (the velocity's
peak, w t = pi/2: a phase error barely moves it there) once per variant
in runs/spectrum_<variant>_N<N>/ and splits the error of v_x at the cell
centres, r = v_x - v_x,exact(X, t), into

- the part proportional to the exact mode (the amplitude factor
  a = <v_x, v_exact>/<v_exact, v_exact>, volume-weighted): what the
  scheme's dissipation and the cell averaging take off the swinging mode;
- the residual, by the discrete Fourier transform of r on the N^3 grid of
  cells: the share of sum |r_hat|^2 at grid-scale wavenumbers
  (max_i |k_i| >= 3N/8, a Nyquist-like alternation along some axis) and at
  smooth ones (max_i |k_i| <= N/8).

Variants: 'quadratic' is the tutorial (compatible, jumpShare quadratic,
linear RK3 CFL 0.8, symmetricPlanes mirror), 'linear' the same with
jumpShare linear, 'oneSided' the tutorial with one-sided planes (its
tutorial setting before 2026-12-03: the grid-scale ripple; with mirrors
the residual is round-off).  Prints a
table; writes nothing else.  Issue 11, acceptance line 6 (velocity error
against CalculiX C3D8).
"""

import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

from touchfoam import analytic, cases, run  # noqa: E402
from touchfoam.postprocess import (PolyMesh, material, read_field,  # noqa: E402
                                   time_dir)

T_END = 0.004

VARIANTS = {"quadratic": {}, "linear": {"jumpShare": "linear"},
            "oneSided": {"symmetricPlanes": "oneSided"}}


def case_dir(variant, n):
    return os.path.join(HERE, "runs", "spectrum_%s_N%d" % (variant, n))


def analyse(case, n):
    mat = material(case)
    sol = analytic.SwingingCube(E=mat["E"], nu=mat["nu"], rho=mat["rho"])
    mesh = PolyMesh(case)
    X, V = mesh.cell_centres, mesh.cell_volumes
    v = read_field(os.path.join(time_dir(case, T_END), "U")) \
        .internal(mesh.n_cells)[:, 0]
    exact = sol.velocity(X, T_END)[:, 0]
    a = np.sum(V * v * exact) / np.sum(V * exact ** 2)
    r = v - exact
    # The blockMesh cube numbers its cells x fastest: index them by centre
    ijk = np.round(X * n - 0.5).astype(int)
    grid = np.zeros((n, n, n))
    grid[ijk[:, 0], ijk[:, 1], ijk[:, 2]] = r
    power = np.abs(np.fft.fftn(grid)) ** 2
    k = np.abs(np.fft.fftfreq(n) * n)
    kmax = np.max(np.stack(np.meshgrid(k, k, k, indexing="ij")), axis=0)
    total = power.sum()
    return {"L2": float(np.sqrt(np.sum(V * r ** 2))),
            "amplitude": float(a),
            "residual": float(np.sqrt(np.sum(V * (v - a * exact) ** 2))),
            "gridScale": float(power[kmax >= 3 * n / 8].sum() / total),
            "smooth": float(power[kmax <= n / 8].sum() / total)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, default=16)
    parser.add_argument("--variants", nargs="+", choices=list(VARIANTS),
                        default=list(VARIANTS))
    parser.add_argument("--no-run", action="store_true")
    args = parser.parse_args()

    print("| variant | N | e_L2(v_x) | amplitude factor | residual "
          "| grid-scale share | smooth share |")
    print("|---|---|---|---|---|---|---|")
    for variant in args.variants:
        case = case_dir(variant, args.n)
        if not args.no_run:
            cases.prepare("swingingCube", case, n=args.n,
                          touch=VARIANTS[variant],
                          control={"writePrecision": 17, "endTime": T_END})
            run.run(["touchFoam"], case)
        res = analyse(case, args.n)
        print("| %s | %d | %.3e | %.5f | %.3e | %.2f | %.2f |"
              % (variant, args.n, res["L2"], res["amplitude"],
                 res["residual"], res["gridScale"], res["smooth"]))


if __name__ == "__main__":
    main()
