"""Gmsh 2.2 ASCII mesh of the unit cube split into tetrahedra.

Each hexahedron of an n x n x n grid is cut into the 6 Kuhn (Freudenthal)
tetrahedra: one per ordering of the axes, walking from the hex's lowest
corner to its highest one axis at a time.  Every square face is then cut
along the diagonal through its lowest and highest corners, whichever hex
it belongs to, so neighbouring hexes share the same triangles (conforming).

Physical groups: surfaces X0 Y0 Z0 X1 Y1 Z1 (the faces X = 0, ..., Z = 1)
and the volume 'cube'; gmshToFoam turns the surfaces into patches.
"""

import itertools

import numpy as np

PATCHES = ["X0", "Y0", "Z0", "X1", "Y1", "Z1"]


def cube_tets(n, length=1.0):
    """(points (N, 3), tets (M, 4) 0-based, positively oriented)."""
    return box_tets((n, n, n), (0.0, 0.0, 0.0), (length, length, length))


def box_tets(counts, lower, upper):
    """The box lower..upper as counts[0] x counts[1] x counts[2] hexes, each
    cut into the 6 Kuhn tetrahedra: (points (N, 3), tets (M, 4))."""
    nx, ny, nz = counts
    idx = np.arange((nx + 1) * (ny + 1) * (nz + 1)).reshape(
        nx + 1, ny + 1, nz + 1)  # [i, j, k]
    axes = [np.linspace(lower[d], upper[d], counts[d] + 1) for d in range(3)]
    I, J, K = np.meshgrid(*axes, indexing="ij")
    points = np.stack([I.ravel(), J.ravel(), K.ravel()], axis=1)

    tets = []
    for order in itertools.permutations(range(3)):
        # Corner offsets along the path (0,0,0) -> ... -> (1,1,1)
        corner = [0, 0, 0]
        path = [tuple(corner)]
        for axis in order:
            corner[axis] = 1
            path.append(tuple(corner))
        verts = [idx[di:di + nx, dj:dj + ny, dk:dk + nz].ravel()
                 for di, dj, dk in path]
        tets.append(np.stack(verts, axis=1))
    tets = np.concatenate(tets)

    # Gmsh tetrahedra have positive volume (v1-v0, v2-v0, v3-v0): swap two
    # vertices of the odd permutations
    p = points[tets]
    vol = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]),
                    p[:, 3] - p[:, 0])
    neg = vol < 0
    tets[neg, 1], tets[neg, 2] = tets[neg, 2].copy(), tets[neg, 1].copy()
    return points, tets


def boundary_triangles(tets, points, length=1.0, tol=1e-12, lower=None,
                       upper=None):
    """{patch: (T, 3) triangles}: the tet faces lying on each cube face
    (or on each face of the box lower..upper)."""
    lower = (0.0, 0.0, 0.0) if lower is None else lower
    upper = (length, length, length) if upper is None else upper
    length = max(abs(v) for v in list(lower) + list(upper))
    faces = np.concatenate([tets[:, [0, 1, 2]], tets[:, [0, 1, 3]],
                            tets[:, [0, 2, 3]], tets[:, [1, 2, 3]]])
    key = np.sort(faces, axis=1)
    _, first, count = np.unique(key, axis=0, return_index=True,
                                return_counts=True)
    boundary = faces[first[count == 1]]
    pts = points[boundary]  # (T, 3, 3)
    out = {}
    for name in PATCHES:
        axis = "XYZ".index(name[0])
        value = lower[axis] if name[1] == "0" else upper[axis]
        on = np.all(np.abs(pts[:, :, axis] - value) < tol * max(1, length),
                    axis=1)
        out[name] = boundary[on]
    nfound = sum(len(v) for v in out.values())
    if nfound != len(boundary):
        raise RuntimeError("%d boundary triangles, %d on the cube faces"
                           % (len(boundary), nfound))
    return out


def write_msh(path, n, length=1.0):
    """Write the cube mesh; returns (number of points, number of tets)."""
    return write_box_msh(path, (n, n, n), (0.0, 0.0, 0.0),
                         (length, length, length))


def write_box_msh(path, counts, lower, upper, groups=None, volume="cube"):
    """Write the box mesh (box_tets); groups maps each box face X0 ... Z1 to
    the physical surface (patch) it joins (default: its own name).
    Returns (number of points, number of tets)."""
    points, tets = box_tets(counts, lower, upper)
    faces = boundary_triangles(tets, points, lower=lower, upper=upper)
    groups = groups or {}
    tris = {}
    for face_name, triangles in faces.items():
        name = groups.get(face_name, face_name)
        tris[name] = np.concatenate([tris[name], triangles]) \
            if name in tris else triangles
    patches = list(tris)
    names = patches + [volume]
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames",
             str(len(names))]
    for tag, name in enumerate(names, start=1):
        dim = 3 if name == volume else 2
        lines.append('%d %d "%s"' % (dim, tag, name))
    lines += ["$EndPhysicalNames", "$Nodes", str(len(points))]
    lines += ["%d %s %s %s" % (i + 1, repr(x), repr(y), repr(z))
              for i, (x, y, z) in enumerate(points.tolist())]
    lines += ["$EndNodes", "$Elements"]
    elements = []
    # element: id type ntags physical elementary nodes (1-based)
    for tag, name in enumerate(patches, start=1):
        for tri in tris[name] + 1:
            elements.append("2 2 %d %d %d %d %d" % (tag, tag, *tri))
    vol_tag = len(names)
    for tet in tets + 1:
        elements.append("4 2 %d %d %d %d %d %d" % (vol_tag, vol_tag, *tet))
    lines.append(str(len(elements)))
    lines += ["%d %s" % (i + 1, e) for i, e in enumerate(elements)]
    lines.append("$EndElements")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return len(points), len(tets)
