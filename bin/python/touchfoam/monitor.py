"""Read the solidMonitor function object's output.

postProcessing/<name>/<startTime>/solidMonitor.dat holds whitespace columns
    # Time  px py pz  Lx Ly Lz  kineticEnergy strainEnergy totalEnergy
(p: total linear momentum, L: angular momentum about the origin from the
current positions).  A restarted run adds a folder per start time; the
folders are joined, a later start replacing the rows it overlaps.
"""

import glob
import os

import numpy as np

COLUMNS = ["Time", "px", "py", "pz", "Lx", "Ly", "Lz",
           "kineticEnergy", "strainEnergy", "totalEnergy"]


def _read_one(path):
    names = None
    rows = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            if line.startswith("#"):
                # The last comment line carries the column names
                names = line.lstrip("#").split()
                continue
            rows.append([float(x) for x in line.split()])
    if not rows:
        return names or COLUMNS, np.zeros((0, len(names or COLUMNS)))
    data = np.array(rows)
    if not names or len(names) != data.shape[1]:
        if data.shape[1] != len(COLUMNS):
            raise ValueError("%s: %d columns and no matching header"
                             % (path, data.shape[1]))
        names = COLUMNS
    return names, data


def read_monitor(case, name="solidMonitor", file_name="solidMonitor.dat"):
    """Monitor columns as {column name: array}, sorted by time.

    Also gives 'p' and 'L' as (n, 3) arrays.
    """
    pattern = os.path.join(case, "postProcessing", name, "*", file_name)
    paths = glob.glob(pattern)
    if not paths:
        raise FileNotFoundError("no monitor output %s" % pattern)

    def start_time(p):
        try:
            return float(os.path.basename(os.path.dirname(p)))
        except ValueError:
            return 0.0

    names, data = None, None
    for path in sorted(paths, key=start_time):
        n, d = _read_one(path)
        if data is None:
            names, data = n, d
            continue
        if n != names:
            raise ValueError("%s: columns differ from the first file" % path)
        if len(d):
            data = data[data[:, 0] < d[0, 0]]
        data = np.vstack([data, d])
    out = {key: data[:, i] for i, key in enumerate(names)}
    if all(k in out for k in ("px", "py", "pz")):
        out["p"] = data[:, [names.index(k) for k in ("px", "py", "pz")]]
    if all(k in out for k in ("Lx", "Ly", "Lz")):
        out["L"] = data[:, [names.index(k) for k in ("Lx", "Ly", "Lz")]]
    return out
