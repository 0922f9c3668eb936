#!/usr/bin/python3
"""Write cube.msh: the unit cube as n^3 hexes, each split into 6 tets.

    ./makeMesh.py [-n N] [-o cube.msh]

Gmsh 2.2 ASCII with physical surfaces X0 Y0 Z0 X1 Y1 Z1 and the physical
volume 'cube'; convert with 'gmshToFoam cube.msh'.  Python's standard
library only (no gmsh, no numpy, not the project's package).

Each hexahedron is cut into the 6 Kuhn (Freudenthal) tetrahedra, one per
ordering of the axes, walking from the hex's lowest corner to its highest
one axis at a time: every square face is then cut along the diagonal
through its lowest and highest corners, so neighbouring hexes share their
triangles (a conforming mesh).  The points, tetrahedra and triangles come
in the order of bin/python/touchfoam/gmsh.py's write_msh, which the tests
use, so the two write the same file.
"""

import argparse
import itertools

PATCHES = ["X0", "Y0", "Z0", "X1", "Y1", "Z1"]


def cube(n):
    """Points [(x, y, z)] (index (i (n+1) + j)(n+1) + k) and tetrahedra
    [(a, b, c, d)], 0-based, positively oriented."""
    step = 1.0 / n
    coord = [i * step + 0.0 for i in range(n)] + [1.0]
    points = [(x, y, z) for x in coord for y in coord for z in coord]

    def index(i, j, k):
        return (i * (n + 1) + j) * (n + 1) + k

    tets = []
    for order in itertools.permutations(range(3)):
        corner = [0, 0, 0]
        path = [tuple(corner)]
        for axis in order:
            corner[axis] = 1
            path.append(tuple(corner))
        for i in range(n):
            for j in range(n):
                for k in range(n):
                    tets.append([index(i + di, j + dj, k + dk)
                                 for di, dj, dk in path])

    for t in tets:
        p = [points[v] for v in t]
        a, b, c = ([p[m][d] - p[0][d] for d in range(3)] for m in (1, 2, 3))
        volume = ((a[1] * b[2] - a[2] * b[1]) * c[0]
                  + (a[2] * b[0] - a[0] * b[2]) * c[1]
                  + (a[0] * b[1] - a[1] * b[0]) * c[2])
        if volume < 0:
            t[1], t[2] = t[2], t[1]
    return points, tets


def boundary_triangles(points, tets):
    """{patch: [triangle]}: the tets' faces that no other tet shares, in
    the order of their sorted vertices, on each face of the cube."""
    faces = [[t[m] for m in local] for local in
             ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)) for t in tets]
    count = {}
    first = {}
    for face in faces:
        key = tuple(sorted(face))
        count[key] = count.get(key, 0) + 1
        first.setdefault(key, face)
    boundary = [first[key] for key in sorted(count) if count[key] == 1]
    out = {}
    for name in PATCHES:
        axis = "XYZ".index(name[0])
        value = 0.0 if name[1] == "0" else 1.0
        out[name] = [f for f in boundary
                     if all(abs(points[v][axis] - value) < 1e-12 for v in f)]
    if sum(len(f) for f in out.values()) != len(boundary):
        raise RuntimeError("boundary triangles off the cube's faces")
    return out


def write_msh(path, n):
    """Write the mesh; returns (number of points, number of tets)."""
    points, tets = cube(n)
    tris = boundary_triangles(points, tets)
    names = PATCHES + ["cube"]
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames",
             str(len(names))]
    for tag, name in enumerate(names, start=1):
        lines.append('%d %d "%s"' % (3 if name == "cube" else 2, tag, name))
    lines += ["$EndPhysicalNames", "$Nodes", str(len(points))]
    lines += ["%d %r %r %r" % (i + 1, x, y, z)
              for i, (x, y, z) in enumerate(points)]
    lines += ["$EndNodes", "$Elements"]
    # element: id type ntags physical elementary nodes (1-based)
    elements = []
    for tag, name in enumerate(PATCHES, start=1):
        for a, b, c in tris[name]:
            elements.append("2 2 %d %d %d %d %d" % (tag, tag, a + 1, b + 1,
                                                    c + 1))
    tag = len(names)
    for a, b, c, d in tets:
        elements.append("4 2 %d %d %d %d %d %d" % (tag, tag, a + 1, b + 1,
                                                   c + 1, d + 1))
    lines.append(str(len(elements)))
    lines += ["%d %s" % (i + 1, e) for i, e in enumerate(elements)]
    lines.append("$EndElements")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return len(points), len(tets)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-n", type=int, default=8,
                        help="hexes per side before the split (default 8)")
    parser.add_argument("-o", default="cube.msh", help="output file")
    args = parser.parse_args()
    if args.n < 1:
        parser.error("-n must be positive")
    npoints, ntets = write_msh(args.o, args.n)
    print("makeMesh: %s with %d points and %d tetrahedra"
          % (args.o, npoints, ntets))
