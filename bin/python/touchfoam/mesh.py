"""Read constant/polyMesh (ASCII) and compute the geometry OpenFOAM uses.

Cell centres and volumes are computed with the algorithm of v1912's
primitiveMesh::makeFaceCentresAndAreas and makeCellCentresAndVols (face
triangles about the face-point average, cell pyramids about the
face-centre average), so they match mesh.C() and mesh.V() to round-off for
any cell shape.  Computing them here rather than with
'postProcess -func writeCellCentres' needs no OpenFOAM run, leaves the
time folders alone and works on a processor folder as well.
"""

import os
import re

import numpy as np

from .foamfile import (FoamFileError, _check_ascii, _matching, parse_list,
                       read_header, read_text, strip_comments)


def _read_list_file(path, ncomp, dtype=float):
    text = read_text(path)
    header = read_header(text)
    _check_ascii(header, path)
    body = strip_comments(text)
    m = re.search(r"\bFoamFile\s*\{", body)
    pos = _matching(body, m.end() - 1, "{", "}") + 1 if m else 0
    values, _ = parse_list(body, pos, ncomp, dtype)
    return header, values


def read_points(path):
    return _read_list_file(path, 3)[1]


def read_labels(path):
    return _read_list_file(path, 1, np.int64)[1]


def read_faces(path):
    """Faces as a list of integer arrays (faceList or faceCompactList)."""
    text = read_text(path)
    header = read_header(text)
    _check_ascii(header, path)
    body = strip_comments(text)
    m = re.search(r"\bFoamFile\s*\{", body)
    pos = _matching(body, m.end() - 1, "{", "}") + 1 if m else 0
    if header.get("class") == "faceCompactList":
        offsets, end = parse_list(body, pos, 1, np.int64)
        labels, _ = parse_list(body, end, 1, np.int64)
        return [labels[offsets[i]:offsets[i + 1]]
                for i in range(len(offsets) - 1)]
    m = re.compile(r"\s*(\d+)\s*\(").match(body, pos)
    if not m:
        raise FoamFileError("%s: no face list" % path)
    nfaces = int(m.group(1))
    close = body.rindex(")")
    faces = [np.array(f.split(), dtype=np.int64)
             for f in re.findall(r"\d+\s*\(([^)]*)\)", body[m.end():close])]
    if len(faces) != nfaces:
        raise FoamFileError(
            "%s: %d faces announced, %d read" % (path, nfaces, len(faces)))
    return faces


def read_boundary(path):
    """Patches of a polyMesh/boundary file: list of dicts in file order.

    Each dict has name, type, nFaces, startFace (ints) and any other entry
    as text (e.g. neighbProcNo for processor patches).
    """
    body = strip_comments(read_text(path))
    m = re.search(r"\bFoamFile\s*\{", body)
    pos = _matching(body, m.end() - 1, "{", "}") + 1 if m else 0
    lm = re.compile(r"\s*(\d+)\s*\(").match(body, pos)
    if not lm:
        raise FoamFileError("%s: no patch list" % path)
    patches = []
    entry = re.compile(r"\s*([^\s{}()]+)\s*\{")
    pos = lm.end()
    while True:
        em = entry.match(body, pos)
        if not em:
            break
        close = _matching(body, em.end() - 1, "{", "}")
        patch = {"name": em.group(1)}
        for key, value in re.findall(r"(\w+)\s+([^;]*);",
                                     body[em.end():close]):
            patch[key] = value.strip()
        for key in ("nFaces", "startFace"):
            patch[key] = int(patch[key])
        patches.append(patch)
        pos = close + 1
    if len(patches) != int(lm.group(1)):
        raise FoamFileError("%s: patch count mismatch" % path)
    return patches


def polymesh_dir(case, processor=None, region=""):
    """The polyMesh folder of a case (or of its processor folder)."""
    root = case if processor is None else os.path.join(
        case, "processor%d" % processor)
    return os.path.join(root, "constant", region, "polyMesh")


class PolyMesh:
    """An OpenFOAM polyMesh read from a case.

    points (nPoints, 3), faces (list of arrays), owner, neighbour,
    patches (list of dicts: name, type, nFaces, startFace, ...).
    Geometry (lazy): face_centres, face_areas, cell_centres, cell_volumes.
    """

    def __init__(self, case, processor=None):
        d = polymesh_dir(case, processor)
        if not os.path.isdir(d):
            raise FoamFileError("no mesh in %s (run blockMesh first?)" % d)
        self.points = read_points(os.path.join(d, "points"))
        self.faces = read_faces(os.path.join(d, "faces"))
        self.owner = read_labels(os.path.join(d, "owner"))
        self.neighbour = read_labels(os.path.join(d, "neighbour"))
        self.patches = read_boundary(os.path.join(d, "boundary"))
        self.n_cells = int(max(self.owner.max(),
                               self.neighbour.max(initial=-1)) + 1)
        self._geometry = None

    @property
    def n_internal_faces(self):
        return len(self.neighbour)

    def patch(self, name):
        for p in self.patches:
            if p["name"] == name:
                return p
        raise KeyError("no patch %r (patches: %s)"
                       % (name, [p["name"] for p in self.patches]))

    def patch_faces(self, name):
        p = self.patch(name)
        return range(p["startFace"], p["startFace"] + p["nFaces"])

    def patch_points(self, name):
        """Sorted unique point labels of a patch."""
        faces = [self.faces[f] for f in self.patch_faces(name)]
        if not faces:
            return np.zeros(0, dtype=np.int64)
        return np.unique(np.concatenate(faces))

    # -- geometry ---------------------------------------------------------

    def _geometry_item(self, i):
        """Face centres, face areas, cell centres, cell volumes (0..3),
        computed together on first use."""
        if self._geometry is None:
            fc, fa = face_centres_and_areas(self.points, self.faces)
            cc, cv = cell_centres_and_volumes(
                fc, fa, self.owner, self.neighbour, self.n_cells)
            self._geometry = (fc, fa, cc, cv)
        return self._geometry[i]

    face_centres = property(lambda self: self._geometry_item(0))
    face_areas = property(lambda self: self._geometry_item(1))
    cell_centres = property(lambda self: self._geometry_item(2))
    cell_volumes = property(lambda self: self._geometry_item(3))


def face_centres_and_areas(points, faces):
    """Face centres and area vectors, as primitiveMesh computes them."""
    nf = len(faces)
    centres = np.zeros((nf, 3))
    areas = np.zeros((nf, 3))
    sizes = np.array([len(f) for f in faces])
    for k in np.unique(sizes):
        idx = np.nonzero(sizes == k)[0]
        pts = points[np.array([faces[i] for i in idx])]  # (n, k, 3)
        if k == 3:
            centres[idx] = (1.0 / 3.0) * (pts[:, 0] + pts[:, 1] + pts[:, 2])
            areas[idx] = 0.5 * np.cross(pts[:, 1] - pts[:, 0],
                                        pts[:, 2] - pts[:, 0])
            continue
        # Sum in the same order as OpenFOAM (point by point) so that the
        # round-off is the same too
        fcentre = pts[:, 0].copy()
        for j in range(1, k):
            fcentre += pts[:, j]
        fcentre /= k
        sum_n = np.zeros((len(idx), 3))
        sum_a = np.zeros(len(idx))
        sum_ac = np.zeros((len(idx), 3))
        for j in range(k):
            this_p = pts[:, j]
            next_p = pts[:, (j + 1) % k]
            c = this_p + next_p + fcentre
            n = np.cross(next_p - this_p, fcentre - this_p)
            a = np.sqrt((n * n).sum(axis=1))
            sum_n += n
            sum_a += a
            sum_ac += a[:, None] * c
        tiny = sum_a < 1e-150   # ROOTVSMALL: degenerate faces
        sum_a[tiny] = 1.0
        centres[idx] = (1.0 / 3.0) * sum_ac / sum_a[:, None]
        areas[idx] = 0.5 * sum_n
        centres[idx[tiny]] = fcentre[tiny]
        areas[idx[tiny]] = 0.0
    return centres, areas


def _cell_sum(cells, values, n):
    """sum over entries of values (n_entries, 3) grouped by cell label."""
    if values.ndim == 1:
        return np.bincount(cells, weights=values, minlength=n)
    return np.stack([np.bincount(cells, weights=values[:, d], minlength=n)
                     for d in range(values.shape[1])], axis=1)


def cell_centres_and_volumes(fc, fa, owner, neighbour, n_cells):
    """Cell centres and volumes, as primitiveMesh computes them."""
    nint = len(neighbour)
    cells = np.concatenate([owner, neighbour])
    fidx = np.concatenate([np.arange(len(owner)), np.arange(nint)])
    count = np.bincount(cells, minlength=n_cells)
    c_est = _cell_sum(cells, fc[fidx], n_cells) / count[:, None]

    # 3 x pyramid volume: positive for the owner, flipped for the neighbour
    sign = np.concatenate([np.ones(len(owner)), -np.ones(nint)])
    pyr3 = sign * (fa[fidx] * (fc[fidx] - c_est[cells])).sum(axis=1)
    pc = 0.75 * fc[fidx] + 0.25 * c_est[cells]
    centres = _cell_sum(cells, pyr3[:, None] * pc, n_cells)
    vols = _cell_sum(cells, pyr3, n_cells)
    ok = np.abs(vols) > 1e-300
    centres[ok] /= vols[ok, None]
    centres[~ok] = c_est[~ok]
    return centres, vols * (1.0 / 3.0)


def processor_count(case):
    """Number of processor* folders of a decomposed case (0 if none)."""
    n = 0
    while os.path.isdir(os.path.join(case, "processor%d" % n)):
        n += 1
    return n


def split_count(case, nprocs, patch):
    """Number of a decomposed case's processors holding faces of patch."""
    count = 0
    for proc in range(nprocs):
        for p in PolyMesh(case, processor=proc).patches:
            if p["name"] == patch and p["nFaces"] > 0:
                count += 1
    return count
