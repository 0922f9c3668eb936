#!/usr/bin/python3
"""The checks of the strong-scaling study (checks.json, validation/Allrun).

    ./compare.py            (Allrun calls it after its runs)

Reads runs/column: the serial run's last fields, kept by Allrun in
serial.<time>/, and the 2-rank run's, reconstructed (reconstructPar
-latestTime) into <time>/, and results.json, and records:

  - the 2-rank run ends at the serial run's time (the same steps: the CFL
    step depends on the state), and every field written (lm U F P sigma
    sigmaEq pressure J D pointD, those present) equals the serial one to
    round-off: max|q_2 - q_1| / max(max|q_1|, floor_q) <= 1e-10, with the
    floors of test/cases/parallelEqualsSerial.py (the size of q in an O(1)
    deformation: 1 for F and J, lambda + 2 mu for the stresses, U_p for U,
    rho0 U_p for lm, the body size for D and pointD); a decomposition
    error is O(1) on that scale, round-off 1e-15 to 1e-12;
  - on a column of at least LARGE_CELLS cells (the published n = 32), the
    peak memory of the serial run per cell <= MAX_BYTES_PER_CELL (measured
    2385 B on 196,608 cells and 2140 B on 1,053,696, 2026-12-03; on a
    smaller column the ~57 MB of the OpenFOAM libraries dominate and the
    memory is reported, not checked).

The parallel efficiency is reported, not checked: on a shared 2-core
machine the second rank waits for a core whenever another job runs, and
Open MPI's polling counts that wait as CPU time of the first.

Exit status 1 when a check fails.
"""

import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import analytic, cases, checks, foamfile, run  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

CASE = os.path.join(HERE, "runs", "column")
TOL = 1e-10
FIELDS = ["lm", "U", "F", "P", "sigma", "sigmaEq", "pressure", "J", "D",
          "pointD"]
LARGE_CELLS = 100000
MAX_BYTES_PER_CELL = 3000


def floors(m):
    mat = cases.material(CASE)
    lam, mu = analytic.lame(mat["E"], mat["nu"])
    Up = analytic.p_wave_speed(mat["E"], mat["nu"], mat["rho"])
    size = float(np.abs(m.points).max())
    return {"F": 1.0, "J": 1.0, "P": lam + 2 * mu, "sigma": lam + 2 * mu,
            "sigmaEq": lam + 2 * mu, "pressure": lam + 2 * mu, "U": Up,
            "lm": mat["rho"] * Up, "D": size, "pointD": size}


def main():
    checks.start(HERE)
    serial = [d for d in os.listdir(CASE) if d.startswith("serial.")]
    if len(serial) != 1:
        checks.record(HERE, "serial run's last fields", "missing",
                      "runs/column/serial.<time>/", False)
        return checks.status(HERE)
    name = serial[0][len("serial."):]
    times = run.time_dirs(CASE)
    reached = sorted(times.values(), key=float)[-1] if times else "none"
    same = name in times.values()
    checks.record(HERE, "2 ranks end at the serial run's time", reached,
                  name, same, "same steps: the CFL step follows the state")
    if same:
        m = PolyMesh(CASE)
        floor = floors(m)
        worst, worst_field, compared = 0.0, "", []
        for field in FIELDS:
            a_path = os.path.join(CASE, serial[0], field)
            if not os.path.exists(a_path):
                continue
            n = m.points.shape[0] if field == "pointD" else m.n_cells
            a = foamfile.read_field(a_path).internal(n)
            b = foamfile.read_field(os.path.join(CASE, name, field)
                                    ).internal(n)
            d = float(np.abs(np.asarray(b, float) - np.asarray(a, float))
                      .max() / max(np.abs(np.asarray(a, float)).max(),
                                   floor[field]))
            compared.append(field)
            if d >= worst:
                worst, worst_field = d, field
        checks.record(HERE, "2 ranks (METIS) = serial, %d cells, fields %s"
                      % (m.n_cells, " ".join(compared)), worst,
                      "<= %g" % TOL, bool(compared) and worst <= TOL,
                      "largest scaled difference (%s), at t = %s"
                      % (worst_field, name))
    with open(os.path.join(HERE, "results.json")) as f:
        res = json.load(f)
    cells = res.get("cells")
    per_cell = res["serial"]["bytesPerCell"]
    if cells and cells >= LARGE_CELLS:
        checks.record(HERE, "serial peak memory per cell, %d cells" % cells,
                      per_cell, "<= %d B" % MAX_BYTES_PER_CELL,
                      per_cell <= MAX_BYTES_PER_CELL,
                      "measured 2385 B on 196,608 cells (2026-12-03)")
    write_markdown(res)
    return checks.status(HERE)


def write_markdown(res):
    """results.md: the measured figures and the checks."""
    s, t = res["serial"], res["twoRanks"]
    lines = ["# Strong scaling: twisting column", "",
             "%s, %d steps, timed between the first and the last; "
             "cell-steps/s from touchFoam's ExecutionTime (CPU time), peak "
             "memory from GNU time (summed over ranks)." % (res["case"],
                                                           res["steps"]),
             "", "| run | cell-steps/s | peak memory [kB] | bytes/cell |",
             "|---|---:|---:|---:|",
             "| 1 rank | %d | %d | %d |" % (s["cellStepsPerSecond"],
                                          s["peakMemoryKB"],
                                          s["bytesPerCell"]),
             "| 2 ranks (METIS) | %d | %d | %d |" % (
                 t["cellStepsPerSecond"], t["peakMemoryKB"],
                 t["peakMemoryKB"] * 1024 // max(res.get("cells") or 1, 1)),
             "", "Parallel efficiency T1/(2 T2): %s (reported, not checked: "
             "a shared machine)." % res["parallelEfficiency"], "",
             "| check | measured | reference | pass/fail |",
             "|---|---|---|---|"]
    for c in checks.load(HERE) or []:
        lines.append("| %s | %s | %s | %s |" % (
            c["quantity"], c["measured"], c["reference"],
            "pass" if c["pass"] else "**FAIL**"))
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())
