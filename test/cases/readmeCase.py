#!/usr/bin/python3
"""The README's new-user case, run as written, moves as a free body must.

    /usr/bin/python3 test/cases/readmeCase.py

Extracts the shell block that follows the marker line '<!-- new-user
case' in README.md (not a copy: an edit of the README is what runs) and
runs it with bash -e in test/runs/readmeCase/: the lines up to the first
'decomposePar' (copy of etc/templates/block, blockMesh, setExprFields,
serial touchFoam), then, in the folder those lines ended in, the rest
(decomposePar, mpirun, reconstructPar, foamToVTK).  mpirun's root and
oversubscription permissions come from the environment (OMPI_ALLOW_RUN_AS_
ROOT, OMPI_MCA_rmaps_base_oversubscribe) so the command stays the README's.

The block is a free body (traction-free) set moving by setExprFields with
v0 = v_t + omega x X about its centre.  References, independent of the
solver:

  - the translation v_t and spin omega parsed from the case's
    system/setExprFieldsDict, rho from constant/mechanicalProperties, the
    cell centres and volumes from OpenFOAM's writeCellCentres and
    writeCellVolumes;
  - the initial 0/U (OpenFOAM's setExprFields) has the volume-weighted mean
    v_t (the spin's mean vanishes on a mesh symmetric about the centre)
                                                         to 1e-12 |v_t|;
  - centre of mass: at every written time t of the serial run
    sum V D / sum V = v_t t                              to 1e-12 |v_t| t;
  - linear momentum: sum V lm = rho v_t V                to 1e-12 (rho |v_t| V);
  - angular momentum about the centre of mass, from the fields (current
    cell positions X + D): at the last time it equals the closed form of
    the initial spin on N^3 equal cells of a cube of side a,
    L = rho omega a^5/6 (1 - 1/N^2)                      to 1e-12 |L|;
  - the parallel run (2 ranks, reconstructed) equals the serial run: D and
    lm at the last time                                  to 1e-12 of max;
  - foamToVTK wrote every time, and the last one carries pointD (the field
    the README says to warp by).

Work folders: test/runs/readmeCase/.
"""

import glob
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import foamfile, run, testing  # noqa: E402

NAME = "readmeCase"
TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
MARKER = "<!-- new-user case"


def readme_block(path):
    """The lines of the fenced block after the marker in path."""
    lines = open(path).read().split("\n")
    starts = [i for i, line in enumerate(lines) if line.startswith(MARKER)]
    if len(starts) != 1:
        raise AssertionError("README.md has %d lines starting with '%s'"
                             " (one expected)" % (len(starts), MARKER))
    i = starts[0] + 1
    if not lines[i].startswith("```"):
        raise AssertionError("README.md line %d: no fenced block after the"
                             " marker" % (i + 1))
    block = []
    for line in lines[i + 1:]:
        if line.startswith("```"):
            return block
        block.append(line)
    raise AssertionError("README.md: the new-user block is not closed")


def split_block(block):
    """(serial part, parallel part): split at the first decomposePar."""
    for i, line in enumerate(block):
        if line.split() and line.split()[0] == "decomposePar":
            return block[:i], block[i:]
    raise AssertionError("the README block has no decomposePar line")


def bash(lines, cwd, log, env):
    with open(log, "w") as f:
        rc = subprocess.call(["bash", "-e", "-c", "\n".join(lines)], cwd=cwd,
                             stdout=f, stderr=subprocess.STDOUT, env=env,
                             stdin=subprocess.DEVNULL,
                             timeout=testing.RUN_TIMEOUT)
    if rc != 0:
        raise AssertionError("the README block failed (exit %d) in %s:\n%s"
                             % (rc, cwd, run.log_tail(log)))


def vector_variable(text, name):
    m = re.search(r'"\s*%s\s*=\s*vector\(([^)]*)\)' % name, text)
    if not m:
        raise AssertionError("setExprFieldsDict has no variable %s" % name)
    return np.array([float(x) for x in m.group(1).split(",")])


def cells(case, field, n=None):
    values = foamfile.read_field(os.path.join(case, field))
    return np.asarray(values.internal(n), float)


def times(case):
    return sorted((d for d in os.listdir(case)
                   if re.match(r"^\d+(\.\d+)?(e-?\d+)?$", d) and d != "0"),
                  key=float)


def body():
    failures, lines = [], []
    serial, parallel = split_block(readme_block(os.path.join(TOP,
                                                             "README.md")))
    work = testing.work_dir(NAME)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    here = os.path.join(work, "cwd")
    bash(serial + ['pwd > "%s"' % here], work,
         os.path.join(work, "log.serialPart"), env)
    case = open(here).read().strip()
    lines.append("README block: %d + %d lines" % (len(serial),
                                                  len(parallel)))

    # The solver-independent references
    expr = open(os.path.join(case, "system", "setExprFieldsDict")).read()
    v_t = vector_variable(expr, "translation")
    omega = vector_variable(expr, "omega")
    law = foamfile.read_dict(os.path.join(case, "constant",
                                          "mechanicalProperties"))
    rho = float(law["rho"])
    for func in ("writeCellCentres", "writeCellVolumes"):
        run.run(["postProcess", "-func", func, "-time", "0"], case, func)
    X = cells(case, "0/C")
    n = len(X)
    V = cells(case, "0/V", n)
    vol = V.sum()
    N = round(n ** (1.0 / 3.0))
    a = vol ** (1.0 / 3.0)
    if N ** 3 != n or np.ptp(V) > 1e-12 * V.max():
        raise AssertionError("the README case is not N^3 equal cells"
                             " (%d cells, volumes %g..%g)"
                             % (n, V.min(), V.max()))

    U0 = cells(case, "0/U", n)
    mean0 = (V[:, None] * U0).sum(0) / vol
    e0 = np.linalg.norm(mean0 - v_t) / np.linalg.norm(v_t)
    if e0 > 1e-12:
        failures.append("0/U mean %s is not v_t %s" % (mean0, v_t))

    # Serial: centre of mass and momenta at every written time
    written = times(case)
    if not written:
        raise AssertionError("the serial run wrote no time")
    worst_c, worst_p = 0.0, 0.0
    for t in written:
        D = cells(case, os.path.join(t, "D"), n)
        lm = cells(case, os.path.join(t, "lm"), n)
        centre = (V[:, None] * D).sum(0) / vol
        expect = v_t * float(t)
        worst_c = max(worst_c, np.linalg.norm(centre - expect)
                      / np.linalg.norm(expect))
        P = (V[:, None] * lm).sum(0)
        worst_p = max(worst_p, np.linalg.norm(P - rho * v_t * vol)
                      / (rho * np.linalg.norm(v_t) * vol))
    if worst_c > 1e-12:
        failures.append("centre of mass off v_t t by %.2e of |v_t t|"
                        % worst_c)
    if worst_p > 1e-12:
        failures.append("momentum off rho v_t V by %.2e" % worst_p)
    lines.append("%d times to t = %s: centre of mass = v_t t to %.1e,"
                 " momentum = rho v_t V (%.4g kg m/s) to %.1e"
                 % (len(written), written[-1], worst_c,
                    rho * np.linalg.norm(v_t) * vol, worst_p))

    last = written[-1]
    D = cells(case, os.path.join(last, "D"), n)
    lm = cells(case, os.path.join(last, "lm"), n)
    x = X + D
    xc = (V[:, None] * x).sum(0) / vol
    L = (V[:, None] * np.cross(x - xc, lm)).sum(0)
    L_exact = rho * omega * a ** 5 / 6.0 * (1.0 - 1.0 / N ** 2)
    eL = np.linalg.norm(L - L_exact) / np.linalg.norm(L_exact)
    if eL > 1e-12:
        failures.append("angular momentum %s against the closed form %s"
                        " (%.2e)" % (L, L_exact, eL))
    lines.append("L at %s = rho omega a^5/6 (1 - 1/N^2) = %.6g to %.1e"
                 % (last, np.linalg.norm(L_exact), eL))
    serial_D, serial_lm = D, lm
    keep = os.path.join(work, "serial")
    shutil.copytree(os.path.join(case, last), keep)

    # Parallel, reconstructed, and the VTK files
    bash(parallel, case, os.path.join(work, "log.parallelPart"), env)
    if not os.path.isdir(os.path.join(case, "processor1")):
        failures.append("no processor1 folder: the block did not decompose")
    dD = np.abs(cells(case, os.path.join(last, "D"), n) - serial_D).max()
    dl = np.abs(cells(case, os.path.join(last, "lm"), n) - serial_lm).max()
    rD = dD / np.abs(serial_D).max()
    rl = dl / np.abs(serial_lm).max()
    if max(rD, rl) > 1e-12:
        failures.append("parallel differs from serial: D %.2e, lm %.2e"
                        % (rD, rl))
    lines.append("parallel = serial: D %.1e, lm %.1e" % (rD, rl))

    series = glob.glob(os.path.join(case, "VTK", "*.vtm.series"))
    vtus = sorted(glob.glob(os.path.join(case, "VTK", "*", "internal.vtu")))
    if not series or len(vtus) != len(written) + 1:
        failures.append("foamToVTK: %d series, %d internal.vtu for %d times"
                        % (len(series), len(vtus), len(written) + 1))
    elif b"pointD" not in open(max(vtus, key=lambda p: int(
            re.search(r"_(\d+)/internal", p).group(1))), "rb").read():
        failures.append("the last VTK file has no pointD")
    lines.append("VTK: %d times with pointD" % len(vtus))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
