#!/usr/bin/python3
"""One material per cellZone: a bar of two materials from an Abaqus/CalculiX
.inp deck (two element sets -> two cellZones -> two laws in the 'materials'
dictionary of constant/mechanicalProperties).

    /usr/bin/python3 test/cases/bimaterial.py

Extras: --with-meshing
(gmsh for bin/inpToGmsh; gmshToFoam is OpenFOAM's)

  - a 1D bar in uniaxial strain (200 x 1 x 1 C3D8, 'sides' symmetric
    planes), 'left' zone rho1, 'right' zone rho2 = 4 rho1, the same E and
    nu (linearElastic): Z2 = 2 Z1.  The end 'left' pushed at v0 sends the
    stress wave -Z1 v0; after it has crossed the interface (x = L/2) and
    before the reflection is back at the pushed end, the plateau of the
    right zone holds the transmitted stress, 2 Z2/(Z1 + Z2) = 4/3 of the
    incident one, and the plateau of the left zone behind the reflected
    front the incident plus the reflected one, (Z2 - Z1)/(Z1 + Z2) = 1/3
    of it: both within 1 % (mean over the plateau cells), for the
    compatible and the constrained F update;
  - a free bimaterial bar (ends traction-free, sides symmetric), started
    from 0/U = v0 cos(pi x/L) x: the initial kinetic energy is
    sum 1/2 rho_cell V U^2 to 1e-12 (each cell's own density), p_x stays
    its initial sum rho V U_x to 1e-10 of rho2 v0 V_bar, and the total
    energy never grows over the run (1e-12 relative slack);
  - both zones vonMisesPlastic (the right one's yieldStress 1e5 Pa below
    the transmitted wave's von Mises stress, the left one's 1e6): each
    zone's state is written under its name (epsilonP.right, CpInv.left,
    ...), epsilonP.right grows in its zone, each zone's field stays
    exactly 0 in the other, and 250 + 250 steps with a restart from the
    written time end where 500 steps do, to 1e-12 (lm, F, both zones'
    epsilonP and CpInv);
  - a decomposed run (2 ranks, the cut on the interface) equals the serial
    one to 1e-10 of the fields' largest values (sigma, U): the sums of
    the cut faces' points come in another order, and 800 steps carry that
    round-off (measured 6.5e-12 on 2026-12-04);
  - refused with a FatalIOError naming the culprit: a zone missing from
    'materials' ('in no listed zone' and the mesh's zones), a zone that is
    not in the mesh ('middle' and the valid names), 'materials' with the
    single law's entries beside it, angularMomentumPreservation on and
    nodal averaging with several materials (both assume one law).
Work folders: test/runs/bimaterial/.
"""

import math
import os
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import foamfile, monitor, run, testing  # noqa: E402
from touchfoam.foamfile import header_text  # noqa: E402
from touchfoam.inp import write_bar_inp  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

NAME = "bimaterial"

COUNTS = (200, 1, 1)
SIZE = (1.0, 0.005, 0.005)
RHO1, E, NU, V0 = 2000.0, 2e9, 0.3, 0.1
RHO2 = 4 * RHO1
TOL = 0.01


def law(rho):
    return ("{ model linearElastic; rho %.17g; E %.17g; nu %.17g; }"
            % (rho, E, NU))


def write_properties(case, text):
    with open(os.path.join(case, "constant", "mechanicalProperties"),
              "w") as f:
        f.write(header_text("dictionary", "mechanicalProperties",
                            "constant") + text)


def materials(zones):
    return "materials\n{\n%s}\n" % "".join(
        "    %s %s\n" % (name, law(rho)) for name, rho in zones)


def make_case(root, name):
    """The bar deck converted into a case; returns its folder."""
    case = os.path.join(root, name)
    if os.path.isdir(case):
        shutil.rmtree(case)
    tutorial = run.tutorial_dir("holedPlate")
    os.makedirs(os.path.join(case, "system"))
    os.makedirs(os.path.join(case, "constant"))
    for entry in ("controlDict", "fvSchemes", "fvSolution",
                  "decomposeParDict"):
        shutil.copy(os.path.join(tutorial, "system", entry),
                    os.path.join(case, "system", entry))
    write_bar_inp(os.path.join(case, "bar.inp"), COUNTS, SIZE)
    tool = os.path.join(run.project_dir(), "bin", "inpToGmsh")
    run.run([tool, "bar.inp", "-o", "mesh.msh"], case, "inpToGmsh")
    run.run(["gmshToFoam", "mesh.msh"], case)
    write_properties(case, materials([("left", RHO1), ("right", RHO2)]))
    return case


def write_velocity(case, name, internal, left, right):
    os.makedirs(os.path.join(case, "0"), exist_ok=True)
    dims = "[0 1 -1 0 0 0 0]" if name == "U" else "[1 -2 -1 0 0 0 0]"
    with open(os.path.join(case, "0", name), "w") as f:
        f.write(header_text("volVectorField", name, "0")
                + "dimensions %s;\n" % dims
                + "internalField %s;\nboundaryField\n{\n" % internal
                + "    left %s\n    right %s\n" % (left, right)
                + "    sides { type symmetricPlane; value uniform (0 0 0); }"
                "\n}\n")


def impedances():
    lam = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E / (2 * (1 + NU))
    c1 = math.sqrt((lam + 2 * mu) / RHO1)
    c2 = math.sqrt((lam + 2 * mu) / RHO2)
    return c1, c2, RHO1 * c1, RHO2 * c2


def wave(root, update, lines, failures):
    """Transmitted and reflected plateaus against the closed form."""
    case = make_case(root, "wave-" + update)
    run.foam_set(case, "system/fvSolution", "TOUCH/FUpdate", update)
    write_velocity(case, "lm", "uniform (0 0 0)",
                   "{ type prescribedVelocity; velocity uniform (%g 0 0); "
                   "value uniform (0 0 0); }" % V0,
                   "{ type traction; value uniform (0 0 0); }")
    length = SIZE[0]
    h = length / COUNTS[0]
    c1, c2, z1, z2 = impedances()
    # The incident front at the interface, then 0.85 of the way back
    end = 0.5 * length / c1 + 0.85 * 0.5 * length / c1
    run.foam_set(case, "system/controlDict", "endTime", end)
    run.foam_set(case, "system/controlDict", "writeInterval", end)
    run.foam_set(case, "system/controlDict", "maxSteps", 100000)
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    latest = run.latest_time_dir(case)
    t = float(os.path.basename(latest))
    after = t - 0.5 * length / c1
    reflected_front = 0.5 * length - c1 * after
    transmitted_front = 0.5 * length + c2 * after
    x = PolyMesh(case).cell_centres[:, 0]
    sigma = testing.read_internal(latest, "sigma", len(x))[:, 0]
    incident = -z1 * V0
    left = (x > reflected_front + 8 * h) & (x < 0.5 * length - 4 * h)
    right = (x > 0.5 * length + 4 * h) & (x < transmitted_front - 8 * h)
    want_t = 2 * z2 / (z1 + z2)
    want_r = (z2 - z1) / (z1 + z2)
    got_t = sigma[right].mean() / incident
    got_r = sigma[left].mean() / incident - 1
    spread_t = np.abs(sigma[right] / incident / want_t - 1).max()
    lines.append("%s: Z2/Z1 %.3f, t %.3g s; transmitted %.5f (closed form "
                 "%.5f, %d cells, largest cell off by %.1e), reflected "
                 "%.5f (closed form %.5f, %d cells)"
                 % (update, z2 / z1, t, got_t, want_t, right.sum(), spread_t,
                    got_r, want_r, left.sum()))
    if right.sum() < 10 or left.sum() < 10:
        failures.append("%s: plateaus of %d and %d cells" %
                        (update, right.sum(), left.sum()))
    if abs(got_t / want_t - 1) > TOL:
        failures.append("%s: transmitted ratio %.5f, closed form %.5f"
                        % (update, got_t, want_t))
    # 1 % of the reflected stress is 1/4 % of the left plateau's
    if abs(got_r - want_r) > TOL * want_r:
        failures.append("%s: reflected ratio %.5f, closed form %.5f"
                        % (update, got_r, want_r))
    return case


def free_body(root, lines, failures):
    """Energy and momentum of a free bimaterial bar."""
    case = make_case(root, "free")
    x = PolyMesh(case).cell_centres
    length = SIZE[0]
    u = V0 * np.cos(math.pi * x[:, 0] / length)
    internal = "nonuniform List<vector> %d\n(\n%s)\n" % (
        len(u), "".join("(%.17g 0 0)\n" % v for v in u))
    free = "{ type traction; value uniform (0 0 0); }"
    write_velocity(case, "U", internal, free, free)
    c1 = impedances()[0]
    end = 1.5 * length / c1
    run.foam_set(case, "system/controlDict", "endTime", end)
    run.foam_set(case, "system/controlDict", "writeInterval", end)
    run.foam_set(case, "system/controlDict", "maxSteps", 100000)
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    mon = monitor.read_monitor(case)
    volume = SIZE[0] * SIZE[1] * SIZE[2] / COUNTS[0]
    rho = np.where(x[:, 0] < 0.5 * length, RHO1, RHO2)
    kinetic0 = 0.5 * (rho * volume * u ** 2).sum()
    px0 = (rho * volume * u).sum()
    scale = RHO2 * V0 * SIZE[0] * SIZE[1] * SIZE[2]
    total = mon["totalEnergy"]
    growth = (np.diff(total) / total[0]).max()
    drift = np.abs(mon["px"] - px0).max() / scale
    k0 = mon["kineticEnergy"][0]
    # The monitor's first row is the end of the first step: the energy
    # at the start is the closed form, its first step may only lose
    lines.append("free bar: %d steps, E_total %.6e -> %.6e (largest step "
                 "gain %.1e of E0), kinetic at start (closed form) %.6e, "
                 "first step %.6e; p_x drift %.1e of rho2 v0 V"
                 % (len(total), total[0], total[-1], max(growth, 0),
                    kinetic0, k0, drift))
    if growth > 1e-12 or total[0] > kinetic0 * (1 + 1e-12):
        failures.append("free bar: the energy grew (step gain %.2e, first "
                        "%.6e above %.6e)" % (growth, total[0], kinetic0))
    if drift > 1e-10:
        failures.append("free bar: p_x drifts by %.2e" % drift)
    if not 0.9 * kinetic0 < total[0] <= kinetic0 * (1 + 1e-12):
        failures.append("free bar: first total energy %.6e, initial "
                        "kinetic sum 1/2 rho_c V U^2 %.6e" % (total[0],
                                                              kinetic0))
    return case


def plastic_restart(root, lines, failures):
    """Two zones with a law with state (vonMisesPlastic both): each zone's
    state fields carry its name (epsilonP.left, epsilonP.right), each stays
    in its zone, and a restart from a written time continues as the
    uninterrupted run."""
    base = make_case(root, "plastic")
    plastic = ("{ model vonMisesPlastic; rho %.17g; E %.17g; nu %.17g; "
               "vonMisesPlasticCoeffs { yieldStress %g; "
               "hardeningModulus 1e8; } }")
    write_properties(base, "materials\n{\n    left %s\n    right %s\n}\n"
                     % (plastic % (RHO1, E, NU, 1e6),
                        plastic % (RHO2, E, NU, 1e5)))
    write_velocity(base, "lm", "uniform (0 0 0)",
                   "{ type prescribedVelocity; velocity uniform (%g 0 0); "
                   "value uniform (0 0 0); }" % V0,
                   "{ type traction; value uniform (0 0 0); }")
    for key, value in (("endTime", 1), ("writeControl", "timeStep"),
                       ("startFrom", "latestTime"), ("writePrecision", 17)):
        run.foam_set(base, "system/controlDict", key, value)
    runs = {}
    for label, parts in (("whole", [500]), ("restarted", [250, 250])):
        case = os.path.join(root, "plastic-" + label)
        if os.path.isdir(case):
            shutil.rmtree(case)
        shutil.copytree(base, case)
        for steps in parts:
            run.foam_set(case, "system/controlDict", "maxSteps", steps)
            run.foam_set(case, "system/controlDict", "writeInterval", steps)
            run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
        runs[label] = run.latest_time_dir(case)
    x = PolyMesh(base).cell_centres[:, 0]
    n = len(x)
    left = x < 0.5 * SIZE[0]
    eps = {zone: testing.read_internal(runs["whole"], "epsilonP." + zone, n)
           for zone in ("left", "right")}
    for name in ("epsilonP", "CpInv"):
        if os.path.exists(os.path.join(runs["whole"], name)):
            failures.append("plastic zones: a field '%s' without a zone's "
                            "name was written" % name)
    worst = 0.0
    for field in ("lm", "F", "epsilonP.left", "epsilonP.right",
                  "CpInv.left", "CpInv.right"):
        a = foamfile.read_field(os.path.join(runs["whole"], field))
        b = foamfile.read_field(os.path.join(runs["restarted"], field))
        worst = max(worst, testing.relative_max_difference(
            b.internal(n), a.internal(n)))
    lines.append("plastic zones: epsilonP.right max %.2e in its zone, %.1e "
                 "in the other; epsilonP.left (yield 10x higher) max %.2e in "
                 "its zone, %.1e in the other; restart after 250 of 500 "
                 "steps: %.1e from the whole run (%s)"
                 % (eps["right"][~left].max(), np.abs(eps["right"][left]).max(),
                    eps["left"][left].max(), np.abs(eps["left"][~left]).max(),
                    worst, os.path.basename(runs["whole"])))
    if not eps["right"][~left].max() > 0 \
            or np.abs(eps["right"][left]).max() != 0 \
            or np.abs(eps["left"][~left]).max() != 0:
        failures.append("plastic zones: epsilonP.right %.2e in it, %.2e "
                        "outside; epsilonP.left %.2e outside its zone"
                        % (eps["right"][~left].max(),
                           np.abs(eps["right"][left]).max(),
                           np.abs(eps["left"][~left]).max()))
    if eps["left"][left].max() >= eps["right"][~left].max():
        failures.append("plastic zones: the left zone (yield 1e6) flowed "
                        "%.2e, not less than the right (yield 1e5) %.2e"
                        % (eps["left"][left].max(), eps["right"][~left].max()))
    if os.path.basename(runs["whole"]) != \
            os.path.basename(runs["restarted"]) or worst > 1e-12:
        failures.append("plastic restart: %.2e from the whole run" % worst)


def parallel(root, serial, lines, failures):
    """Two ranks cut at the interface equal the serial run."""
    case = os.path.join(root, "wave-parallel")
    if os.path.isdir(case):
        shutil.rmtree(case)
    shutil.copytree(serial, case, ignore=shutil.ignore_patterns(
        "processor*", "[1-9]*", "0.[0-9]*", "postProcessing", "log.*"))
    run.write_options(case, "system/decomposeOptions", {
        "numberOfSubdomains": 2, "method": "simple",
        "simpleCoeffs": {"n": "(2 1 1)"}})
    run.run(["decomposePar", "-force"], case)
    run.run_parallel(["touchFoam"], case, 2, timeout=testing.RUN_TIMEOUT)
    run.run(["reconstructPar", "-latestTime"], case)
    a_dir, b_dir = run.latest_time_dir(serial), run.latest_time_dir(case)
    n = PolyMesh(serial).n_cells
    worst = 0.0
    for field in ("sigma", "U"):
        a = foamfile.read_field(os.path.join(a_dir, field)).internal(n)
        b = foamfile.read_field(os.path.join(b_dir, field)).internal(n)
        worst = max(worst, testing.relative_max_difference(b, a))
    lines.append("2 ranks cut at the interface: max relative difference "
                 "to serial %.1e (sigma, U) at %s"
                 % (worst, os.path.basename(b_dir)))
    if os.path.basename(a_dir) != os.path.basename(b_dir) or worst > 1e-10:
        failures.append("parallel: %.2e from serial" % worst)


def refused(root, serial, lines, failures):
    """Bad 'materials' dictionaries, each with the words that must say
    why."""
    cases = [
        ("missing zone", materials([("left", RHO1)]),
         ["mechanicalProperties", "materials", "in no listed zone",
          "The mesh's cellZones", "right"]),
        ("unknown zone", materials([("left", RHO1), ("right", RHO2),
                                    ("middle", RHO1)]),
         ["mechanicalProperties", "'middle' is not a cellZone",
          "The mesh's cellZones", "left", "right"]),
        ("flat and materials", "model linearElastic;\nrho 1000;\n"
         + materials([("left", RHO1), ("right", RHO2)]),
         ["mechanicalProperties", "use one form", "model", "rho"]),
    ]
    two = materials([("left", RHO1), ("right", RHO2)])
    controls = [
        ("angular momentum preservation", two,
         ["fvSolution", "angularMomentumPreservation",
          "several materials", "set angularMomentumPreservation off"],
         ("TOUCH/angularMomentumPreservation", "on")),
        ("nodal averaging", two,
         ["fvSolution", "nodalAveraging deformation",
          "several materials", "nodalAveraging off"],
         ("TOUCH/nodalAveraging", "deformation")),
    ]
    cases = [c + (None,) for c in cases] + controls
    for label, text, words, control in cases:
        case = os.path.join(root, "refused-" + label.replace(" ", "-"))
        if os.path.isdir(case):
            shutil.rmtree(case)
        shutil.copytree(serial, case, ignore=shutil.ignore_patterns(
            "processor*", "[1-9]*", "0.[0-9]*", "postProcessing", "log.*"))
        write_properties(case, text)
        if control:
            run.foam_set(case, "system/fvSolution", *control)
        log = os.path.join(case, "log.touchFoam")
        with open(log, "w") as f:
            status = subprocess.call(["touchFoam"], cwd=case, stdout=f,
                                     stderr=subprocess.STDOUT,
                                     stdin=subprocess.DEVNULL,
                                     timeout=testing.RUN_TIMEOUT)
        out = " ".join(open(log).read().split())
        missing = [w for w in words if w not in out]
        lines.append("%s: exit %d, %s" % (
            label, status, "message names %s" % ", ".join(words)
            if not missing else "missing %s" % missing))
        if status == 0 or missing or "FOAM FATAL IO ERROR" not in out:
            failures.append("%s: exit %d, missing %s" % (label, status,
                                                         missing))


def body():
    root = testing.work_dir(NAME)
    failures, lines = [], []
    serial = wave(root, "compatible", lines, failures)
    wave(root, "constrained", lines, failures)
    free_body(root, lines, failures)
    plastic_restart(root, lines, failures)
    parallel(root, serial, lines, failures)
    refused(root, serial, lines, failures)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
