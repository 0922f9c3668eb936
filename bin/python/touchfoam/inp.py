"""Abaqus/CalculiX .inp decks of test geometries, for bin/inpToGmsh.

write_bar_inp() writes a bar of C3D8 hexahedra along x in two element
sets, 'left' (x < split) and 'right', with the element-face surfaces
'left' (x = 0), 'right' (x = length) and 'sides' (the four lateral
faces).  Converted with

    inpToGmsh bar.inp && gmshToFoam bar.msh

it gives the cellZones 'left' and 'right' and the patches 'left', 'right'
and 'sides' (a bimaterial bar once each zone has its material).
"""

import numpy as np


def bar_labels(counts):
    """(node label array [i, j, k], element label array [i, j, k]),
    1-based, x fastest."""
    nx, ny, nz = counts
    nodes = 1 + np.arange((nx + 1) * (ny + 1) * (nz + 1)).reshape(
        nz + 1, ny + 1, nx + 1).transpose(2, 1, 0)
    elements = 1 + np.arange(nx * ny * nz).reshape(nz, ny, nx).transpose(
        2, 1, 0)
    return nodes, elements


def write_bar_inp(path, counts=(20, 1, 1), size=(1.0, 0.05, 0.05),
                  split=None, inverted=(), heading="bimaterial bar"):
    """Write the bar deck; returns {'left': n, 'right': n} element counts.

    counts: hexahedra along x, y, z; size: the bar's length, width and
    height [m]; split: the x of the interface (default the middle, moved to
    the nearest element face); inverted: element labels written with their
    nodes in the mirror order (negative volume), for error tests.
    """
    nx, ny, nz = counts
    length, width, height = size
    split = 0.5 * length if split is None else split
    nleft = int(round(split / length * nx))
    if not 0 < nleft < nx:
        raise ValueError("split %g leaves an empty element set" % split)
    node, elem = bar_labels(counts)
    xs = np.linspace(0.0, length, nx + 1)
    ys = np.linspace(0.0, width, ny + 1)
    zs = np.linspace(0.0, height, nz + 1)

    out = ["*HEADING\n%s\n" % heading, "*NODE, NSET=NALL\n"]
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                out.append("%d, %.17g, %.17g, %.17g\n"
                           % (node[i, j, k], xs[i], ys[j], zs[k]))
    out.append("*ELEMENT, TYPE=C3D8, ELSET=EALL\n")
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                corners = [node[i, j, k], node[i + 1, j, k],
                           node[i + 1, j + 1, k], node[i, j + 1, k],
                           node[i, j, k + 1], node[i + 1, j, k + 1],
                           node[i + 1, j + 1, k + 1], node[i, j + 1, k + 1]]
                if elem[i, j, k] in inverted:
                    corners = corners[4:] + corners[:4]
                out.append("%d, %s\n" % (elem[i, j, k],
                                         ", ".join(map(str, corners))))

    def elset(name, labels):
        labels = sorted(int(v) for v in np.ravel(labels))
        out.append("*ELSET, ELSET=%s\n" % name)
        for s in range(0, len(labels), 16):
            out.append(", ".join(map(str, labels[s:s + 16])) + "\n")

    elset("left", elem[:nleft])
    elset("right", elem[nleft:])
    # The surfaces list their elements and faces (Abaqus C3D8 faces: S1
    # z-, S2 z+, S3 y-, S4 x+, S5 y+, S6 x-); no helper element set, so
    # that the default zones of inpToGmsh are 'left' and 'right'
    def surface(name, parts):
        out.append("*SURFACE, NAME=%s, TYPE=ELEMENT\n" % name)
        for labels, face in parts:
            out.extend("%d, %s\n" % (v, face)
                       for v in sorted(int(v) for v in np.ravel(labels)))

    surface("left", [(elem[0], "S6")])
    surface("right", [(elem[-1], "S4")])
    surface("sides", [(elem[:, 0], "S3"), (elem[:, -1], "S5"),
                      (elem[:, :, 0], "S1"), (elem[:, :, -1], "S2")])
    with open(path, "w") as f:
        f.write("".join(out))
    return {"left": nleft * ny * nz, "right": (nx - nleft) * ny * nz}
