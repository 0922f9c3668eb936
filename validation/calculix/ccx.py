"""CalculiX side of the comparison: decks, timed runs, output readers.

The decks come from the CalculiX peer's deck generators, a folder outside
this project named by $CALCULIX_PEER, called as programs; everything read
back from CalculiX's files is read here:

    peer_dir         the generators' folder, checked
    column_deck      gen_column.py: n x 6n x n twisting column to t_end
    cube_deck        gen_cube.py: N^3 swinging cube to 0.004 s, plus an
                     element print of the stresses at the last increment
    version          'CalculiX 2.20', from ccx -v
    timed            run a command, return wall and CPU time of the process
    read_inp         node coordinates and element connectivity of a deck
    read_dat         the node and element prints of a .dat file
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

PYTHON = run.PYTHON
#: one thread: OpenMP and CalculiX's own per-task counts
ONE_THREAD = {"OMP_NUM_THREADS": "1", "CCX_NPROC_STIFFNESS": "1",
              "CCX_NPROC_RESULTS": "1", "CCX_NPROC_EQUATION_SOLVER": "1",
              "MKL_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}
#: material and motion the peer's generators write (their docstrings);
#: compared with the tutorials' by the driver
COLUMN_PEER = {"E": 17e6, "rho": 1100.0, "Omega": 105.0, "L": 6.0}
CUBE_PEER = {"E": 1.7e7, "nu": 0.3, "rho": 1100.0, "U0": 5e-4}


def peer_dir():
    """The folder of the peer's deck generators, $CALCULIX_PEER."""
    path = os.environ.get("CALCULIX_PEER", "")
    if not path:
        raise run.RunError("set CALCULIX_PEER to the folder of the CalculiX"
                           " deck generators (gen_column.py, gen_cube.py)")
    path = os.path.abspath(path)
    for name in ("gen_column.py", "gen_cube.py"):
        if not os.path.isfile(os.path.join(path, name)):
            raise run.RunError("CalculiX deck generator %s not found in %s "
                               "($CALCULIX_PEER)" % (name, path))
    return path


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


def _generate(script, args, folder, env=None):
    os.makedirs(folder, exist_ok=True)
    cmd = [PYTHON, os.path.join(peer_dir(), script)] + [str(a) for a in args]
    run.run(cmd, folder, "generate", env=env)


def column_deck(folder, job, n, element, nu, t_end):
    """Deck of the n x 6n x n column, one explicit step to t_end.

    One step: the increment is CalculiX's initial estimate for the whole
    run (the peer's run_A1.sh, which ends at 0.3 s; t_end = 0.1 here).
    DTOUT = t_end asks for output only at the end: the generator turns it
    into an output frequency in increments, and the last increment of a
    step is always written (peer README, note 3).
    """
    _generate("gen_column.py", [job, n, 6 * n, n, element, nu, t_end,
                                "explicit", "-", t_end], folder,
              env={"DTOUT": repr(t_end)})
    return os.path.join(folder, job + ".inp")


def cube_deck(folder, job, n, element, t_end=0.004):
    """Deck of the N^3 cube (explicit, CalculiX's increment), with the
    integration-point stresses printed at the last increment."""
    _generate("gen_cube.py", [job, n, element, "explicit", "-", t_end],
              folder)
    path = os.path.join(folder, job + ".inp")
    with open(path) as f:
        text = f.read()
    if text.count("*END STEP") != 1:
        raise ValueError("%s: expected one *END STEP" % path)
    text = text.replace("*END STEP", "*EL PRINT, ELSET=EALL, "
                        "FREQUENCY=100000000\nS\n*END STEP")
    with open(path, "w") as f:
        f.write(text)
    return path


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


_DAT_HEADER = re.compile(r"^\s*(\S.*?)\s+for set\s+(\S+)\s+and time\s+(\S+)")


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
