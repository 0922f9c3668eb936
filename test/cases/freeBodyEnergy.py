#!/usr/bin/python3
"""A free spinning body keeps its momenta and never gains energy, on
hexahedra, polyhedra and tetrahedra (issue 9).

    /usr/bin/python3 test/cases/freeBodyEnergy.py [--steps 1000]

tutorials/spinningCube (translating and spinning about a tilted axis, all
faces traction-free, angular momentum preservation on, default scheme) on
6^3 hexahedra, their polyhedral dual (polyDualMesh) and 4^3 hexahedra cut
into 6 tetrahedra each, the tetrahedra once more with nodalAveraging deformation,
for 1000 steps; from the solidMonitor (every step, 17 digits):
    linear drift   max_n |P_n - P_0| / |P_0|  <= 1e-12,
    angular drift  max_n |L_n - L_0| / |L_0|  <= 1e-10,
    energy         max_n (E_n+1 - E_n) / E_0  <= 1e-10.
Work folders: test/runs/freeBodyEnergy/.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, gmsh, postprocess, run, testing  # noqa: E402

NAME = "freeBodyEnergy"
LIMITS = {"linear": 1e-12, "angular": 1e-10, "energy": 1e-10}


def spin(root, label, steps):
    mesh = "tet" if label.startswith("tet") else label
    case = os.path.join(root, label)
    control = cases.precise_output()
    control.update({"maxSteps": steps, "endTime": 100,
                    "writeControl": "timeStep", "writeInterval": steps})
    touch = {"nodalAveraging": "deformation"} if label == "tetNodal" else None
    cases.prepare("spinningCube", case, n=6 if mesh != "tet" else 4,
                  control=control, initialise=(mesh == "hex"), touch=touch)
    if mesh == "poly":
        run.run(["polyDualMesh", "80", "-overwrite", "-concaveMultiCells"],
                case)
    elif mesh == "tet":
        gmsh.write_box_msh(os.path.join(case, "cube.msh"), (4, 4, 4),
                           (-0.5, -0.5, -0.5), (0.5, 0.5, 0.5),
                           {f: "surface" for f in gmsh.PATCHES})
        run.run(["gmshToFoam", "cube.msh"], case)
    if mesh != "hex":
        run.restore0(case)
        cases.set_initial_state(case)
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    drift = postprocess.momentum_drift(case)
    gain, _, _ = postprocess.energy_increase(case)
    return {"linear": drift["linear"], "angular": drift["angular"],
            "energy": gain}


def body(args):
    root = testing.work_dir(NAME)
    failures = []
    lines = []
    for mesh in ("hex", "poly", "tet", "tetNodal"):
        r = spin(root, mesh, args.steps)
        lines.append("%s: linear %.1e, angular %.1e, dE/E0 %+.1e"
                     % (mesh, r["linear"], r["angular"], r["energy"]))
        failures += ["%s %s %.2e > %g" % (mesh, key, r[key], limit)
                     for key, limit in LIMITS.items() if r[key] > limit]
    summary = "%d steps: %s" % (args.steps, "; ".join(lines))
    if failures:
        raise AssertionError("; ".join(failures) + " | " + summary)
    return summary


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=1000)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
