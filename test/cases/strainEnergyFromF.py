#!/usr/bin/python3
"""The monitor's energies recomputed from the written fields.

    /usr/bin/python3 test/cases/strainEnergyFromF.py [--mu-scale 1]

tutorials/twistingColumn (neo-Hookean, E 1.7e7, nu 0.45, rho 1100) on
4 x 24 x 4 cells to t = 0.05 s, fields and monitor at 17 digits.  From the
written F and U of that time alone, with the neo-Hookean strain energy
written out here (not the solver's):

    psi(F) = mu/2 (J^(-2/3) F:F - 3) + kappa/2 (J - 1)^2,
    mu = E/(2 (1 + nu)), kappa = E/(3 (1 - 2 nu)),

the strain energy sum_e V_e psi(F_e) and the kinetic energy
sum_e V_e rho |U_e|^2/2 (V_e the reference cell volumes) must equal the
solidMonitor's strainEnergy and kineticEnergy at t = 0.05 s to 1e-10
(measured 2026-12-04: 1.1e-15 and 2.3e-16 of the total, round-off).
--mu-scale 1.001 (a perturbed formula) fails.
Work folders: test/runs/strainEnergyFromF/.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

NAME = "strainEnergyFromF"
T = 0.05
TOLERANCE = 1e-10


def body(args):
    root = testing.work_dir(NAME)
    control = cases.precise_output()
    control.update({"endTime": T, "writeInterval": T})
    case = cases.prepare("twistingColumn", os.path.join(root, "n4"), n=4,
                         control=control)
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    mat = cases.material(case)
    E, nu, rho = mat["E"], mat["nu"], mat["rho"]
    mu = args.mu_scale * E / (2 * (1 + nu))
    kappa = E / (3 * (1 - 2 * nu))
    mesh = PolyMesh(case)
    V = mesh.cell_volumes
    tdir = run.time_dir(case, T)
    F = read_field(os.path.join(tdir, "F")).internal(mesh.n_cells)
    F = F.reshape(-1, 3, 3)
    U = read_field(os.path.join(tdir, "U")).internal(mesh.n_cells)
    J = np.linalg.det(F)
    FF = np.einsum("eij,eij->e", F, F)
    psi = 0.5 * mu * (J ** (-2.0 / 3.0) * FF - 3) + 0.5 * kappa * (J - 1) ** 2
    strain = float(np.sum(V * psi))
    kinetic = float(np.sum(V * 0.5 * rho * np.sum(U ** 2, axis=1)))
    mon = read_monitor(case)
    i = int(np.argmin(np.abs(mon["Time"] - T)))
    if abs(mon["Time"][i] - T) > 1e-9:
        raise AssertionError("no monitor sample at t = %g" % T)
    ms, mk = mon["strainEnergy"][i], mon["kineticEnergy"][i]
    ds = abs(strain - ms) / (ms + mk)
    dk = abs(kinetic - mk) / (ms + mk)
    lines = ["t = %g: strain energy %.12e J from F, %.12e J monitor "
             "(%.1e); kinetic %.12e J from U, %.12e J monitor (%.1e)"
             % (T, strain, ms, ds, kinetic, mk, dk)]
    failures = []
    if not ds <= TOLERANCE:
        failures.append("strain energy differs by %.2e of the total" % ds)
    if not dk <= TOLERANCE:
        failures.append("kinetic energy differs by %.2e of the total" % dk)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mu-scale", type=float, default=1.0,
                        help="scale mu in the formula (a perturbation)")
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
