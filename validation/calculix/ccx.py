"""CalculiX side of the comparison: decks, timed runs, output readers.

The decks are written by decks.py (this folder); everything read back from
CalculiX's files is read here:

    column_deck      the n x 6n x n twisting column to t_end
    cube_deck        the N^3 swinging cube to 0.004 s, with an element
                     print of the stresses at the last increment
    version          'CalculiX 2.20', from ccx -v
    timed            run a command, return wall and CPU time of the process
    read_inp         node coordinates and element connectivity of a deck
    read_dat         the node and element prints of a .dat file
    read_frd         the node coordinates and the last nodal block of each
                     named result of a .frd file
    increments       increments CalculiX took (the .frd step headers)
    selected_dt      the increment CalculiX chose ('SELECTED time increment')
"""

import os
import re
import resource
import shutil
import subprocess
import time

from touchfoam import run

import decks

PYTHON = run.PYTHON
#: one thread: OpenMP and CalculiX's own per-task counts
ONE_THREAD = {"OMP_NUM_THREADS": "1", "CCX_NPROC_STIFFNESS": "1",
              "CCX_NPROC_RESULTS": "1", "CCX_NPROC_EQUATION_SOLVER": "1",
              "MKL_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}
#: material and motion the decks are written with; compared with the
#: tutorials' by the driver
COLUMN_DECK = decks.COLUMN
CUBE_DECK = decks.CUBE


def check_ccx():
    if shutil.which("ccx") is None:
        raise run.RunError("ccx (CalculiX) is not in the PATH: "
                           "bin/touchSetup --with-calculix installs it")


def version():
    """'CalculiX <version>' from ccx -v, or 'CalculiX (version unknown)'."""
    try:
        out = subprocess.run(["ccx", "-v"], capture_output=True,
                                 text=True, timeout=30).stdout
        for line in out.splitlines():
            if "Version" in line:
                return "CalculiX " + line.split("Version", 1)[1].strip()
    except (OSError, subprocess.SubprocessError):
        pass
    return "CalculiX (version unknown)"


def column_deck(folder, job, n, element, nu, t_end):
    """Deck of the n x 6n x n column, one explicit step to t_end.

    One step: the increment is CalculiX's initial estimate for the whole
    run; the top face's displacements are printed at the step's last
    increment only (decks.py).
    """
    os.makedirs(folder, exist_ok=True)
    return decks.column_deck(os.path.join(folder, job + ".inp"), n, element,
                             nu, t_end)


def cube_deck(folder, job, n, element, t_end=0.004):
    """Deck of the N^3 cube (explicit, CalculiX's increment), with the
    nodes' U and V and the integration-point stresses printed at the last
    increment."""
    os.makedirs(folder, exist_ok=True)
    return decks.cube_deck(os.path.join(folder, job + ".inp"), n, element,
                           t_end)


def timed(cmd, case, name, env=None):
    """Run cmd in case (log.<name>); (wall, cpu) seconds of the process.

    wall is the elapsed time of the whole process; cpu its user + system
    time (getrusage of the children), which contention on a shared
    machine stretches less than wall.
    """
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    run.run(cmd, case, name, env=env)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime
                                                - before.ru_stime)
    return wall, cpu


def run_ccx(folder, job, prefix=()):
    """ccx -i job on one thread (after the command prefix, e.g. nice);
    (wall, cpu).  A '*ERROR' in the log is a failure even when ccx exits
    0."""
    check_ccx()
    wall, cpu = timed(list(prefix) + ["ccx", "-i", job], folder, "ccx",
                      env=ONE_THREAD)
    log = os.path.join(folder, "log.ccx")
    with open(log, errors="replace") as f:
        text = f.read()
    if "*ERROR" in text:
        raise run.RunError("ccx reported an error in %s:\n%s"
                           % (folder, run.log_tail(log)))
    threads = re.findall(r"Using up to (\d+) cpu", text)
    if any(t != "1" for t in threads):
        raise run.RunError("ccx used more than one thread in %s" % folder)
    return wall, cpu


# -- readers ------------------------------------------------------------------

def _keyword_blocks(path):
    """[(keyword line upper-cased, [data lines])] of an .inp file."""
    blocks = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("**"):
                continue
            if line.startswith("*"):
                blocks.append((line.upper(), []))
            elif blocks:
                blocks[-1][1].append(line)
    return blocks


def read_inp(path):
    """({node id: (x, y, z)}, {element id: [node ids]}, {keyword: lines})."""
    nodes, elements, other = {}, {}, {}
    for key, lines in _keyword_blocks(path):
        if key.startswith("*NODE") and not key.startswith("*NODE PRINT") \
                and not key.startswith("*NODE FILE"):
            for line in lines:
                p = line.split(",")
                nodes[int(p[0])] = tuple(float(x) for x in p[1:4])
        elif key.startswith("*ELEMENT"):
            for line in lines:
                p = [x for x in line.split(",") if x.strip()]
                elements[int(p[0])] = [int(x) for x in p[1:]]
        else:
            other.setdefault(key.split(",")[0], []).extend(lines)
    return nodes, elements, other


_DAT_HEADER = re.compile(r"^\s*(\S.*?)\s*for set\s+(\S+)\s+and time\s+(\S+)")


def read_dat(path):
    """[{'label', 'set', 'time', 'rows'}] of the prints in a .dat file.

    label is the first word of the header ('displacements', 'velocities',
    'stresses'); rows are lists of numbers, ids first (node, or element
    and integration point).
    """
    blocks = []
    with open(path) as f:
        for line in f:
            m = _DAT_HEADER.match(line)
            if m:
                blocks.append({"label": m.group(1).split()[0],
                               "set": m.group(2), "time": float(m.group(3)),
                               "rows": []})
            elif blocks and line.strip():
                try:
                    blocks[-1]["rows"].append([float(x)
                                               for x in line.split()])
                except ValueError:
                    pass
    return blocks


def last_block(blocks, label, set_name):
    found = [b for b in blocks if b["label"] == label
             and b["set"] == set_name]
    if not found:
        raise ValueError("no '%s' print for set %s" % (label, set_name))
    return found[-1]


def increments(frd):
    """Increments of a run: the largest increment number of each step's
    result headers ('1PSTEP' lines of the .frd), summed over the steps."""
    last = {}
    with open(frd, errors="replace") as f:
        for line in f:
            if line.startswith("    1PSTEP"):
                p = line.split()
                inc, step = int(p[2]), int(p[3])
                last[step] = max(last.get(step, 0), inc)
    return sum(last.values()) if last else None


def selected_dt(log):
    """CalculiX's increments ('SELECTED time increment') from its log."""
    with open(log, errors="replace") as f:
        return [float(x) for x in re.findall(
            r"SELECTED time increment[^:]*:\s*([0-9.eE+-]+)", f.read())]


def read_frd(path, names):
    """(node coordinates {id: (x, y, z)}, {name: {id: [values]}}) of a .frd
    file: the geometry block ('    2C') and, for each result in names
    ('DISP', 'PE', ...), its last nodal block (' -4  NAME' header, ' -1'
    records: id in columns 4-13, then 12-character values)."""
    nodes, last = {}, {}
    current = None
    with open(path, errors="replace") as f:
        for line in f:
            if line.startswith("    2C"):
                current = nodes
            elif line.startswith(" -4"):
                name = line.split()[1]
                current = {} if name in names else None
                if current is not None:
                    last[name] = current
            elif line.startswith(" -1") and current is not None:
                values = [float(line[c:c + 12])
                          for c in range(13, len(line.rstrip()) - 11, 12)]
                current[int(line[3:13])] = values
            elif line.startswith(" -3"):
                current = None
    return {i: tuple(v[:3]) for i, v in nodes.items()}, last
