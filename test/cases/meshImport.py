#!/usr/bin/python3
"""Imported meshes: a gmsh geometry and an Abaqus/CalculiX .inp deck become
touchFoam cases whose patches and cellZones are the files' named groups.

    /usr/bin/python3 test/cases/meshImport.py

Extras: --with-meshing

  - tutorials/holedPlate at -n 2 (gmsh -3, gmshToFoam), 40 steps: the
    Allrun reports 'checkMesh: Mesh OK.'; checkMesh lists the patches
    left right sides hole frontAndBack and the cellZone 'plate' holding
    every cell; the mesh volume is the plate's (L H - pi R^2) t within
    1 % (the hole is a polygon); the right end pulled at v0 with the left
    end's wave not yet back, the energy never exceeds the work done,
    v0 p_x (the scheme dissipates, it must not create energy), and p_x is
    60 to 105 % of the acoustic rho c v0 A t, A = H t_z the end's area
    (release from the free edges and the smeared front only lower it).
  - a 24 x 2 x 2 C3D8 bar .inp (bin/python/touchfoam/inp.py) through
    bin/inpToGmsh and gmshToFoam: checkMesh passes and finds the cellZones
    'left' and 'right' with the element sets' cell counts (as meshio, an
    independent reader, counts them) and volumes, in x < L/2 and x > L/2,
    and the patches 'left', 'right' (ny nz faces each) and 'sides'
    (2 nx (ny + nz)), no 'defaultFaces'; the same with 'right' given as a
    node-based surface (TYPE=NODE over a node set); touchFoam runs on it
    (linearElastic, 'left' pushed at v0, 'sides' symmetric planes: uniaxial
    strain) until the front is at 3/4 of the bar: six cells behind it
    sigma_xx is -rho c v0 and sigma_yy lambda/(lambda + 2 mu) of it within
    2 % (the limited scheme's ripple behind the front), and
    p_x within 2 % of the acoustic end force's impulse rho c v0 A t.
  - refused, exit status 1, with a message naming the culprit: an element
    with its nodes in the mirror order (its label and 'negative volume'),
    a zone that is no element set (-zones left middle: 'middle' and the
    sets that exist), a surface over an undefined element set, zones that
    overlap (-zones EALL left).
Work folders: test/runs/meshImport/.
"""

import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import monitor, run, testing  # noqa: E402
from touchfoam.foamfile import header_text  # noqa: E402
from touchfoam.inp import bar_labels, write_bar_inp  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

NAME = "meshImport"

# The plate of tutorials/holedPlate (plate.geo, constant/)
PLATE = {"L": 0.2, "H": 0.1, "R": 0.02, "t": 0.005}
RHO, E, NU, V0 = 1000.0, 1e6, 0.4, 2.0

BAR_COUNTS = (24, 2, 2)
BAR_SIZE = (1.0, 0.05, 0.05)


def check_mesh(case):
    """(verdict line, {patch: faces}, {zone: (cells, volume, bbox)}) from
    checkMesh's log."""
    log = run.run(["checkMesh"], case)
    text = open(log).read()
    verdict = "Mesh OK." if re.search(r"^Mesh OK\.", text, re.M) else \
        (re.findall(r"^Failed.*", text, re.M) or ["no verdict"])[0]
    patches = {}
    block = re.search(r"Patch\s+Faces\s+Points.*?\n(.*?)\n\n", text, re.S)
    for line in (block.group(1).splitlines() if block else []):
        words = line.split()
        patches[words[0]] = int(words[1])
    zones = {}
    block = re.search(r"CellZone\s+Cells.*?\n(.*?)\n\n", text, re.S)
    for line in (block.group(1).splitlines() if block else []):
        m = re.match(r"\s*(\S+)\s+(\d+)\s+\d+\s+(\S+)\s+\((.*?)\)\s+\((.*?)\)",
                     line)
        if m:
            zones[m.group(1)] = (int(m.group(2)), float(m.group(3)),
                                 [float(v) for v in m.group(4).split()],
                                 [float(v) for v in m.group(5).split()])
    cells = int(re.search(r"^\s+cells:\s+(\d+)", text, re.M).group(1))
    volume = float(re.search(r"Total volume = (\S+?)\.\s", text).group(1))
    return verdict, patches, zones, cells, volume


def plate(root, failures, lines):
    case = run.copy_case(run.tutorial_dir("holedPlate"),
                         os.path.join(root, "holedPlate"))
    run.foam_set(case, "system/controlDict", "maxSteps", 40)
    log = run.run(["./Allrun", "-n", "2"], case, "Allrun",
                  timeout=testing.RUN_TIMEOUT)
    reported = "checkMesh: Mesh OK." in open(log).read()
    verdict, patches, zones, cells, volume = check_mesh(case)
    want = {"left", "right", "sides", "hole", "frontAndBack"}
    exact = (PLATE["L"] * PLATE["H"] - math.pi * PLATE["R"] ** 2) \
        * PLATE["t"]
    lines.append("holedPlate -n 2: %d cells, %s (Allrun %s), patches %s, "
                 "zones %s, volume %+.2f %% of (L H - pi R^2) t"
                 % (cells, verdict, "reports it" if reported else "silent",
                    " ".join(sorted(patches)), " ".join(sorted(zones)),
                    100 * (volume / exact - 1)))
    if verdict != "Mesh OK." or not reported:
        failures.append("holedPlate: checkMesh %s, Allrun %s"
                        % (verdict, "reports it" if reported else "silent"))
    if set(patches) != want or min(patches.values()) == 0:
        failures.append("holedPlate patches %s, expected %s"
                        % (patches, sorted(want)))
    if set(zones) != {"plate"} or zones["plate"][0] != cells:
        failures.append("holedPlate cellZones %s, expected 'plate' with "
                        "all %d cells" % (zones, cells))
    if abs(volume / exact - 1) > 0.01:
        failures.append("holedPlate volume %.6g, plate %.6g" % (volume,
                                                                 exact))

    # Energy balance while the left end is at rest: E = v0 p_x - dissipated
    mon = monitor.read_monitor(case)
    t, px, energy = mon["Time"], mon["px"], mon["totalEnergy"]
    lam = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E / (2 * (1 + NU))
    c = math.sqrt((lam + 2 * mu) / RHO)
    work = V0 * px
    excess = max((energy - work) / work)
    acoustic = RHO * c * V0 * PLATE["H"] * PLATE["t"] * t
    ratio = px / acoustic
    lines.append("%d steps to t = %.3g ms: E/(v0 p_x) <= %.3f, p_x/(rho c "
                 "v0 A t) %.3f..%.3f" % (len(t), 1e3 * t[-1],
                                           1 + excess, ratio.min(),
                                           ratio.max()))
    if len(t) != 40 or t[-1] * c > PLATE["L"]:
        failures.append("holedPlate ran %d steps to %g s" % (len(t), t[-1]))
    if excess > 1e-12:
        failures.append("holedPlate energy above the work done by %.2e"
                        % excess)
    if ratio.min() < 0.6 or ratio.max() > 1.05:
        failures.append("holedPlate momentum %.3f..%.3f of the acoustic one"
                        % (ratio.min(), ratio.max()))


def convert(case, inp, *options):
    """inpToGmsh then gmshToFoam in case; returns checkMesh's findings."""
    tool = os.path.join(run.project_dir(), "bin", "inpToGmsh")
    run.run([tool, inp, "-o", "mesh.msh"] + list(options), case, "inpToGmsh")
    run.run(["gmshToFoam", "mesh.msh"], case)
    return check_mesh(case)


def foam_case(path):
    """An empty case folder with the system files checkMesh needs."""
    tutorial = run.tutorial_dir("holedPlate")
    os.makedirs(os.path.join(path, "system"), exist_ok=True)
    for name in ("controlDict", "fvSchemes", "fvSolution"):
        with open(os.path.join(tutorial, "system", name)) as f:
            text = f.read()
        with open(os.path.join(path, "system", name), "w") as f:
            f.write(text)
    return path


def bar(root, failures, lines):
    nx, ny, nz = BAR_COUNTS
    length, width, height = BAR_SIZE
    case = foam_case(os.path.join(root, "bar"))
    counts = write_bar_inp(os.path.join(case, "bar.inp"), BAR_COUNTS,
                           BAR_SIZE)

    # meshio, an independent reader, counts the sets of the deck
    try:
        import meshio
        deck = meshio.read(os.path.join(case, "bar.inp"), "abaqus")
        independent = {k: sum(len(v) for v in deck.cell_sets[k])
                       for k in ("left", "right")}
    except ImportError:
        raise run.RunError("python3-meshio is not installed: "
                           "bin/touchSetup --with-meshing")
    if independent != counts:
        failures.append("bar.inp: meshio counts %s, the generator %s"
                        % (independent, counts))

    verdict, patches, zones, cells, _ = convert(case, "bar.inp")
    half = 0.5 * length
    cell_volume = length * width * height / (nx * ny * nz)
    want_patches = {"left": ny * nz, "right": ny * nz,
                    "sides": 2 * nx * (ny + nz)}
    lines.append("bar.inp %dx%dx%d: %s, cellZones %s, patches %s"
                 % (nx, ny, nz, verdict,
                    " ".join("%s %d" % (k, v[0]) for k, v in
                             sorted(zones.items())),
                    " ".join("%s %d" % kv for kv in sorted(patches.items()))))
    if verdict != "Mesh OK.":
        failures.append("bar: checkMesh %s" % verdict)
    if set(zones) != {"left", "right"}:
        failures.append("bar cellZones %s, expected left right"
                        % sorted(zones))
    else:
        for name, (lo, hi) in (("left", (0, half)), ("right", (half,
                                                               length))):
            n, volume, bmin, bmax = zones[name]
            if n != independent[name] \
                    or abs(volume - n * cell_volume) > 1e-12 \
                    or abs(bmin[0] - lo) > 1e-12 or abs(bmax[0] - hi) > 1e-12:
                failures.append("bar cellZone %s: %d cells, volume %g, x "
                                "%g..%g; expected %d, %g, %g..%g"
                                % (name, n, volume, bmin[0], bmax[0],
                                   independent[name], n * cell_volume, lo,
                                   hi))
    if patches != want_patches:
        failures.append("bar patches %s, expected %s" % (patches,
                                                         want_patches))

    # The right end as a node-based surface over a node set
    node, _ = bar_labels(BAR_COUNTS)
    with open(os.path.join(case, "bar.inp")) as f:
        text = f.read()
    start = text.index("*SURFACE, NAME=right")
    end = text.index("*SURFACE", start + 1)
    text = text[:start] + "*NSET, NSET=NXMAX\n" \
        + ", ".join(str(v) for v in sorted(node[-1].ravel())) + "\n" \
        + "*SURFACE, NAME=right, TYPE=NODE\nNXMAX\n" + text[end:]
    nodecase = foam_case(os.path.join(root, "barNodeSurface"))
    with open(os.path.join(nodecase, "bar.inp"), "w") as f:
        f.write(text)
    verdict, patches, _, _, _ = convert(nodecase, "bar.inp")
    lines.append("node-based 'right': %d faces" % patches.get("right", 0))
    if verdict != "Mesh OK." or patches != want_patches:
        failures.append("bar with a node surface: %s, patches %s"
                        % (verdict, patches))
    run_bar(case, failures, lines)


def run_bar(case, failures, lines):
    """touchFoam on the converted bar: its end 'left' pushed at v0, the
    'sides' symmetric planes (uniaxial strain), linearElastic; until the
    wave reaches the far end the momentum is the impulse of the acoustic
    end force, p_x = rho c v0 A t."""
    length, width, height = BAR_SIZE
    rho, e, nu, v0 = 7800.0, 2e11, 0.3, 1.0
    with open(os.path.join(case, "constant", "mechanicalProperties"),
              "w") as f:
        f.write(header_text("dictionary", "mechanicalProperties",
                            "constant")
                + "model linearElastic;\nrho %g;\nE %g;\nnu %g;\n"
                % (rho, e, nu))
    os.makedirs(os.path.join(case, "0"), exist_ok=True)
    with open(os.path.join(case, "0", "lm"), "w") as f:
        f.write(header_text("volVectorField", "lm", "0")
                + "dimensions [1 -2 -1 0 0 0 0];\n"
                "internalField uniform (0 0 0);\nboundaryField\n{\n"
                "    left { type prescribedVelocity; velocity uniform "
                "(%g 0 0); value uniform (0 0 0); }\n"
                "    right { type traction; value uniform (0 0 0); }\n"
                "    sides { type symmetricPlane; value uniform (0 0 0); }\n"
                "}\n" % v0)
    nx, ny, nz = BAR_COUNTS
    # The front to 3/4 of the bar at CFL 0.3 on the smallest cell size
    h = min(length / nx, width / ny, height / nz)
    steps = int(0.75 * length / (0.3 * h))
    run.foam_set(case, "system/controlDict", "maxSteps", steps)
    run.foam_set(case, "system/controlDict", "endTime", 1)
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    mon = monitor.read_monitor(case)
    t, px = mon["Time"], mon["px"]
    lam = e * nu / ((1 + nu) * (1 - 2 * nu))
    mu = e / (2 * (1 + nu))
    c = math.sqrt((lam + 2 * mu) / rho)
    front = c * t[-1]
    momentum = px[-1] / (rho * c * v0 * width * height * t[-1])

    # The plateau behind the front, six cells clear of its spread
    centres = PolyMesh(case).cell_centres
    sigma = testing.read_internal(run.latest_time_dir(case), "sigma",
                                  len(centres))
    behind = centres[:, 0] < front - 6 * length / nx
    xx, yy = sigma[behind, 0], sigma[behind, 3]
    plateau = -rho * c * v0
    lateral = lam / (lam + 2 * mu) * plateau
    error = max(abs(xx / plateau - 1).max(), abs(yy / lateral - 1).max())
    lines.append("touchFoam on it, %d steps, front at %.2f L: p_x %.4f of "
                 "rho c v0 A t, sigma_xx and sigma_yy of %d cells behind "
                 "the front within %.1e of -rho c v0 and its lambda/(lambda "
                 "+ 2 mu)" % (len(t), front / length, momentum,
                              behind.sum(), error))
    if len(t) != steps or front > length or behind.sum() < nx / 4 \
            or abs(momentum - 1) > 0.02 or error > 0.02:
        failures.append("bar run: %d steps, front at %.2f L, p_x %.4f of "
                        "the acoustic one, stress error %.2e"
                        % (len(t), front / length, momentum, error))


def refused(root, failures, lines):
    tool = os.path.join(run.project_dir(), "bin", "inpToGmsh")
    folder = os.path.join(root, "refused")
    os.makedirs(folder)
    write_bar_inp(os.path.join(folder, "bar.inp"), BAR_COUNTS, BAR_SIZE)
    write_bar_inp(os.path.join(folder, "inverted.inp"), BAR_COUNTS,
                  BAR_SIZE, inverted=(17,))
    with open(os.path.join(folder, "bar.inp")) as f:
        text = f.read()
    with open(os.path.join(folder, "undefined.inp"), "w") as f:
        f.write(text + "*SURFACE, NAME=extra\nENDS, S4\n")
    cases = [
        ("inverted", ["inverted.inp"],
         ["inverted.inp", "element 17", "negative volume", "mirror order"]),
        ("missing zone", ["bar.inp", "-zones", "left", "middle"],
         ["'middle' is not defined", "EALL left right"]),
        ("undefined set", ["undefined.inp"],
         ["undefined.inp", "element set 'ENDS' is not defined"]),
        ("overlap", ["bar.inp", "-zones", "EALL", "left"],
         ["element sets EALL and left", "-zones"]),
    ]
    ok = []
    for label, args, words in cases:
        proc = subprocess.run([tool] + args + ["-o", "x.msh"], cwd=folder,
                              capture_output=True, text=True)
        message = proc.stderr.strip()
        missing = [w for w in words if w not in message]
        if proc.returncode != 1 or missing or os.path.exists(
                os.path.join(folder, "x.msh")):
            failures.append("%s: exit %d, missing %s in %r"
                            % (label, proc.returncode, missing, message))
        else:
            ok.append(label)
    lines.append("refused: %s" % ", ".join(ok))


def body():
    root = testing.work_dir(NAME)
    failures, lines = [], []
    plate(root, failures, lines)
    bar(root, failures, lines)
    refused(root, failures, lines)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
