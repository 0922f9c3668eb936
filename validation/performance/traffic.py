"""Memory traffic of a touchFoam step, counted from the loops of src/TOUCH.

The estimate of bytes moved between memory and the cores per cell-step of
the baseline (compatible F update, limitedLinear, RK2, angular momentum
preservation off, solidMonitor every step) on a hexahedral mesh, read
from src/TOUCH after the compatible update took the stress gradients cell
by cell (a change of the loops needs a change of STAGE or STEP below):

  - every loop ('pass') streams each array it touches once: a face loop
    reaches a cell's values from its six faces, but the column is six
    n^3 blocks stacked along y, each numbered x fastest, then y, then z,
    so the neighbours are 1, n and n^2 cells away (but at the five block
    interfaces), and n^2 cells of the cell arrays of a pass (at n = 56,
    3,136 x about 0.55 kB = 1.7 MB) stay in the L2 and the 32 MB L3 while
    the loop passes them;
  - nothing survives from one pass to the next (the arrays of a 1M-cell
    mesh, 2 kB a cell, are 60 times the L3): an array read in three
    passes is read three times.  At 10k cells the whole state (about
    20 MB) fits in L3 and the model overstates the traffic; it is meant
    for the largest size;
  - a store costs a read and a write (write-allocate: the compiler emits
    cached stores), so an array written is counted twice whether or not
    the pass reads it first ('w' and 'rw' cost the same), as the triad's
    4-array figure counts it;
  - the point constraints are stored and applied at the boundary points
    only (kinematicPointConstraints), so they are boundary loops;
  - sizes: label 4 B, scalar 8, vector 24, tensor 72; a face's point
    list (faceList: 16 B List header, 4 labels in a 32 B heap chunk) 48 B;
    a cell's face, point and a point's cell list in compactAddressing's
    flat rows, 6 or 8 labels and an offset: 28 and 36 B;
  - interior faces and points per cell are the mesh's (3 - 13/(6n) and
    (n+1)^2 (6n+1)/(6n^3) for the n x 6n x n column); boundary faces
    (26 n^2 of them, 4.3/n per cell) and their patch loops are left out:
    they add O(1/n), 8 % of the faces at n = 56, a third at n = 12.

Modes: 'r' read (bytes once), 'w' written, 'rw' read and written (bytes
twice).  Entities: 'cell', 'face' (interior face), 'point'.
"""

SIZES = {"label": 4, "scalar": 8, "vector": 24, "tensor": 72,
         "face": 48, "csr6": 28, "csr8": 36}

#: (routine, [(array, entity, type, mode), ...]): one pass each, per stage
STAGE = [
    ("mechanicalLaw::correct: P(F)",
     [("F", "cell", "tensor", "r"), ("P", "cell", "tensor", "w")]),
    ("linearReconstruction::update: max |p|, max |P| (tolerances)",
     [("lm", "cell", "vector", "r"), ("P", "cell", "tensor", "r")]),
    ("linearReconstruction::update: cell loop, gathering over its faces "
     "(gradients, bounds, increments, limiter), and in it "
     "compatible::addCellForces: the cell's nodal forces, reconstructed "
     "traction forces (point upwinding) and boundary tractions at its faces; "
     "the stress gradients are used there, never stored",
     [("cellFaces (compactAddressing)", "cell", "csr6", "r"),
      ("owner, neighbour", "face", 8, "r"), ("Cf", "face", "vector", "r"),
      ("Minv", "cell", 48, "r"), ("X", "cell", "vector", "r"),
      ("lm", "cell", "vector", "r"), ("P", "cell", "tensor", "r"),
      ("momentumLimiter", "cell", "vector", "w"),
      ("gradp", "cell", "tensor", "w"),
      ("Sf (the cell forces)", "face", "vector", "r"),
      ("faces (point lists)", "face", "face", "r"),
      ("pointForce, reconstructedForce", "point", 48, "rw")]),
    ("touchSolid::computeRates: zero lmRate, FRate",
     [("lmRate", "cell", "vector", "w"), ("FRate", "cell", "tensor", "w")]),
    ("compatible::reconstruct: pointForce = 0, reconstructedForce = 0",
     [("pointForce, reconstructedForce", "point", 48, "w")]),
    ("compatible::addFaceRates: forAllCoupled (upwind Riemann flux)",
     [("owner, neighbour", "face", 8, "r"), ("Sf, Cf", "face", 48, "r"),
      ("magSf", "face", "scalar", "r"),
      ("lm, F, X", "cell", 24 + 72 + 24, "r"),
      ("gradp", "cell", "tensor", "r"),
      ("lmRate", "cell", "vector", "rw")]),
    ("linearPointInterpolation::interpolate: point loop",
     [("pointCells (compactAddressing)", "point", "csr8", "r"),
      ("points", "point", "vector", "r"),
      ("lm, X", "cell", 48, "r"),
      ("gradp (the reconstruction's)", "cell", "tensor", "r"),
      ("pointV", "point", "vector", "w")]),
    ("linearPointInterpolation::interpolate: scale",
     [("nPointCells", "point", "scalar", "r"),
      ("pointV", "point", "vector", "rw")]),
    ("compatible::addPointUpwinding: constrainTranspose(reconstructedForce)"
     " (boundary points only: left out)", []),
    ("compatible::addPointUpwinding: point loop",
     [("pointForce, reconstructedForce", "point", 48, "r"),
      ("boundaryIndex (constraints)", "point", "label", "r"),
      ("pointMobility", "point", "scalar", "r"),
      ("pointV", "point", "vector", "rw")]),
    ("deformationUpdate::addFaceMeanFRate",
     [("owner, neighbour", "face", 8, "r"), ("Sf", "face", "vector", "r"),
      ("faces (point lists)", "face", "face", "r"),
      ("pointV", "point", "vector", "r"), ("FRate", "cell", "tensor", "rw")]),
    ("compatible::addTransposeRate: constrainTranspose, negate pointForce",
     [("pointForce (negate)", "point", "vector", "rw")]),
    ("linearPointInterpolation::addTranspose: shares f_a/n_a",
     [("pointForce", "point", "vector", "r"),
      ("nPointCells", "point", "scalar", "r"),
      ("shares", "point", "vector", "w")]),
    ("linearPointInterpolation::addTranspose: cell loop (dual, then "
     "moved to the face neighbours)",
     [("cellPoints (compactAddressing)", "cell", "csr8", "r"),
      ("shares, points", "point", 48, "r"),
      ("cellFaces (compactAddressing)", "cell", "csr6", "r"),
      ("owner, neighbour", "face", 8, "r"),
      ("X, momentumLimiter, Minv", "cell", 96, "r"),
      ("lmRate", "cell", "vector", "rw")]),
    ("touchSolid::computeRates: lmRate /= V, FRate /= V",
     [("V (twice)", "cell", 16, "r"), ("lmRate", "cell", "vector", "rw"),
      ("FRate", "cell", "tensor", "rw")]),
    ("touchSolid::advanceStage: D",
     [("D0, lm", "cell", 48, "r"), ("D", "cell", "vector", "rw")]),
    ("touchSolid::advanceStage: lm, F",
     [("lm0, lmRate, F0, FRate", "cell", 24 + 24 + 72 + 72, "r"),
      ("lm, F", "cell", 96, "rw")]),
    ("touchSolid::advanceStage: pointD",
     [("pointD0, pointV", "point", 48, "r"),
      ("pointD", "point", "vector", "rw")]),
    ("touchSolid::valid",
     [("F, lm", "cell", 96, "r")]),
]

#: Passes once per step (whatever the number of stages)
STEP = [
    ("stableTimeStep::deltaT",
     [("F", "cell", "tensor", "r"), ("hCell", "cell", "scalar", "r")]),
    ("touchSolid::storeOldTime",
     [("lm, F, D", "cell", 120, "r"), ("lm0, F0, D0", "cell", 120, "w"),
      ("pointD", "point", "vector", "r"),
      ("pointD0", "point", "vector", "w")]),
]

#: The solidMonitor's totals, every step in the baseline
MONITOR = [
    ("totalLinearMomentum (twice: p and L's origin term)",
     [("V, lm", "cell", 2 * 32, "r"), ("V*lm tmp", "cell", 2 * 24, "w"),
      ("V*lm tmp", "cell", 2 * 24, "r")]),
    ("totalAngularMomentum: x = C + u, sum V x ^ lm",
     [("C, u", "cell", 48, "r"), ("x tmp", "cell", "vector", "w"),
      ("x tmp, lm, V", "cell", 56, "r")]),
    ("kineticEnergy",
     [("lm, V", "cell", 32, "r"), ("magSqr, V* tmps", "cell", 16, "w"),
      ("tmps", "cell", 16, "r")]),
    ("strainEnergy: sum V W(F)",
     [("V, F", "cell", 80, "r")]),
]


def _bytes(item):
    size = item[2] if isinstance(item[2], int) else SIZES[item[2]]
    return size * (1 if item[3] == "r" else 2)


def _per_cell(passes, per_cell):
    """[(routine, bytes per cell)] of a list of passes."""
    return [(name, sum(_bytes(a) * per_cell[a[1]] for a in arrays))
            for name, arrays in passes]


def estimate(n_cells, n_internal_faces, n_points, stages=2, monitor=True):
    """Bytes per cell-step and the breakdown, for a mesh's counts."""
    per_cell = {"cell": 1.0, "face": n_internal_faces / n_cells,
                "point": n_points / n_cells}
    stage = _per_cell(STAGE, per_cell)
    step = _per_cell(STEP, per_cell)
    mon = _per_cell(MONITOR, per_cell) if monitor else []
    stage_total = sum(b for _, b in stage)
    total = stages * stage_total + sum(b for _, b in step + mon)
    return {
        "bytesPerCellStep": total,
        "bytesPerCellStage": stage_total,
        "stages": stages,
        "facesPerCell": per_cell["face"],
        "pointsPerCell": per_cell["point"],
        "perStage": stage,
        "perStep": step + mon,
    }


def by_entity(passes=STAGE):
    """Bytes per entity and stage, split into cell, face and point arrays."""
    out = {"cell": 0, "face": 0, "point": 0}
    for _, arrays in passes:
        for a in arrays:
            out[a[1]] += _bytes(a)
    return out
