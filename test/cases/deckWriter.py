#!/usr/bin/python3
"""The CalculiX decks of validation/calculix/decks.py hold the scenes they
claim to, checked without CalculiX.

    /usr/bin/python3 test/cases/deckWriter.py

The decks are read back with the comparison's own reader (ccx.read_inp)
and checked against closed forms written here, independently of the
writer:

  - counts: (n+1)^2 (6n+1) nodes and 6 n^3 elements for the column,
    (N+1)^3 and N^3 for the cube, (N^2 + 2 N M) NY elements for the
    Taylor bar; the node sets' sizes and positions (column base at Y = 0
    and top at Y = 6; the cube's six faces; the bar's impact face at
    Y = 0, its moving nodes all others);
  - every element: the Jacobian of CalculiX's C3D8 map at the element
    centre is positive (nodes 1-4 on one face, 5-8 on the other, in the
    order that gives an outward right-handed frame), and for the column
    and the cube 8 det J is the cell volume h^3;
  - initial fields: the column's velocity at each node against v = omega
    x X, omega = (0, 105 sin(pi Y / 12), 0) (a cross product here, not
    the writer's components), and the cube's displacement against
    U0 sin(pi X_i / 2) prod_j!=i cos(pi X_j / 2); the Taylor bar's -227 m/s
    on the moving set;
  - material: C10 = E / (4 (1 + nu)) and D1 = 6 (1 - 2 nu) / E (neo-Hooke
    from E and nu), density, the step's keywords (NLGEOM, explicit, end
    time).

Controls: a column deck whose spin is reversed and one with an element's
two faces swapped must fail the velocity and the Jacobian checks.  No
solver and no ccx are needed.
"""

import math
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "validation", "calculix"))

from touchfoam import testing  # noqa: E402

import ccx  # noqa: E402
import decks  # noqa: E402

NAME = "deckWriter"
NU = 0.45
#: natural coordinates of C3D8's nodes 1-8
CORNERS = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
           (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]


def det3(a):
    return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
            - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))


def centre_jacobian(points):
    """det of dx/d(r, s, t) at the centre of a C3D8 with nodes points."""
    J = [[sum(p[i] * c[j] / 8.0 for p, c in zip(points, CORNERS))
          for j in range(3)] for i in range(3)]
    return det3(J)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def initial_values(other, kind):
    """{(node, dof): value} of the deck's *INITIAL CONDITIONS of kind
    (read_inp keeps the data lines under the keyword's first word)."""
    values = {}
    for line in other.get("*INITIAL CONDITIONS", []):
        p = [x.strip() for x in line.split(",")]
        if p[0].isdigit():
            values[(int(p[0]), int(p[1]))] = float(p[2])
    return values


def keyword_lines(path):
    with open(path) as f:
        return [line.strip().upper() for line in f
                if line.startswith("*") and not line.startswith("**")]


def data_after(path, keyword):
    """The first data line after the keyword line."""
    with open(path) as f:
        lines = [line.strip() for line in f]
    i = next(k for k, line in enumerate(lines)
             if line.upper().startswith(keyword))
    return [float(x) for x in lines[i + 1].split(",") if x.strip()]


def node_sets(path):
    sets, current = {}, None
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line.upper().startswith("*NSET"):
                current = line.split("=")[1].strip()
                sets[current] = []
            elif line.startswith("*"):
                current = None
            elif current:
                sets[current] += [int(x) for x in line.split(",")
                                  if x.strip()]
    return sets


def check_elements(nodes, elements, volume, failures, label):
    """Count of elements with det J <= 0 or a wrong volume."""
    bad = 0
    for e, ids in elements.items():
        det = centre_jacobian([nodes[i] for i in ids])
        if det <= 0 or (volume and abs(8 * det - volume) > 1e-9 * volume):
            bad += 1
    if bad:
        failures.append("%s: %d of %d elements with det J <= 0 or 8 det J "
                        "!= h^3" % (label, bad, len(elements)))
    return bad


def check_column(path, n, failures):
    nodes, elements, other = ccx.read_inp(path)
    label = "column n=%d" % n
    if len(nodes) != (n + 1) ** 2 * (6 * n + 1) or len(elements) != 6 * n ** 3:
        failures.append("%s: %d nodes, %d elements" % (label, len(nodes),
                                                       len(elements)))
    bad = check_elements(nodes, elements, (1.0 / n) ** 3, failures, label)
    sets = node_sets(path)
    for name, y in (("NBOT", 0.0), ("NTOP", 6.0)):
        ids = sets.get(name, [])
        if len(ids) != (n + 1) ** 2 or any(abs(nodes[i][1] - y) > 1e-12
                                           for i in ids):
            failures.append("%s: set %s is not the face Y = %g"
                            % (label, name, y))
    v = initial_values(other, "VELOCITY")
    worst = 0.0
    for i, X in nodes.items():
        omega = (0.0, 105.0 * math.sin(math.pi * X[1] / 12.0), 0.0)
        exact = cross(omega, X)
        for d in range(3):
            worst = max(worst, abs(v.get((i, d + 1), 0.0) - exact[d]))
    if worst > 1e-9:
        failures.append("%s: initial velocity off omega x X by %.3g m/s"
                        % (label, worst))
    E = decks.COLUMN["E"]
    c10, d1 = data_after(path, "*HYPERELASTIC")
    if abs(c10 - E / (4 * (1 + NU))) > 1e-9 * c10 or \
            abs(d1 - 6 * (1 - 2 * NU) / E) > 1e-9 * d1:
        failures.append("%s: C10, D1 = %g, %g" % (label, c10, d1))
    keys = keyword_lines(path)
    if "*STEP, NLGEOM, INC=%d" % decks.OUTPUT_AT_END not in keys \
            or "*DYNAMIC, EXPLICIT" not in keys \
            or data_after(path, "*DYNAMIC")[1] != 0.1 \
            or data_after(path, "*DENSITY")[0] != 1100.0:
        failures.append("%s: step or density not as the tutorial" % label)
    return len(nodes), len(elements), bad, worst


def check_cube(path, n, failures):
    nodes, elements, other = ccx.read_inp(path)
    label = "cube N=%d" % n
    if len(nodes) != (n + 1) ** 3 or len(elements) != n ** 3:
        failures.append("%s: %d nodes, %d elements" % (label, len(nodes),
                                                       len(elements)))
    check_elements(nodes, elements, (1.0 / n) ** 3, failures, label)
    sets = node_sets(path)
    for axis in range(3):
        for end in (0, 1):
            ids = sets.get("XYZ"[axis] + str(end), [])
            if len(ids) != (n + 1) ** 2 or any(
                    abs(nodes[i][axis] - end) > 1e-12 for i in ids):
                failures.append("%s: set %s%d is not its face"
                                % (label, "XYZ"[axis], end))
    u = initial_values(other, "DISPLACEMENT")
    worst = 0.0
    for i, X in nodes.items():
        c = [math.cos(math.pi * x / 2) for x in X]
        for d in range(3):
            exact = 5e-4 * math.sin(math.pi * X[d] / 2) * \
                c[(d + 1) % 3] * c[(d + 2) % 3]
            worst = max(worst, abs(u.get((i, d + 1), 0.0) - exact))
    if worst > 1e-15:
        failures.append("%s: initial displacement off the mode by %.3g m"
                        % (label, worst))
    return worst


def check_taylor(path, n, m, layers, failures):
    nodes, elements, other = ccx.read_inp(path)
    label = "Taylor %d/%d/%d" % (n, m, layers)
    if len(elements) != (n * n + 2 * n * m) * layers:
        failures.append("%s: %d elements" % (label, len(elements)))
    bad = check_elements(nodes, elements, None, failures, label)
    sets = node_sets(path)
    impact, moving = set(sets["NIMP"]), set(sets["NMOVE"])
    if impact & moving or impact | moving != set(nodes) or any(
            abs(nodes[i][1]) > 1e-15 for i in impact):
        failures.append("%s: NIMP is not the face Y = 0 or NMOVE not the "
                        "rest" % label)
    R = decks.TAYLOR["R"]
    outside = max(math.hypot(x, z) for x, _, z in nodes.values())
    if abs(outside - R) > 1e-12:
        failures.append("%s: outer radius %g, not %g" % (label, outside, R))
    v = other.get("*INITIAL CONDITIONS", [])
    if v != ["NMOVE, 2, %s" % decks.field(-227.0)]:
        failures.append("%s: initial velocity %s" % (label, v))
    return len(elements), bad


def body():
    failures, lines = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for n, element in ((2, "C3D8R"), (3, "C3D8")):
            path = decks.column_deck(os.path.join(tmp, "column.inp"), n,
                                     element, NU, 0.1)
            count, cells, bad, worst = check_column(path, n, failures)
            lines.append("column %s n=%d: %d nodes, %d elements, velocity "
                         "within %.1e m/s of omega x X"
                         % (element, n, count, cells, worst))
        path = decks.cube_deck(os.path.join(tmp, "cube.inp"), 3, "C3D8")
        worst = check_cube(path, 3, failures)
        lines.append("cube N=3: displacement within %.1e m of the mode"
                     % worst)
        path = decks.taylor_deck(os.path.join(tmp, "taylor.inp"), 2, 2, 6)
        cells, bad = check_taylor(path, 2, 2, 6, failures)
        lines.append("Taylor 2/2/6: %d elements, %d with det J <= 0"
                     % (cells, bad))

        # Controls: the spin reversed, one element's faces swapped
        path = decks.column_deck(os.path.join(tmp, "control.inp"), 2,
                                 "C3D8R", NU, 0.1)
        with open(path) as f:
            text = f.read()
        head, tail = text.split("*INITIAL CONDITIONS, TYPE=VELOCITY\n")
        data, rest = tail.split("*STEP", 1)
        flipped = "\n".join(
            ", ".join(p[:2] + [decks.field(-float(p[2]))])
            for p in (line.split(", ") for line in data.strip().split("\n")))
        element = text.split("*ELEMENT")[1].split("\n")[1]
        ids = element.split(", ")
        swapped = ", ".join([ids[0]] + ids[5:9] + ids[1:5])
        with open(path, "w") as f:
            f.write((head + "*INITIAL CONDITIONS, TYPE=VELOCITY\n" + flipped
                     + "\n*STEP" + rest).replace(element, swapped, 1))
        control = []
        check_column(path, 2, control)
        caught = [any("initial velocity" in c for c in control),
                  any("det J <= 0" in c for c in control)]
        if not all(caught):
            failures.append("controls not caught (reversed spin %s, swapped "
                            "faces %s): %s" % (caught[0], caught[1],
                                               control))
        lines.append("controls: reversed spin %s, swapped faces %s"
                     % tuple("caught" if c else "MISSED" for c in caught))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body, needs_solver=False))
