#!/usr/bin/python3
"""decomposePar with METIS (and scotch) splits the tutorials evenly.

    /usr/bin/python3 test/cases/decomposeMetis.py

For swingingCube (8^3 hexes), twistingColumn (4 x 24 x 4) and
unstructuredCube (6 x 4^3 tets): mesh and initialise a copy, decompose it
with metis on 2 and 4 subdomains and scotch on 2, and check that
  - decomposePar succeeds (Debian's own metis/scotch libraries are stubs;
    etc/bashrc puts the real ones first),
  - the processor meshes hold every cell once (counts sum to the total),
  - each part is within 20 % of the mean,
  - the initial fields lm and F were decomposed with the right sizes.
Does not need touchFoam.  Work folders: test/runs/decomposeMetis/.
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, foamfile, mesh, run, testing  # noqa: E402

NAME = "decomposeMetis"
TUTORIALS = [("swingingCube", 8), ("twistingColumn", 4),
             ("unstructuredCube", 4)]
DECOMPOSITIONS = [("metis", 2), ("metis", 4), ("scotch", 2)]
BALANCE = 0.2


def check(case, method, nprocs, total):
    run.write_options(case, "system/decomposeOptions",
                      {"numberOfSubdomains": nprocs, "method": method})
    run.run(["decomposePar", "-force"], case,
            "decomposePar.%s%d" % (method, nprocs))
    if mesh.processor_count(case) != nprocs:
        raise AssertionError("%d processor folders for %d subdomains"
                             % (mesh.processor_count(case), nprocs))
    counts = []
    patches_cut = {}
    for proc in range(nprocs):
        m = mesh.PolyMesh(case, processor=proc)
        counts.append(m.n_cells)
        for p in m.patches:
            if p["type"] != "processor" and p["nFaces"] > 0:
                patches_cut[p["name"]] = patches_cut.get(p["name"], 0) + 1
        for field in ("U", "F"):
            fld = foamfile.read_field(os.path.join(
                case, "processor%d" % proc, "0", field))
            if not fld.uniform and len(fld.values) != m.n_cells:
                raise AssertionError("processor%d/0/%s has %d values for %d "
                                     "cells" % (proc, field, len(fld.values),
                                                m.n_cells))
    if sum(counts) != total:
        raise AssertionError("%s %d: %d cells in the parts, %d in the mesh"
                             % (method, nprocs, sum(counts), total))
    mean = total / nprocs
    worst = max(abs(c - mean) / mean for c in counts)
    if worst > BALANCE:
        raise AssertionError("%s %d: parts %s, %.0f %% off the mean"
                             % (method, nprocs, counts, 100 * worst))
    shared = sum(1 for n in patches_cut.values() if n > 1)
    return "%s%d %s (%d patches split)" % (
        method, nprocs, "+".join(map(str, counts)), shared)


def body():
    root = testing.work_dir(NAME)
    report = []
    for tutorial, n in TUTORIALS:
        case = cases.prepare(tutorial, os.path.join(root, tutorial), n=n)
        total = mesh.PolyMesh(case).n_cells
        parts = [check(case, method, nprocs, total)
                 for method, nprocs in DECOMPOSITIONS]
        report.append("%s %d cells: %s" % (tutorial, total, ", ".join(parts)))
    return "; ".join(report)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body, needs_solver=False))
