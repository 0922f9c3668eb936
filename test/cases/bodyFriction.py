#!/usr/bin/python3
"""Coulomb friction between deformable bodies: a free oblique collision of
two blocks, frictionless and with friction (issue 28, acceptance 3 and 5).

    /usr/bin/python3 test/cases/bodyFriction.py

The case (built here from tutorials/barCollision's files): two square
blocks L = 0.1 m, N x N cells each (plane strain: one cell across, empty
front and back), neo-Hookean, rho0 = 1400, E = 1.04e9, nu = 0.3
(c_p = 1000 m/s, c_s = 535 m/s); block A on [-L, 0] x [0, L] at (v, w),
block B on [0, L] x [L/2, 3L/2] at (-v, -w), v = w = 1 m/s: they touch at
x = 0 along half of their faces, off their centres, and slide along each
other at 2 w.  No wall, no clamp, no gravity; FUpdate plain,
angularMomentumPreservation on, RK2, limitedLinear, to 6e-4 s (contact
from 0 to about 2L/c_p = 2e-4 s).  Runs:

  frictionless  no friction entry;
  mu = 0        coulomb with muStatic = muKinetic = 0;
  friction      coulomb with muStatic = muKinetic = 0.3 (the faces slide
                throughout: the sticking traction needs Z_s/Z_p = 0.53 of
                the normal one);
  offset        friction, B's mesh (N + 2) x (N + 2): the faces that meet
                do not match;
  nodes         FUpdate compatible, faceB with side nodes (its points
                held on faceA's surface), B's mesh (N + 2) x (N + 2):
                frictionless, mu = 0 and friction (the friction acts at
                the held points: compatible::addNodeFriction);
  auto          friction, side auto on both faces (compatible);
  compatible    friction with FUpdate compatible and neither face with
                side nodes: refused.

Asserted:
  - every run: total linear momentum constant to 1e-12 |p0| (|p0| the
    sum of the bodies' |p|), total angular momentum about the origin (the
    monitor's, current cell centres) constant to 1e-10 |L_A(0)|
    (L_A(0) = block A's about the origin; the bodies' L add up to
    -0.05 m |p_A|/sqrt 2), the total energy (kinetic + strain) never grows
    (1e-12 E0 per step) and the numerical dissipation stays >= 0 and
    holds the exchange's loss: boundaryWork stays 0 (only the contact
    acts, and its two sides' works are an exchange, not the boundaries'
    work; until 2026-12-07 the monitor booked the exchange's loss there,
    -4.4e-3 E0 frictionless) and numericalDissipation
    equals the bodies' numericalDissipation(<body>) plus the loss,
    -(boundaryWork(faceA) + boundaryWork(faceB)) - frictionDissipation,
    to 1e-12 E0;
  - mu = 0: lm, F, D and pointD at every written time equal the
    frictionless run's byte for byte (the internal fields: the friction
    run's U carries its friction and slip entries);
  - friction, at every step (contact.dat, all stages of the step): the
    faces' contact tractions within the cone, |t_t| <= mu |t_n| (1e-12),
    and every pair's friction power <= 0; the monitor's friction
    dissipation >= 0 and never decreasing, and within 1 % of the contact
    patches' flux work with the opposite sign (a second, independent
    account: the boundaries' work of the fluxes) beyond what the exchange
    itself takes on faces sliding across each other (>= 0, the
    frictionless run's contact work);
  - friction against the closed form of sliding Coulomb friction: each
    body's tangential impulse mu times its normal impulse, to within the
    frictionless run's own tangential/normal impulse ratio (the tilt of
    the contact normals at the deforming corners; 0.041 measured, asserted
    < 0.2 mu); each body's spin change about its centroid equals the
    angular impulse of its tangential impulse at the contact face (lever
    L/2) plus that of its normal impulse at the middle of the overlap
    (lever L/4) within 2 % (friction and frictionless runs); friction spins
    block A against its sliding (its spin below the frictionless run's);
    the relative tangential velocity at the end is below the frictionless
    run's by at least half of 2 mu J_n/M;
  - nodes sticking (mu 0.8, side nodes): the invariants, every point's
    |F_t|/N at most mu, the impulse ratio between 0.9 c_s/c_p (the
    acoustic sticking traction's ratio) and mu, and a restart at 2e-4 s
    (in contact) bit for bit;
  - nodes: the invariants above (angular momentum to 1e-10 included),
    mu = 0 byte-equal to frictionless, the held points' friction force
    within the cone of their normal reactions and its power <= 0 at
    every step (contact.dat's pair columns), the tangential/normal impulse
    mu within the nodes frictionless run's ratio;
  - auto: faceB, finer, reported as given side nodes and faceA as both,
    and every written field byte-equal to the nodes friction run;
  - FUpdate compatible with friction and no side nodes is refused naming
    FUpdate, side nodes and plain.
Work folders: test/runs/bodyFriction/.
"""

import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, contact, monitor, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

NAME = "bodyFriction"
N = 10
L = 0.1
V = 1.0
W = 1.0
MU = 0.3
#: a coefficient at which the faces stick (above c_s/c_p)
MU_STICK = 0.8
RHO = 1400.0
#: the blocks' wave speeds (E 1.04e9, nu 0.3)
C_P = 1000.0
C_S = 535.0
END = 6e-4

HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    object      %s;
}
"""

BLOCKMESH = """
scale 1;
vertices
(
    (-%(L)g 0 0) (0 0 0) (0 %(L)g 0) (-%(L)g %(L)g 0)
    (-%(L)g 0 %(h)g) (0 0 %(h)g) (0 %(L)g %(h)g) (-%(L)g %(L)g %(h)g)
    (0 %(y0)g 0) (%(L)g %(y0)g 0) (%(L)g %(y1)g 0) (0 %(y1)g 0)
    (0 %(y0)g %(h)g) (%(L)g %(y0)g %(h)g) (%(L)g %(y1)g %(h)g)
    (0 %(y1)g %(h)g)
);
blocks
(
    hex (0 1 2 3 4 5 6 7) blockA (%(N)d %(N)d 1) simpleGrading (1 1 1)
    hex (8 9 10 11 12 13 14 15) blockB (%(NB)d %(NB)d 1)
        simpleGrading (1 1 1)
);
boundary
(
    faceA { type patch; faces ((1 2 6 5)); }
    faceB { type patch; faces ((8 12 15 11)); }
    free
    {
        type patch;
        faces
        (
            (0 4 7 3) (0 1 5 4) (3 7 6 2)
            (9 10 14 13) (8 9 13 12) (11 15 14 10)
        );
    }
    frontAndBack
    {
        type empty;
        faces ((0 3 2 1) (4 5 6 7) (8 11 10 9) (12 13 14 15));
    }
);
"""

MATERIAL = """
model           neoHookean;
rho             %g;
E               1.04e9;
nu              0.3;
""" % RHO

FIELD_U = """
dimensions      [0 1 -1 0 0 0 0];
internalField   uniform (0 0 0);
boundaryField
{
    faceA { type bodyContact; %(friction)s value uniform (0 0 0); }
    faceB { type bodyContact; %(friction)s value uniform (0 0 0); }
    free { type traction; value uniform (0 0 0); }
    frontAndBack { type empty; }
}
"""

EXPRESSIONS = """
expressions
(
    blockA
    {
        field U; keepPatches true;
        expression #{ vector(%(v)g, %(w)g, 0) #};
    }
    blockB
    {
        field U; keepPatches true;
        condition #{ pos().x() > 0 #};
        expression #{ vector(%(mv)g, %(mw)g, 0) #};
    }
);
"""


def write(case, rel, cls, obj, body):
    path = os.path.join(case, rel)
    with open(path, "w") as f:
        f.write(HEADER % (cls, obj) + body)


def make_case(dst, friction=None, nb=N, update="plain", nodes=False,
              auto=False):
    """The oblique collision at dst; friction: (muStatic, muKinetic) or
    None; nb: block B's cells a side; nodes: faceB with side nodes; auto:
    both faces with side auto."""
    run.copy_case(run.tutorial_dir("barCollision"), dst)
    for name in ("0.orig", "0"):
        shutil.rmtree(os.path.join(dst, name), ignore_errors=True)
    os.makedirs(os.path.join(dst, "0"))
    h = L / N
    write(dst, "system/blockMeshDict", "dictionary", "blockMeshDict",
          BLOCKMESH % {"L": L, "h": h, "y0": L / 2, "y1": 1.5 * L,
                       "N": N, "NB": nb})
    write(dst, "constant/mechanicalProperties", "dictionary",
          "mechanicalProperties", MATERIAL)
    text = "" if friction is None else (
        "friction { type coulomb; muStatic %g; muKinetic %g; }" % friction)
    field = FIELD_U % {"friction": text}
    if nodes:
        field = field.replace("faceB { type bodyContact;",
                              "faceB { type bodyContact; side nodes;")
    if auto:
        field = field.replace("type bodyContact;",
                              "type bodyContact; side auto;")
    write(dst, "0/U", "volVectorField", "U", field)
    write(dst, "system/setExprFieldsDict", "dictionary", "setExprFieldsDict",
          EXPRESSIONS % {"v": V, "w": W, "mv": -V, "mw": -W})
    run.foam_set(dst, "system/fvSolution", "TOUCH/FUpdate", update)
    run.foam_set(dst, "system/fvSolution",
                 "TOUCH/angularMomentumPreservation", "on")
    run.foam_set(dst, "system/controlDict", "endTime", END)
    run.foam_set(dst, "system/controlDict", "writeInterval", 2e-4)
    run.foam_set(dst, "system/controlDict",
                 "functions/solidMonitor/writePrecision", 17)
    run.run(["blockMesh"], dst)
    run.run(["setExprFields"], dst)
    return dst


def internal_text(path):
    """The internalField entry of a field file, as written."""
    with open(path) as f:
        text = f.read()
    start = text.index("internalField")
    return text[start:text.index("boundaryField", start)]


def bodies(case, time_name, n_a):
    """Per block: momentum, centroid and angular momentum about it, from
    the written lm and D (x = C + D) and the cell volumes."""
    mesh = PolyMesh(case)
    X = mesh.cell_centres
    vol = mesh.cell_volumes
    n = len(X)
    folder = os.path.join(case, time_name)
    if os.path.exists(os.path.join(folder, "lm")):
        lm = read_field(os.path.join(folder, "lm")).internal(n)
        D = read_field(os.path.join(folder, "D")).internal(n)
    else:
        # The start: 0/U and no displacement
        lm = RHO * read_field(os.path.join(folder, "U")).internal(n)
        D = np.zeros_like(lm)
    x = X + D
    out = []
    for cells in (slice(0, n_a), slice(n_a, n)):
        Vc = vol[cells][:, None]
        p = np.sum(Vc * lm[cells], axis=0)
        xc = np.sum(Vc * x[cells], axis=0) / np.sum(Vc)
        spin = np.sum(np.cross(x[cells] - xc, Vc * lm[cells]), axis=0)
        out.append({"p": p, "xc": xc, "spin": spin[2], "M": RHO * Vc.sum()})
    return out


def invariants(case, label, failures, lines):
    m = monitor.read_monitor(case)
    p, Lm = m["p"], m["L"]
    pA = RHO * L * L * (L / N) * np.hypot(V, W)
    p0 = 2 * pA
    LA = pA * np.hypot(0.5 * L, 0.5 * L)
    dp = np.max(np.abs(p - p[0])) / p0
    dL = np.max(np.abs(Lm - Lm[0])) / LA
    e = m["totalEnergy"]
    growth = np.max(np.diff(e)) / e[0]
    num = m["numericalDissipation"]
    lines.append("%s: %d steps, |dp| %.1e |p0|, |dL| %.1e |L_A|, energy "
                 "step %+.1e E0, end %.4f E0" % (label, len(e), dp, dL,
                                                growth, e[-1] / e[0]))
    if dp > 1e-12:
        failures.append("%s: momentum drift %.2e |p0|" % (label, dp))
    if dL > 1e-10:
        failures.append("%s: angular momentum drift %.2e |L_A|"
                        % (label, dL))
    if growth > 1e-12:
        failures.append("%s: energy grew by %.2e E0 in a step"
                        % (label, growth))
    if np.min(num) < -1e-12 * e[0]:
        failures.append("%s: numerical dissipation %.2e E0 < 0"
                        % (label, np.min(num) / e[0]))
    work = np.max(np.abs(m["boundaryWork"])) / e[0]
    if work > 1e-12:
        failures.append("%s: boundaryWork %.2e E0, not 0: the contact's "
                        "exchange booked as work" % (label, work))
    loss = -(m["boundaryWork(faceA)"] + m["boundaryWork(faceB)"]) \
        - (m["frictionDissipation"] if "frictionDissipation" in m else 0)
    bodies = sum(m[c] for c in m if c.startswith("numericalDissipation("))
    booked = np.max(np.abs(num - bodies - loss)) / e[0]
    lines.append("%s: exchange loss %.2e E0 in numericalDissipation "
                 "(to %.0e)" % (label, loss[-1] / e[0], booked))
    if booked > 1e-12:
        failures.append("%s: numericalDissipation is not the bodies' plus "
                        "the exchange's loss (%.2e E0 off)" % (label, booked))
    return m


def sticking_restart(root, failures):
    """The sticking side nodes (they keep no state) stopped at 2e-4 s in
    contact and restarted to END: lm and F equal the uninterrupted run's
    bit for bit (17 digits written); the line."""
    runs = {}
    for name, end in (("stickWhole", END), ("stickRestarted", 2e-4)):
        case = make_case(os.path.join(root, name),
                         friction=(MU_STICK, MU_STICK), nb=N + 2,
                         update="compatible", nodes=True)
        for key, value in cases.precise_output().items():
            run.foam_set(case, "system/controlDict", key, value)
        run.foam_set(case, "system/controlDict", "endTime", end)
        run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
        runs[name] = case
    cut = runs["stickRestarted"]
    run.foam_set(cut, "system/controlDict", "endTime", END)
    run.run(["touchFoam"], cut, "touchFoam.restart",
            timeout=testing.RUN_TIMEOUT)
    n = PolyMesh(cut).n_cells
    worst = max(float(np.max(np.abs(
        testing.read_internal(run.time_dir(cut, END), f, n)
        - testing.read_internal(run.time_dir(runs["stickWhole"], END), f,
                                n)))) for f in ("lm", "F"))
    if worst != 0:
        failures.append("nodes sticking: the restart at 2e-4 s differs by "
                        "%.1e at %g s" % (worst, END))
    return ("nodes sticking restarted at 2e-4 s: lm, F at %g s %.1e off"
            % (END, worst))


def auto_side(root, explicit, failures):
    """side auto on both faces: block B, of the same material and finer
    ((N + 2)^2 cells against N^2), gets side nodes and faceA keeps both;
    the run byte-equal to the one with faceB's side nodes given
    (explicit)."""
    case = make_case(os.path.join(root, "autoSide"), friction=(MU, MU),
                     nb=N + 2, update="compatible", auto=True)
    log = run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    with open(log) as f:
        text = f.read()
    for face, side in (("faceA", "both"), ("faceB", "nodes")):
        if "bodyContact %s: side auto -> %s" % (face, side) not in text:
            failures.append("side auto: %s not reported as %s" % (face, side))
    differ, n = [], 0
    for t, name in sorted(run.time_dirs(explicit).items()):
        if t == 0:
            continue
        for field in ("lm", "F", "D", "pointD"):
            n += 1
            if internal_text(os.path.join(explicit, name, field)) \
                    != internal_text(os.path.join(case, name, field)):
                differ.append("%s at %s" % (field, name))
    if differ or n == 0:
        failures.append("side auto: differs from faceB's side nodes: %s"
                        % ", ".join(differ[:5]))
    return ("side auto on both faces: faceB (finer) nodes, faceA both; %d"
            " written fields byte-equal to faceB's side nodes given" % n)


def body():
    root = testing.work_dir(NAME)
    failures, lines = [], []

    none = make_case(os.path.join(root, "frictionless"))
    zero = make_case(os.path.join(root, "mu0"), friction=(0, 0))
    fric = make_case(os.path.join(root, "friction"), friction=(MU, MU))
    offs = make_case(os.path.join(root, "offset"), friction=(MU, MU),
                     nb=N + 2)
    for case in (none, zero, fric, offs):
        run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)

    mNone = invariants(none, "frictionless", failures, lines)
    invariants(zero, "mu 0", failures, lines)
    mFric = invariants(fric, "friction", failures, lines)
    invariants(offs, "friction, faces not matching", failures, lines)

    # Side nodes (compatible): faceB's points held on faceA's surface
    nNone = make_case(os.path.join(root, "nodesFrictionless"), nb=N + 2,
                      update="compatible", nodes=True)
    nZero = make_case(os.path.join(root, "nodesMu0"), friction=(0, 0),
                      nb=N + 2, update="compatible", nodes=True)
    nFric = make_case(os.path.join(root, "nodesFriction"),
                      friction=(MU, MU), nb=N + 2, update="compatible",
                      nodes=True)
    nStick = make_case(os.path.join(root, "nodesSticking"),
                       friction=(MU_STICK, MU_STICK), nb=N + 2,
                       update="compatible", nodes=True)
    for case in (nNone, nZero, nFric, nStick):
        run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    for case, label in ((nNone, "nodes frictionless"), (nZero, "nodes mu 0"),
                        (nFric, "nodes friction"),
                        (nStick, "nodes sticking")):
        invariants(case, label, failures, lines)

    # mu = 0: byte-equal to frictionless
    for a_case, b_case, label in ((none, zero, "mu 0"),
                                  (nNone, nZero, "nodes mu 0")):
        times = sorted(t for t in run.time_dirs(a_case) if t > 0)
        differ = []
        for t in times:
            name = run.time_dirs(a_case)[t]
            for field in ("lm", "F", "D", "pointD"):
                a = internal_text(os.path.join(a_case, name, field))
                b = internal_text(os.path.join(
                    b_case, run.time_dirs(b_case)[t], field))
                if a != b:
                    differ.append("%s at %s" % (field, name))
        lines.append("%s = frictionless: %d times x 4 fields, %d differ"
                     % (label, len(times), len(differ)))
        if differ or not times:
            failures.append("%s differs from frictionless: %s"
                            % (label, ", ".join(differ[:4])))

    # Coulomb cone and friction power, every step (with side nodes the
    # pairs' columns are the held points')
    rows = contact.read_contact(nFric)
    ratio = np.max(rows["maxPairFrictionRatio"])
    power = np.max(rows["maxPairFrictionPower"])
    lines.append("nodes friction: max |F_t|/N of a held point %.6f (mu %g),"
                 " max point friction power %.1e W" % (ratio, MU, power))
    if ratio > MU * (1 + 1e-12):
        failures.append("nodes friction: |F_t|/N = %.15g > mu" % ratio)
    if not ratio > 0.5 * MU:
        failures.append("nodes friction: |F_t|/N at most %.3g: the held "
                        "points do not slide at mu" % ratio)
    if power > 0:
        failures.append("nodes friction: a point's friction power %.2e > 0"
                        % power)

    for case, label in ((fric, "friction"), (offs, "offset")):
        rows = contact.read_contact(case)
        ratio = np.max(rows["maxFrictionRatio"])
        power = np.max(rows["maxPairFrictionPower"])
        lines.append("%s: max |t_t|/|t_n| %.6f (mu %g), max pair friction "
                     "power %.1e W" % (label, ratio, MU, power))
        if ratio > MU * (1 + 1e-12):
            failures.append("%s: |t_t|/|t_n| = %.15g > mu" % (label, ratio))
        if power > 0:
            failures.append("%s: a pair's friction power %.2e > 0"
                            % (label, power))

    # Friction dissipation: >= 0, growing, and the fluxes' account.  The
    # contact fluxes' work is the friction's plus what the exchange itself
    # takes where the faces slide across each other (a face's traction is
    # its pairs' by their overlaps, its velocity its own: >= 0), which the
    # frictionless run measures alone
    Df = mFric["frictionDissipation"]
    flux = mFric["boundaryWork(faceA)"] + mFric["boundaryWork(faceB)"]
    E0 = mFric["totalEnergy"][0]
    exchange = -(mNone["boundaryWork(faceA)"][-1]
                 + mNone["boundaryWork(faceB)"][-1])
    rest = -flux[-1] - Df[-1]
    gap = abs(rest) / max(Df[-1], 1e-300)
    lines.append("friction dissipation %.4e E0 at the end, min step "
                 "%+.1e E0, the contact fluxes' work %.4e E0 (%.2e off; the"
                 " exchange's own loss frictionless %.2e E0)"
                 % (Df[-1] / E0, np.min(np.diff(Df)) / E0, flux[-1] / E0,
                    gap, exchange / E0))
    if np.min(Df) < 0 or np.min(np.diff(Df)) < -1e-15 * E0:
        failures.append("friction dissipation negative or decreasing")
    if Df[-1] < 1e-3 * E0:
        failures.append("friction dissipation %.2e E0: no friction"
                        % (Df[-1] / E0))
    if exchange < -1e-12 * E0 or rest < -1e-12 * E0:
        failures.append("the contact's work besides friction gains energy"
                        " (%.2e E0 frictionless, %.2e E0 with friction)"
                        % (-exchange / E0, -rest / E0))
    if rest > 0.01 * Df[-1] + exchange:
        failures.append("friction dissipation off the contact fluxes' "
                        "work by %.2e, beyond 1 %% and the exchange's own"
                        " %.2e" % (gap, exchange / Df[-1]))

    # Sliding Coulomb friction: impulses, relative velocity, spin
    def impulses(case):
        folders = run.time_dirs(case)
        b0 = bodies(case, folders[0.0], N * N)
        b1 = bodies(case, folders[max(folders)], N * N)
        return b0, b1, [b1[k]["p"] - b0[k]["p"] for k in (0, 1)]

    def coulomb_impulses(j, jFree, prefix):
        """Each block's tangential/normal impulse against mu, to within
        the frictionless run's own ratio (the tilt of the contact normals
        at the deforming corners); that ratio."""
        tilt = abs(jFree[0][1] / jFree[0][0])
        for k, label in enumerate("AB"):
            ratio = abs(j[k][1] / j[k][0])
            lines.append("%sblock %s: impulse normal %.4e, tangential %.4e,"
                         " ratio %.4f (frictionless %.4f)"
                         % (prefix, label, j[k][0], j[k][1], ratio, tilt))
            if abs(ratio - MU) > tilt:
                failures.append("%sblock %s: tangential/normal impulse "
                                "%.4f, sliding Coulomb %g, frictionless %.4f"
                                % (prefix, label, ratio, MU, tilt))
        if tilt > 0.2 * MU:
            failures.append("%sfrictionless: tangential/normal impulse %.4f"
                            % (prefix, tilt))
        return tilt

    b0, bF, jF = impulses(fric)
    _, bN, jN = impulses(none)
    coulomb_impulses(jF, jN, "")
    # Side nodes: the same closed form
    coulomb_impulses(impulses(nFric)[2], impulses(nNone)[2], "nodes, ")

    # Sticking (side nodes, mu above Z_s/Z_p): the faces' acoustic
    # sticking traction has |t_t|/|t_n| = Z_s w_rel/(Z_p v_rel) = c_s/c_p
    # here; the impulse ratio at least 0.9 of that and at most mu (a
    # sticking point held by a force alone reached only 0.37), every
    # point within its cone
    jS = impulses(nStick)[2]
    stickRatio = abs(jS[0][1] / jS[0][0])
    acoustic = C_S / C_P
    lines.append("nodes sticking (mu %g): impulse ratio %.4f (acoustic "
                 "sticking %.3f)" % (MU_STICK, stickRatio, acoustic))
    if not 0.9 * acoustic <= stickRatio <= MU_STICK:
        failures.append("nodes sticking: impulse ratio %.4f outside [0.9 "
                        "c_s/c_p, mu] = [%.3f, %g]"
                        % (stickRatio, 0.9 * acoustic, MU_STICK))
    rows = contact.read_contact(nStick)
    if np.max(rows["maxPairFrictionRatio"]) > MU_STICK * (1 + 1e-12):
        failures.append("nodes sticking: a point's |F_t|/N %.15g > mu"
                        % np.max(rows["maxPairFrictionRatio"]))
    lines.append(sticking_restart(root, failures))
    # Spin: the angular impulse about each centroid of the friction at the
    # contact face (L/2 from the centre along x) and of the normal force at
    # the middle of the overlap (L/4 from it along y), closed forms
    for case, b1, j, label in ((fric, bF, jF, "friction"),
                               (none, bN, jN, "frictionless")):
        for k, side in enumerate((1, -1)):
            dspin = b1[k]["spin"] - b0[k]["spin"]
            friction = side * 0.5 * L * j[k][1]
            normal = -side * 0.25 * L * j[k][0]
            off = abs(dspin - friction - normal) / (abs(friction)
                                                    + abs(normal))
            lines.append("%s block %s: spin %.4e, angular impulses: "
                         "tangential %.4e + normal %.4e (%.1e off)"
                         % (label, "AB"[k], dspin, friction, normal, off))
            if off > 0.02:
                failures.append("%s block %s: spin %.4e, angular impulse "
                                "%.4e" % (label, "AB"[k], dspin,
                                          friction + normal))
    fSpin = bF[0]["spin"] - bN[0]["spin"]
    if fSpin >= 0:
        failures.append("friction did not spin block A against its sliding")
    wF = bF[0]["p"][1] / bF[0]["M"] - bF[1]["p"][1] / bF[1]["M"]
    wN = bN[0]["p"][1] / bN[0]["M"] - bN[1]["p"][1] / bN[1]["M"]
    coulomb = 2 * MU * abs(jF[0][0]) / bF[0]["M"]
    lines.append("relative tangential velocity at the end %.4f m/s "
                 "(frictionless %.4f, start %.1f; 2 mu J_n/M %.4f)"
                 % (wF, wN, 2 * W, coulomb))
    if wN - wF < 0.5 * coulomb:
        failures.append("relative tangential velocity %.4f, frictionless "
                        "%.4f: not reduced" % (wF, wN))

    lines.append(auto_side(root, nFric, failures))

    # FUpdate compatible with friction and no side nodes is refused
    comp = make_case(os.path.join(root, "compatible"), friction=(MU, MU),
                     update="compatible")
    try:
        run.run(["touchFoam"], comp, name="touchFoam",
                timeout=testing.RUN_TIMEOUT)
        failures.append("compatible with friction and no side nodes ran")
    except run.RunError:
        with open(os.path.join(comp, "log.touchFoam")) as f:
            log = f.read()
        if any(word not in log for word in ("FUpdate", "side nodes",
                                            "plain", "faceA", "faceB")):
            failures.append("compatible with friction: the refusal does "
                            "not name the patches, FUpdate, side nodes "
                            "and plain")
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
