"""CalculiX input decks of the comparisons with touchFoam, written here.

Three scenes, each the same physics as touchFoam's case it is compared
with, on structured hexahedral meshes written straight into the deck
(no pre-processor needed):

    column_deck   twisting column (tutorials/twistingColumn): n x 6n x n
                  C3D8 or C3D8R, neo-Hookean, base clamped, initial
                  velocity v = omega x X with omega = (0, Omega
                  sin(pi Y / 2L), 0), one explicit NLGEOM step to t_end
    cube_deck     swinging cube (tutorials/swingingCube): N^3, linear
                  elastic, small strain, symmetric planes X0 Y0 Z0 and
                  skew-symmetric X1 Y1 Z1, the exact mode as initial
                  displacement, explicit to t_end
    taylor_deck   Taylor bar (validation/taylorImpact): quarter model of a
                  copper bar with an O-grid ("butterfly") cross-section,
                  J2 plasticity with linear isotropic hardening, rigid
                  frictionless wall at Y = 0, explicit NLGEOM

What CalculiX 2.20 needs, and why the decks look as they do:

- Numeric fields are read as at most 20 characters and longer ones are
  cut without a warning, so every number is written with at most 13
  significant digits (FIELD).
- *DYNAMIC, EXPLICIT picks its own ("Volumetric COURANT") increment at the
  start of each step and keeps it for the step; the initial increment of
  the data line is not used.  A fourth field caps it (the Taylor bar
  needs the cap: the step's first estimate is too large once the bar has
  deformed).  One step per deck, so results at t_end come from the step's
  end: the last increment of a step is always written.
- One output FREQUENCY applies to both the .dat and the .frd, the last
  given wins; OUTPUT_AT_END (larger than any increment count) writes only
  the step's last increment.
- Neo-Hooke: *HYPERELASTIC, NEO HOOKE with C10 = mu/2, D1 = 2/K, CalculiX's
  W = C10 (I1bar - 3) + (J - 1)^2 / D1, which is the tutorial's
  neoHookean law (mu/2 (I1bar - 3) + K/2 (J - 1)^2).

Node numbers: the node at grid point (i, j, k) is 1 + i + (nx + 1) (k +
(nz + 1) j) for the column (layers along the long axis Y), 1 + i + (N + 1)
(j + (N + 1) k) for the cube.  Element nodes are listed face k, then
face k + 1, each counter-clockwise seen from +Z (CalculiX's C3D8 order, a
positive Jacobian).

Also used by the test deckWriter (no ccx needed), which checks the counts,
the node sets and the initial fields against their closed forms.
"""

import math

#: an output frequency larger than any run's increments: only the last
#: increment of the step is written
OUTPUT_AT_END = 100000000
#: the initial-increment field of *DYNAMIC, EXPLICIT (CalculiX replaces it
#: by its own estimate)
NOMINAL_DT = 1e-4

#: twisting column (the seed paper's example; tutorials/twistingColumn)
COLUMN = {"E": 17e6, "rho": 1100.0, "Omega": 105.0, "L": 6.0, "width": 1.0}
#: swinging cube (tutorials/swingingCube)
CUBE = {"E": 1.7e7, "nu": 0.3, "rho": 1100.0, "U0": 5e-4}
#: Taylor bar (validation/taylorImpact): copper, radius and length [m],
#: impact speed [m/s], yield stress and hardening modulus [Pa]
TAYLOR = {"E": 117e9, "nu": 0.35, "rho": 8930.0, "R": 3.2e-3,
          "L": 32.4e-3, "V0": 227.0, "sigmaY": 0.4e9, "H": 0.1e9,
          "innerFraction": 0.5}


def field(x):
    """A number as CalculiX reads it in full (at most 20 characters)."""
    text = "%.12e" % x if x != 0.0 else "0."
    assert len(text) <= 20, text
    return text


class Deck:
    """Lines of an .inp file, with the keyword blocks the scenes share."""

    def __init__(self, title):
        self.lines = ["** " + title]

    def add(self, *lines):
        self.lines.extend(lines)

    def nodes(self, points):
        """points: [(id, (x, y, z))]"""
        self.add("*NODE, NSET=NALL")
        self.add(*("%d, %s, %s, %s" % ((i,) + tuple(field(c) for c in p))
                   for i, p in points))

    def elements(self, element, connectivity):
        self.add("*ELEMENT, TYPE=%s, ELSET=EALL" % element)
        self.add(*("%d, %s" % (e + 1, ", ".join(str(n) for n in nodes))
                   for e, nodes in enumerate(connectivity)))

    def node_set(self, name, ids):
        self.add("*NSET, NSET=%s" % name)
        ids = list(ids)
        for start in range(0, len(ids), 12):
            self.add(", ".join(str(i) for i in ids[start:start + 12]) + ",")

    def initial(self, kind, values):
        """values: [(node id, dof, value)], zeros left out."""
        self.add("*INITIAL CONDITIONS, TYPE=%s" % kind)
        self.add(*("%d, %d, %s" % (n, d, field(v))
                   for n, d, v in values if v != 0.0))

    def write(self, path):
        with open(path, "w") as f:
            f.write("\n".join(self.lines) + "\n")
        return path


def hexahedron(node, i, j, k):
    """The 8 node ids of the cell (i, j, k) in CalculiX's C3D8 order."""
    face = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
    return [node(a, b, k) for a, b in face] + [node(a, b, k + 1)
                                               for a, b in face]


def neo_hooke_constants(E, nu):
    """(C10, D1) of CalculiX's NEO HOOKE for Young's modulus and Poisson's
    ratio: C10 = mu/2, D1 = 2/K."""
    mu = E / (2.0 * (1.0 + nu))
    K = E / (3.0 * (1.0 - 2.0 * nu))
    return mu / 2.0, 2.0 / K


# -- twisting column ----------------------------------------------------------

class ColumnGrid:
    """n x 6n x n grid of the column [-w/2, w/2] x [0, L] x [-w/2, w/2]
    (L = 6 w: cubic cells)."""

    def __init__(self, n, length=COLUMN["L"], width=COLUMN["width"]):
        self.nx, self.ny, self.nz = n, 6 * n, n
        self.length, self.width = length, width

    def node(self, i, j, k):
        return 1 + i + (self.nx + 1) * (k + (self.nz + 1) * j)

    def point(self, i, j, k):
        return (self.width * (i / self.nx - 0.5), self.length * j / self.ny,
                self.width * (k / self.nz - 0.5))

    def grid_points(self):
        return [(i, j, k) for j in range(self.ny + 1)
                for k in range(self.nz + 1) for i in range(self.nx + 1)]

    def cells(self):
        return [(i, j, k) for j in range(self.ny) for k in range(self.nz)
                for i in range(self.nx)]


def column_velocity(point, Omega=COLUMN["Omega"], L=COLUMN["L"]):
    """v = omega x X, omega = (0, Omega sin(pi Y / 2L), 0): (w Z, 0, -w X)."""
    x, y, z = point
    w = Omega * math.sin(math.pi * y / (2.0 * L))
    return (w * z, 0.0, -w * x)


def column_deck(path, n, element, nu, t_end):
    """Write the twisting column's deck to path.

    Prints the displacements of the top face (NTOP) to the .dat and of
    every node to the .frd at the step's last increment only.
    """
    grid = ColumnGrid(n)
    c10, d1 = neo_hooke_constants(COLUMN["E"], nu)
    deck = Deck("twisting column %dx%dx%d %s, nu %g, to t = %g s "
                "(validation/calculix/decks.py)"
                % (grid.nx, grid.ny, grid.nz, element, nu, t_end))
    deck.nodes([(grid.node(*g), grid.point(*g)) for g in grid.grid_points()])
    deck.elements(element, [hexahedron(grid.node, *c) for c in grid.cells()])
    layer = [(i, k) for k in range(grid.nz + 1) for i in range(grid.nx + 1)]
    deck.node_set("NBOT", [grid.node(i, 0, k) for i, k in layer])
    deck.node_set("NTOP", [grid.node(i, grid.ny, k) for i, k in layer])
    deck.add("*BOUNDARY", "NBOT, 1, 3",
             "*MATERIAL, NAME=RUBBER", "*HYPERELASTIC, NEO HOOKE",
             "%s, %s" % (field(c10), field(d1)),
             "*DENSITY", field(COLUMN["rho"]),
             "*SOLID SECTION, ELSET=EALL, MATERIAL=RUBBER")
    velocities = []
    for g in grid.grid_points():
        v = column_velocity(grid.point(*g))
        velocities += [(grid.node(*g), 1, v[0]), (grid.node(*g), 3, v[2])]
    deck.initial("VELOCITY", velocities)
    deck.add("*STEP, NLGEOM, INC=%d" % OUTPUT_AT_END,
             "*DYNAMIC, EXPLICIT", "%s, %s" % (field(NOMINAL_DT),
                                               field(t_end)),
             "*NODE PRINT, NSET=NTOP, FREQUENCY=%d" % OUTPUT_AT_END, "U",
             "*NODE FILE, NSET=NALL, FREQUENCY=%d" % OUTPUT_AT_END, "U",
             "*END STEP")
    return deck.write(path)


# -- swinging cube ------------------------------------------------------------

def cube_node(n):
    """Node id of grid point (i, j, k) of the N^3 cube."""
    return lambda i, j, k: 1 + i + (n + 1) * (j + (n + 1) * k)


def cube_mode(point, U0=CUBE["U0"]):
    """The swinging mode's displacement at t = 0: U0 (sin(pX) cos(pY)
    cos(pZ), cos(pX) sin(pY) cos(pZ), cos(pX) cos(pY) sin(pZ)), p = pi/2."""
    s = [math.sin(0.5 * math.pi * c) for c in point]
    c = [math.cos(0.5 * math.pi * c) for c in point]
    return (U0 * s[0] * c[1] * c[2], U0 * c[0] * s[1] * c[2],
            U0 * c[0] * c[1] * s[2])


def cube_deck(path, n, element, t_end=0.004):
    """Write the N^3 swinging cube's deck to path: linear elastic, small
    strain, released from the exact mode at rest.

    Faces X0, Y0, Z0 are symmetric planes (normal displacement zero), X1,
    Y1, Z1 skew-symmetric (tangential displacements zero), as the closed
    form has them.  Prints U and V of every node and the stresses of every
    integration point at the step's last increment only.
    """
    node = cube_node(n)
    R = range(n + 1)
    points = [(i, j, k) for k in R for j in R for i in R]
    deck = Deck("swinging cube %d^3 %s to t = %g s "
                "(validation/calculix/decks.py)" % (n, element, t_end))
    deck.nodes([(node(*g), tuple(c / n for c in g)) for g in points])
    deck.elements(element, [hexahedron(node, i, j, k) for k in range(n)
                            for j in range(n) for i in range(n)])
    face = [(a, b) for a in R for b in R]
    deck.node_set("X0", [node(0, a, b) for a, b in face])
    deck.node_set("Y0", [node(a, 0, b) for a, b in face])
    deck.node_set("Z0", [node(a, b, 0) for a, b in face])
    deck.node_set("X1", [node(n, a, b) for a, b in face])
    deck.node_set("Y1", [node(a, n, b) for a, b in face])
    deck.node_set("Z1", [node(a, b, n) for a, b in face])
    deck.add("*BOUNDARY", "X0, 1, 1", "Y0, 2, 2", "Z0, 3, 3",
             "X1, 2, 3", "Y1, 1, 1", "Y1, 3, 3", "Z1, 1, 2",
             "*MATERIAL, NAME=CUBE", "*ELASTIC",
             "%s, %s" % (field(CUBE["E"]), field(CUBE["nu"])),
             "*DENSITY", field(CUBE["rho"]),
             "*SOLID SECTION, ELSET=EALL, MATERIAL=CUBE")
    displacements = []
    for g in points:
        u = cube_mode(tuple(c / n for c in g))
        displacements += [(node(*g), d + 1, u[d]) for d in range(3)
                          if abs(u[d]) > 1e-300]
    deck.initial("DISPLACEMENT", displacements)
    deck.add("*STEP, INC=%d" % OUTPUT_AT_END, "*DYNAMIC, EXPLICIT",
             "%s, %s" % (field(1e-6), field(t_end)),
             "*NODE PRINT, NSET=NALL, FREQUENCY=%d" % OUTPUT_AT_END, "U, V",
             "*EL PRINT, ELSET=EALL, FREQUENCY=%d" % OUTPUT_AT_END, "S",
             "*END STEP")
    return deck.write(path)


# -- Taylor bar ---------------------------------------------------------------

def quarter_disk(n, m, R, inner_fraction):
    """O-grid of the quarter disk x, z >= 0, x^2 + z^2 <= R^2: an n x n
    square [0, a]^2 (a = inner_fraction R) and two n x m blocks from its
    edges x = a and z = a to the arc, blended linearly along the radius.
    Returns the points [(x, z)] and the quads (point indices,
    counter-clockwise in (x, z) or not: taylor_deck orients them)."""
    a = inner_fraction * R
    points, index = [], {}

    def point(x, z):
        key = (round(x * 1e12), round(z * 1e12))
        if key not in index:
            index[key] = len(points)
            points.append((x, z))
        return index[key]

    square = [[point(a * i / n, a * j / n) for j in range(n + 1)]
              for i in range(n + 1)]
    quads = [(square[i][j], square[i + 1][j], square[i + 1][j + 1],
              square[i][j + 1]) for i in range(n) for j in range(n)]
    for along_x in (True, False):
        rows = []
        for t in (i / n for i in range(n + 1)):
            inner = (a, a * t) if along_x else (a * t, a)
            angle = (t if along_x else 2.0 - t) * math.pi / 4
            outer = (R * math.cos(angle), R * math.sin(angle))
            rows.append([point(inner[0] + s * (outer[0] - inner[0]),
                               inner[1] + s * (outer[1] - inner[1]))
                         for s in (k / m for k in range(m + 1))])
        quads += [(rows[i][k], rows[i][k + 1], rows[i + 1][k + 1],
                   rows[i + 1][k]) for i in range(n) for k in range(m)]
    return points, quads


def taylor_deck(path, n, m, layers, element="C3D8R", t_end=8e-5,
                dt_max=6e-9, output_every=667):
    """Write the Taylor bar's deck to path (quarter model, axis Y, wall at
    Y = 0).

    The impact face's nodes are held at u_y = 0 from t = 0 (a rigid
    frictionless wall that the bar never leaves in 80 us), every other
    node starts at v_y = -V0; symmetry planes X = 0 and Z = 0.  J2
    plasticity, sigma_y = sigma_y0 + H eps_p (the table is extended to
    eps_p = 10 on the same line).  dt_max caps CalculiX's increment: its
    own estimate (about 1.2e-8 s) goes unstable near 45 us.  Writes the
    monitored nodes' U (NMON: the axis top and bottom, the rims of both
    ends) every output_every increments, and at the end every node's U
    and PEEQ to the .frd and the integration points' PEEQ to the .dat.
    """
    p = TAYLOR
    points, quads = quarter_disk(n, m, p["R"], p["innerFraction"])
    per_layer = len(points)
    ys = [p["L"] * j / layers for j in range(layers + 1)]

    def node(q, j):
        return 1 + q + per_layer * j

    deck = Deck("Taylor bar, quarter model, O-grid %d/%d/%d %s "
                "(validation/calculix/decks.py)" % (n, m, layers, element))
    deck.nodes([(node(q, j), (x, y, z)) for j, y in enumerate(ys)
                for q, (x, z) in enumerate(points)])
    connectivity = []
    for j in range(layers):
        for quad in quads:
            (x0, z0), (x1, z1), (x3, z3) = (points[quad[0]],
                                            points[quad[1]], points[quad[3]])
            # (n2 - n1) x (n4 - n1) must point to +Y, the next layer:
            # its Y component is dz1 dx3 - dx1 dz3
            if (z1 - z0) * (x3 - x0) - (x1 - x0) * (z3 - z0) < 0:
                quad = (quad[0], quad[3], quad[2], quad[1])
            connectivity.append([node(q, j) for q in quad]
                                + [node(q, j + 1) for q in quad])
    deck.elements(element, connectivity)
    tol = 1e-12
    axis = [q for q, (x, z) in enumerate(points) if abs(x) < tol
            and abs(z) < tol][0]
    rim = [q for q, (x, z) in enumerate(points)
           if abs(math.hypot(x, z) - p["R"]) < 1e-9]
    every = [(q, j) for j in range(layers + 1) for q in range(per_layer)]
    deck.node_set("NX0", [node(q, j) for q, j in every
                          if abs(points[q][0]) < tol])
    deck.node_set("NZ0", [node(q, j) for q, j in every
                          if abs(points[q][1]) < tol])
    deck.node_set("NIMP", [node(q, 0) for q in range(per_layer)])
    deck.node_set("NMOVE", [node(q, j) for q, j in every if j > 0])
    deck.node_set("NMON", [node(axis, layers), node(axis, 0)]
                  + [node(q, 0) for q in rim]
                  + [node(q, layers) for q in rim])
    deck.add("*BOUNDARY", "NX0, 1, 1", "NZ0, 3, 3", "NIMP, 2, 2",
             "*MATERIAL, NAME=COPPER", "*ELASTIC",
             "%s, %s" % (field(p["E"]), field(p["nu"])), "*PLASTIC",
             "%s, 0." % field(p["sigmaY"]),
             "%s, 3." % field(p["sigmaY"] + 3.0 * p["H"]),
             "%s, 10." % field(p["sigmaY"] + 10.0 * p["H"]),
             "*DENSITY", field(p["rho"]),
             "*SOLID SECTION, ELSET=EALL, MATERIAL=COPPER",
             "*INITIAL CONDITIONS, TYPE=VELOCITY",
             "NMOVE, 2, %s" % field(-p["V0"]),
             "*STEP, NLGEOM, INC=%d" % OUTPUT_AT_END, "*DYNAMIC, EXPLICIT",
             "%s, %s, %s, %s" % (field(1e-9), field(t_end), field(1e-15),
                                 field(dt_max)),
             "*NODE PRINT, NSET=NMON, FREQUENCY=%d" % output_every, "U",
             "*EL PRINT, ELSET=EALL, FREQUENCY=%d" % output_every, "PEEQ",
             "*NODE FILE, FREQUENCY=%d" % output_every, "U",
             "*EL FILE, FREQUENCY=%d" % output_every, "PEEQ",
             "*END STEP")
    return deck.write(path)
