#!/usr/bin/python3
"""The output fields under OpenFOAM's names, what they hold, what ParaView
gets of them, and a restart from a time folder with the former names.

    /usr/bin/python3 test/cases/outputFields.py [--steps 40]

Runs tutorials/taylorImpact at -n 3 (240 cells, vonMisesPlastic, the bar's
end on the rigid wall 'wall' from t = 0) for N = --steps steps, written at
N/2 and N with 17 digits, so that equal numbers are equal doubles.

Asserted at the end:
  names     lm F D pointD U P sigma sigmaEq pressure J contact (and the
            law's epsilonP CpInv) are written; v, u and pointU are not;
  values    U = lm/rho (rho of constant/mechanicalProperties) to 1e-15,
            sigmaEq = sqrt(3/2 dev(sigma) && dev(sigma)), pressure =
            -tr(sigma)/3 and J = det F of the written sigma and F to 1e-12;
            on the patch 'wall', F, P, sigma, sigmaEq, pressure, J and D
            hold the values of the faces' cells (they held I, 0 and 1
            before, which ParaView drew as zero stress on the surface);
  yield     the von Mises equivalent of the Kirchhoff stress, J sigmaEq,
            is nowhere above the yield stress of the cell's plastic
            strain, yieldStress + hardeningModulus epsilonP (1e-9), and
            equals it in the cells that yield (max ratio within 1e-9 of
            1): the law's own yield condition, seen through sigmaEq;
  contact   the patch values of 'contact' on 'wall' equal the active set
            the wall writes in lm (its entry 'contact'), some face is in
            contact, and a cell is 1 exactly when one of its wall faces is
            in contact, 0 else;
  ParaView  foamToVTK writes 'contact' as cell data of the wall patch
            (VTK/*/boundary/wall.vtp) with the same values, and pointD as
            point data of the internal mesh (Warp By Vector);
  decomposed  the same run on 2 ranks (metis), not reconstructed:
            'mpirun -np 2 foamToVTK -parallel' writes one file of all 240
            cells whose sigmaEq and wall contact are the serial run's
            (sorted: the cells come in processor order) to 1e-12;
  restart   from the folder at N/2 with D, pointD, U renamed u, pointU, v
            (a folder of the former names) the run ends with the straight
            run's lm, F, gradD, D and pointD bit for bit, says in its log
            that it read u and pointU, and writes D and pointD; a control
            with the displacements deleted ends with another D (so the
            test sees whether they are read).
Work folders: test/runs/outputFields/.
"""

import argparse
import glob
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, foamfile, mesh, run, testing  # noqa: E402

NAME = "outputFields"
WALL = "wall"
WRITTEN = ("lm", "F", "gradD", "D", "pointD", "U", "P", "sigma", "sigmaEq",
           "pressure", "J", "contact", "epsilonP", "CpInv")
FORMER = ("v", "u", "pointU")
STATE = ("lm", "F", "gradD", "D", "pointD")
#: renamed in the restart folder: new name -> former name
RENAMED = {"D": "u", "pointD": "pointU", "U": "v"}


def field(folder, name, n):
    path = os.path.join(folder, name)
    if not os.path.exists(path):
        raise AssertionError("%s: no field %s" % (folder, name))
    return np.asarray(foamfile.read_field(path).internal(n), float)


def patch_values(folder, name, entry, n_faces, ncomp=1):
    """The values of entry ('value', 'contact') of field name's patch
    WALL: one per face (of ncomp components)."""
    text = foamfile.FoamField(os.path.join(folder, name)) \
        .boundary_patches()[WALL]
    m = re.search(r"\b%s\s+uniform\s+([^;]+);" % entry, text)
    if m:
        value = foamfile.parse_numbers(m.group(1))
        return np.tile(value, (n_faces, 1)) if ncomp > 1 \
            else np.full(n_faces, value[0])
    m = re.search(r"\b%s\s+nonuniform\s+List<\w+>\s*" % entry, text)
    if not m:
        raise AssertionError("%s/%s: no '%s' on patch %s"
                             % (folder, name, entry, WALL))
    return np.asarray(foamfile.parse_list(text, m.end(), ncomp)[0], float)


def von_mises(s):
    """sqrt(3/2 dev(s) && dev(s)) of symmTensors (xx xy xz yy yz zz)."""
    p = (s[:, 0] + s[:, 3] + s[:, 5]) / 3
    dev2 = ((s[:, 0] - p) ** 2 + (s[:, 3] - p) ** 2 + (s[:, 5] - p) ** 2
            + 2 * (s[:, 1] ** 2 + s[:, 2] ** 2 + s[:, 4] ** 2))
    return np.sqrt(1.5 * dev2)


def vtk_array(path, name, section):
    """The values of DataArray name in section (CellData, PointData) of
    an ASCII VTK XML file."""
    text = open(path).read()
    block = re.search(r"<%s>(.*?)</%s>" % (section, section), text, re.S)
    if not block:
        return None
    m = re.search(r"<DataArray[^>]*Name='%s'[^>]*>(.*?)</DataArray>" % name,
                  block.group(1), re.S)
    return None if not m else np.array(m.group(1).split(), float)


def check_values(end, case, m, lines, failures):
    n = m.n_cells
    mat = cases.material(case)
    lm, U = field(end, "lm", n), field(end, "U", n)
    sigma, F = field(end, "sigma", n), field(end, "F", n)
    J = field(end, "J", n)
    d_U = testing.relative_max_difference(U, lm / mat["rho"])
    d_eq = testing.relative_max_difference(field(end, "sigmaEq", n),
                                           von_mises(sigma))
    d_p = testing.relative_max_difference(
        field(end, "pressure", n), -(sigma[:, 0] + sigma[:, 3]
                                     + sigma[:, 5]) / 3)
    d_J = testing.relative_max_difference(
        J, np.linalg.det(F.reshape(-1, 3, 3)))
    lines.append("U - lm/rho %.1e, sigmaEq %.1e, pressure %.1e, J %.1e"
                 % (d_U, d_eq, d_p, d_J))
    for label, d, tol in (("U", d_U, 1e-15), ("sigmaEq", d_eq, 1e-12),
                          ("pressure", d_p, 1e-12), ("J", d_J, 1e-12)):
        if not d <= tol:
            failures.append("%s differs from its definition by %.2e > %g"
                            % (label, d, tol))

    p = m.patch(WALL)
    owners = m.owner[p["startFace"]:p["startFace"] + p["nFaces"]]
    stale = []
    for name, ncomp in (("F", 9), ("P", 9), ("sigma", 6), ("sigmaEq", 1),
                        ("pressure", 1), ("J", 1), ("D", 3)):
        cells = field(end, name, n)[owners]
        if not np.array_equal(patch_values(end, name, "value", p["nFaces"],
                                           ncomp), cells):
            stale.append(name)
    lines.append("on patch %s the cells' values: %s"
                 % (WALL, "yes" if not stale else "not " + " ".join(stale)))
    if stale:
        failures.append("%s on patch %s are not the values of the faces' "
                        "cells" % (" ".join(stale), WALL))

    props = foamfile.read_dict(os.path.join(case, "constant",
                                            "mechanicalProperties"))
    eps = field(end, "epsilonP", n)
    coeffs = props["vonMisesPlasticCoeffs"]
    flow = float(coeffs["yieldStress"]) \
        + float(coeffs["hardeningModulus"]) * eps
    ratio = J * field(end, "sigmaEq", n) / flow
    plastic = int(np.count_nonzero(eps > 0))
    lines.append("J sigmaEq / (yieldStress + H epsilonP): max 1 %+.1e "
                 "(%d cells plastic)" % (ratio.max() - 1, plastic))
    if plastic == 0:
        failures.append("no cell plastic: the yield check sees nothing")
    if not abs(ratio.max() - 1) <= 1e-9:
        failures.append("largest J sigmaEq / flow stress %.12f, not 1: "
                        "sigmaEq is not the law's von Mises stress"
                        % ratio.max())


def check_contact(end, m, lines, failures):
    p = m.patch(WALL)
    n_wall = p["nFaces"]
    active = patch_values(end, "lm", "contact", n_wall)
    shown = patch_values(end, "contact", "value", n_wall)
    cells = field(end, "contact", m.n_cells)
    owners = m.owner[p["startFace"]:p["startFace"] + n_wall]
    expected = np.zeros(m.n_cells)
    expected[owners[active > 0.5]] = 1
    lines.append("contact: %d of %d wall faces, %d cells"
                 % (int(active.sum()), n_wall, int(cells.sum())))
    if not active.any():
        failures.append("no wall face in contact at the end")
    if not np.array_equal(shown, active):
        failures.append("contact on patch %s %s, the wall's active set %s"
                        % (WALL, shown, active))
    if not np.array_equal(cells, expected):
        failures.append("contact in the cells is not 1 exactly at the "
                        "cells of the faces in contact")
    return shown


def check_vtk(case, end_name, wall_contact, lines, failures):
    run.run(["foamToVTK", "-ascii", "-latestTime"], case)
    folder = vtk_folder(case)
    wall = vtk_array(os.path.join(folder, "boundary", WALL + ".vtp"),
                     "contact", "CellData")
    pointD = vtk_array(os.path.join(folder, "internal.vtu"), "pointD",
                       "PointData")
    if wall is None or not np.array_equal(wall, wall_contact):
        failures.append("foamToVTK: contact on %s.vtp %s, the field's %s"
                        % (WALL, wall, wall_contact))
    if pointD is None:
        failures.append("foamToVTK: no point data pointD in internal.vtu")
    lines.append("foamToVTK: contact on %s.vtp %s, pointD %s"
                 % (WALL, "as written" if wall is not None
                    and np.array_equal(wall, wall_contact) else "WRONG",
                    "present" if pointD is not None else "MISSING"))


def vtk_folder(case):
    folders = [d for d in glob.glob(os.path.join(case, "VTK", "*"))
               if os.path.isdir(d)]
    if len(folders) != 1:
        raise AssertionError("foamToVTK -latestTime wrote %s" % folders)
    return folders[0]


def check_parallel_vtk(root, base, straight, lines, failures):
    """The run on 2 ranks, converted by foamToVTK -parallel without
    reconstructPar, against the serial run's VTK files."""
    case = os.path.join(root, "decomposed")
    shutil.copytree(base, case)
    run.write_options(case, "system/decomposeOptions",
                      {"method": "metis", "numberOfSubdomains": 2})
    run.run(["decomposePar", "-force"], case)
    run.run_parallel(["touchFoam"], case, 2, timeout=testing.RUN_TIMEOUT)
    run.run_parallel(["foamToVTK", "-ascii", "-latestTime"], case, 2)
    serial, parallel = vtk_folder(straight), vtk_folder(case)
    diffs = []
    for name, part in (("sigmaEq", "internal.vtu"),
                       ("contact", os.path.join("boundary", WALL + ".vtp"))):
        a = vtk_array(os.path.join(parallel, part), name, "CellData")
        b = vtk_array(os.path.join(serial, part), name, "CellData")
        if a is None or len(a) != len(b):
            failures.append("foamToVTK -parallel: %s of %s has %s values, "
                            "serial %d" % (name, part, None if a is None
                                           else len(a), len(b)))
            continue
        d = testing.relative_max_difference(np.sort(a), np.sort(b))
        diffs.append("%s %.1e" % (name, d))
        if not d <= 1e-12:
            failures.append("foamToVTK -parallel: %s differs from serial by "
                            "%.2e" % (name, d))
    lines.append("decomposed on 2, foamToVTK -parallel against serial: %s"
                 % ", ".join(diffs))


def check_restart(root, base, straight, mid, end_name, steps, m, lines,
                  failures):
    ref = os.path.join(straight, end_name)

    def restarted(label, edit):
        case = os.path.join(root, label)
        shutil.copytree(base, case)
        shutil.copytree(os.path.join(straight, mid), os.path.join(case, mid))
        edit(os.path.join(case, mid))
        run.foam_set(case, "system/controlDict", "maxSteps", steps // 2)
        run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
        out = os.path.join(case, end_name)
        if not os.path.isdir(out):
            raise AssertionError("%s ended at %s, the straight run at %s"
                                 % (label, sorted(run.time_dirs(case)
                                                  .values())[-1], end_name))
        return case, out

    def rename(folder):
        for new, old in RENAMED.items():
            os.rename(os.path.join(folder, new), os.path.join(folder, old))

    case, out = restarted("formerNames", rename)
    size = {"pointD": len(m.points)}
    equal = [name for name in STATE
             if field(out, name, size.get(name, m.n_cells)).tobytes()
             == field(ref, name, size.get(name, m.n_cells)).tobytes()]
    log = open(os.path.join(case, "log.touchFoam")).read()
    said = [old for old in ("u", "pointU")
            if re.search(r"read from %s\b" % old, log)]
    left = [old for old in FORMER if os.path.exists(os.path.join(out, old))]
    lines.append("restart from u, pointU, v: %s equal to the straight run, "
                 "log names %s" % (" ".join(equal) or "none",
                                   " ".join(said) or "neither"))
    if len(equal) != len(STATE):
        failures.append("restart from the former names: %s differ"
                        % " ".join(sorted(set(STATE) - set(equal))))
    if len(said) != 2:
        failures.append("the restart's log does not say it read u and "
                        "pointU")
    if left:
        failures.append("the restart wrote the former names %s" % left)

    def drop(folder):
        for name in ("D", "pointD"):
            os.remove(os.path.join(folder, name))

    _, control = restarted("withoutDisplacement", drop)
    d = testing.relative_max_difference(field(control, "D", m.n_cells),
                                        field(ref, "D", m.n_cells))
    lines.append("control without D, pointD: D differs by %.2g" % d)
    if not d > 1e-3:
        failures.append("a restart without the displacements ends with the "
                        "straight run's D: the test cannot see them read")


def body(steps):
    root = testing.work_dir(NAME)
    control = cases.precise_output()
    control.update({"maxSteps": steps, "writeControl": "timeStep",
                    "writeInterval": steps // 2, "endTime": 1,
                    "startFrom": "latestTime"})
    base = cases.prepare("taylorImpact", os.path.join(root, "base"), n=3,
                         control=control)
    straight = os.path.join(root, "straight")
    shutil.copytree(base, straight)
    run.run(["touchFoam"], straight, timeout=testing.RUN_TIMEOUT)
    times = run.time_dirs(straight)
    written = [times[t] for t in sorted(times) if t > 0]
    if len(written) != 2:
        raise AssertionError("the run wrote %s, expected the times of steps "
                             "%d and %d" % (written, steps // 2, steps))
    mid, end_name = written
    end = os.path.join(straight, end_name)
    m = mesh.PolyMesh(base)

    lines, failures = [], []
    missing = [f for f in WRITTEN if not os.path.exists(os.path.join(end, f))]
    former = [f for f in FORMER if os.path.exists(os.path.join(end, f))]
    lines.append("%d cells, %d steps: written %s"
                 % (m.n_cells, steps, " ".join(sorted(os.listdir(end)))))
    if missing:
        failures.append("not written: %s" % " ".join(missing))
    if former:
        failures.append("written under the former names: %s"
                        % " ".join(former))
    if missing:
        return testing.verdict(lines, failures)

    check_values(end, straight, m, lines, failures)
    wall_contact = check_contact(end, m, lines, failures)
    check_vtk(straight, end_name, wall_contact, lines, failures)
    check_parallel_vtk(root, base, straight, lines, failures)
    check_restart(root, base, straight, mid, end_name, steps, m, lines,
                  failures)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=40)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args.steps)))
