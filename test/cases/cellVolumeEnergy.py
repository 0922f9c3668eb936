#!/usr/bin/python3
"""nodalAveraging cellVolume: the stored energy of the cells' volumes, never growing.

    /usr/bin/python3 test/cases/cellVolumeEnergy.py [--n 4] [--end 0.3]

tutorials/twistingColumn (neoHookean, linear, RK3, CFL 0.8) on
n x 6n x n cells with 'nodalAveraging cellVolume;' (the volume ratio of
each cell from its current volume, src/TOUCH/nodalAveraging/cellVolume),
nu = 0.45 and 0.495, to t = end, writing every 0.01 s at 17 digits.
Asserted, for both nu:
  - the solidMonitor's strain energy at t = 0.1 s equals, to 1e-9 of
    itself, sum_e V_e [mu/2 (det(F)^(-2/3) F:F - 3) + kappa/2 (J_e - 1)^2]
    computed here from the written F and pointD, J_e the volume of cell e
    with its faces split about the mean of their points (current over
    reference): the law's volumetric part takes the cells' volumes, not
    det F (with det F the sum differs by 1e-4 to 1e-3 of itself);
  - the total energy never grows from one step to the next by more than
    1e-12 E0 (the nodal forces are the exact derivative of that energy);
  - the twists at 0.1 s of the two nu agree within 10 % (no locking).
Work folders: test/runs/cellVolumeEnergy/.
"""

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, postprocess, run, testing  # noqa: E402
from touchfoam.foamfile import FoamField  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

NAME = "cellVolumeEnergy"
T_CHECK = 0.1
ENERGY_TOL = 1e-9


def volumes(m, x):
    """Cell volumes, faces split into triangles about their points' mean."""
    v = np.zeros(m.n_cells)
    n_internal = len(m.neighbour)
    for facei, f in enumerate(m.faces):
        r = x[f]
        s = np.dot(r.mean(axis=0),
                   np.cross(r, np.roll(r, -1, axis=0)).sum(axis=0)) / 6
        v[m.owner[facei]] += s
        if facei < n_internal:
            v[m.neighbour[facei]] -= s
    return v


def expected_energy(case, t):
    m = PolyMesh(case)
    mat = cases.material(case)
    E, nu = mat["E"], mat["nu"]
    mu, kappa = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
    tdir = os.path.join(case, "%g" % t)
    F = np.asarray(FoamField(os.path.join(tdir, "F")).internal())
    F = F.reshape(-1, 3, 3)
    pD = np.asarray(FoamField(os.path.join(tdir, "pointD")).internal())
    J = volumes(m, m.points + pD) / volumes(m, m.points)
    d = np.linalg.det(F)
    FF = np.einsum("kij,kij->k", F, F)
    iso = 0.5 * mu * (d ** (-2.0 / 3) * FF - 3)
    V = m.cell_volumes
    return (float(np.sum(V * (iso + 0.5 * kappa * (J - 1) ** 2))),
            float(np.sum(V * (iso + 0.5 * kappa * (d - 1) ** 2))))


def column(root, nu, args):
    control = cases.precise_output()
    control.update({"endTime": args.end, "writeInterval": 0.01})
    case = cases.prepare("twistingColumn", os.path.join(root, "nu%s" % nu),
                         n=args.n, nu=nu, control=control,
                         touch={"nodalAveraging": "cellVolume"})
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    E0 = postprocess.initial_energy(case)
    growth, _, _ = postprocess.energy_increase(case, reference=E0)
    mon = read_monitor(case)
    k = int(np.argmin(np.abs(mon["Time"] - T_CHECK)))
    if abs(mon["Time"][k] - T_CHECK) > 1e-9:
        raise AssertionError("nu %s: no monitor sample at t = %g"
                             % (nu, T_CHECK))
    stored = float(mon["strainEnergy"][k])
    volume, determinant = expected_energy(case, T_CHECK)
    twist = [a for t, a in postprocess.column_twist(case, t_end=T_CHECK)
             if abs(t - T_CHECK) < 1e-9][0]
    return {"growth": growth, "stored": stored, "volume": volume,
            "determinant": determinant, "twist": twist}


def body(args):
    root = testing.work_dir(NAME)
    results = {nu: column(root, nu, args) for nu in (0.45, 0.495)}
    lines, failures = [], []
    for nu, r in results.items():
        off = abs(r["stored"] - r["volume"]) / r["stored"]
        offDet = abs(r["stored"] - r["determinant"]) / r["stored"]
        lines.append("nu %s: strain energy at %g s %.10g J, from the cell"
                     " volumes %.3e off, from det F %.3e off; largest growth"
                     " %.1e E0; twist %.2f deg"
                     % (nu, T_CHECK, r["stored"], off, offDet, r["growth"],
                        math.degrees(r["twist"])))
        if not off <= ENERGY_TOL:
            failures.append("nu %s: strain energy %.3e off the cell volumes'"
                            % (nu, off))
        if r["growth"] > 1e-12:
            failures.append("nu %s: the energy grew by %.2e E0 in a step"
                            % (nu, r["growth"]))
    a, b = results[0.45]["twist"], results[0.495]["twist"]
    if abs(a - b) / max(abs(a), abs(b)) > 0.1:
        failures.append("twists differ by more than 10 %")
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, default=4)
    parser.add_argument("--end", type=float, default=0.3)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
