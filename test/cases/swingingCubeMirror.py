#!/usr/bin/python3
"""Swinging cube with its planes as mirrors: the discrete mode is one mode.

    /usr/bin/python3 test/cases/swingingCubeMirror.py

The swinging cube's faces are symmetric planes (X0, Y0, Z0: rollers) and
skew-symmetric planes (X1, Y1, Z1: tangential velocity and normal stress
zero).  With 'symmetricPlanes mirror' (the tutorial's setting) every
boundary cell sees its reflection, p' = R p at a symmetric plane and
p' = -R p at a skew-symmetric one (P' = R P R and -R P R), R = I - 2 n n:
the scheme is then the scheme of the periodic grid the reflections make,
and the swinging mode, one Fourier mode of that grid, can only change its
amplitude and phase.  Asserted on 8^3 and 16^3, tutorial as is (linear,
RK3, CFL 0.8, angular momentum preservation on), to t = 0.004 s (the
velocity's peak):

- the velocity is a multiple of the exact mode: the residual
  sqrt(sum V (v - a v_exact)^2), a the volume-weighted projection, is below
  1e-8 of sqrt(sum V v^2) (measured 2e-10 and 3e-11: round-off; a wrong
  sign or a wrong reflected stress at one plane gives 1e-2 or more);
- the velocity error converges at order >= 3 between 8^3 and 16^3
  (measured 4.05: the amplitude error alone), and the stress at >= 1.6;
- the total energy never grows over 0.02 s (16^3, 1.25 periods).

The same runs with oneSided planes are reported (velocity error 8.5e-4
against 2.1e-5 m/s on 16^3).
Work folders: test/runs/swingingCubeMirror/.
"""

import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import analytic, cases, postprocess, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

NAME = "swingingCubeMirror"
T_END = 0.004
T_ENERGY = 0.02
MESHES = (8, 16)
MODE_TOLERANCE = 1e-8
MIN_ORDER_V = 3.0
MIN_ORDER_P = 1.6


def mode_residual(case, t):
    """(residual of v after its projection on the exact mode) / |v|."""
    mat = cases.material(case)
    sol = analytic.SwingingCube(E=mat["E"], nu=mat["nu"], rho=mat["rho"])
    mesh = PolyMesh(case)
    X, V = mesh.cell_centres, mesh.cell_volumes
    v = read_field(os.path.join(run.time_dir(case, t), "U")) \
        .internal(mesh.n_cells)
    exact = sol.velocity(X, t)
    a = np.sum(V[:, None] * v * exact) / np.sum(V[:, None] * exact ** 2)
    residual = np.sqrt(np.sum(V[:, None] * (v - a * exact) ** 2))
    return float(residual / np.sqrt(np.sum(V[:, None] * v ** 2)))


def velocity_error(errors):
    return float(np.sqrt(sum(errors[c]["L2"] ** 2
                             for c in ("vx", "vy", "vz"))))


def stress_error(errors):
    return float(np.sqrt(sum(errors[c]["L2"] ** 2
                             for c in ("Pxx", "Pyy", "Pzz"))))


def body():
    root = testing.work_dir(NAME)
    lines, failures = [], []
    results = {}
    for planes in ("mirror", "oneSided"):
        for n in MESHES:
            case = cases.prepare(
                "swingingCube",
                os.path.join(root, "%s_N%d" % (planes, n)), n=n,
                touch={"symmetricPlanes": planes},
                control={"writePrecision": 17, "endTime": T_END})
            run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
            errors = postprocess.swinging_cube_errors(case, T_END)
            results[planes, n] = (velocity_error(errors),
                                  stress_error(errors),
                                  mode_residual(case, T_END))

    for n in MESHES:
        ev, eP, residual = results["mirror", n]
        lines.append("mirror %d^3: e_v %.3e m/s, e_P %.3e Pa, mode residual "
                     "%.1e (oneSided: e_v %.3e, e_P %.3e, residual %.1e)"
                     % ((n, ev, eP, residual) + results["oneSided", n]))
        if not residual < MODE_TOLERANCE:
            failures.append("mirror %d^3: the velocity is not one mode "
                            "(residual %.2e of |v|, limit %g)"
                            % (n, residual, MODE_TOLERANCE))

    h = [1.0 / n for n in MESHES]
    order_v = postprocess.observed_orders(
        h, [results["mirror", n][0] for n in MESHES])[-1]
    order_P = postprocess.observed_orders(
        h, [results["mirror", n][1] for n in MESHES])[-1]
    lines.append("orders v %.2f, P %.2f" % (order_v, order_P))
    if order_v is None or order_v < MIN_ORDER_V:
        failures.append("velocity order %s < %g" % (order_v, MIN_ORDER_V))
    if order_P is None or order_P < MIN_ORDER_P:
        failures.append("stress order %s < %g" % (order_P, MIN_ORDER_P))

    # The energy over a longer run: mirrors must not feed it
    case = cases.prepare("swingingCube", os.path.join(root, "energy_N16"),
                         n=16, control={"endTime": T_ENERGY})
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    growth, E0, samples = postprocess.energy_increase(case)
    lines.append("16^3 to %g s: largest energy growth in a step %.1e E0 "
                 "(%d steps)" % (T_ENERGY, growth, samples - 1))
    if growth > 0:
        failures.append("the total energy grew by %.2e E0 in a step"
                        % growth)

    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
