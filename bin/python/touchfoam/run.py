"""Run OpenFOAM programs on cases, copy cases, set case options.

Every command writes its output to <case>/log.<name>; a failure raises
RunError whose message ends with the tail of that log, so a test or a
validation script reports why it stopped without anyone opening files.
"""

import os
import re
import shutil
import subprocess
import sys

from .foamfile import header_text

#: Debian's interpreter, which has numpy (the default python3 may not)
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") \
    else sys.executable


class RunError(RuntimeError):
    pass


def log_tail(path, lines=30):
    try:
        with open(path, errors="replace") as f:
            return "".join(f.readlines()[-lines:])
    except OSError:
        return "(no log %s)" % path


def run(cmd, case, name=None, env=None, tail=30, timeout=None):
    """Run cmd (list) in folder case, output to case/log.<name>.

    name defaults to the program's base name.  Returns the log path.
    Raises RunError with the log tail on a non-zero exit status.
    """
    name = name or os.path.basename(cmd[0])
    log = os.path.join(case, "log." + name)
    full_env = dict(os.environ)
    full_env["PWD"] = os.path.abspath(case)   # OpenFOAM warns otherwise
    if env:
        full_env.update(env)
    with open(log, "w") as f:
        try:
            rc = subprocess.call(cmd, cwd=case, stdout=f,
                                 stderr=subprocess.STDOUT, env=full_env,
                                 stdin=subprocess.DEVNULL, timeout=timeout)
        except FileNotFoundError:
            raise RunError("%s: command not found (source etc/bashrc?)"
                           % cmd[0])
        except subprocess.TimeoutExpired:
            raise RunError("%s timed out after %s s in %s\n--- %s:\n%s"
                           % (" ".join(cmd), timeout, case, log,
                              log_tail(log, tail)))
    if rc != 0:
        raise RunError("%s failed (exit %d%s) in %s\n--- tail of %s:\n%s"
                       % (" ".join(cmd), rc, _last_time(log), case, log,
                          log_tail(log, tail)))
    return log


def _last_time(log):
    """', at Time = t' from the last time line of a solver log, or ''."""
    last = ""
    try:
        with open(log, errors="replace") as f:
            for line in f:
                if line.startswith("Time = "):
                    last = line.split()[2]
    except OSError:
        pass
    return ", at Time = %s" % last if last else ""


def mpirun(np_, app_args):
    """mpirun command line for np_ ranks of app_args (list).

    Root needs --allow-run-as-root; more ranks than cores need
    --oversubscribe.
    """
    cmd = ["mpirun", "-np", str(np_)]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    if np_ > (os.cpu_count() or 1):
        cmd.append("--oversubscribe")
    return cmd + list(app_args) + ["-parallel"]


def run_parallel(app_args, case, np_, name=None, **kw):
    name = name or os.path.basename(app_args[0])
    return run(mpirun(np_, app_args), case, name, **kw)


# -- cases ----------------------------------------------------------------

_OUTPUT_RE = re.compile(
    r"^(0|processor\d+|postProcessing|VTK|log\..*|.*\.foam|.*\.msh|"
    r"[-+]?\d*\.?\d+([eE][-+]?\d+)?)$")


def _ignore_outputs(folder, names):
    """copytree filter: leave out results and generated files of a case."""
    ignored = [n for n in names if _OUTPUT_RE.match(n)]
    if os.path.basename(folder) == "polyMesh":
        ignored += [n for n in names if n != "blockMeshDict"]
    return ignored


def copy_case(src, dst):
    """Fresh copy of a tutorial's set-up (no results, no mesh) at dst."""
    if os.path.exists(dst):
        shutil.rmtree(dst)
    shutil.copytree(src, dst, ignore=_ignore_outputs)
    return dst


def restore0(case):
    """0/ from 0.orig/ (what RunFunctions' restore0Dir does)."""
    zero = os.path.join(case, "0")
    if os.path.exists(zero):
        shutil.rmtree(zero)
    shutil.copytree(os.path.join(case, "0.orig"), zero)


def write_options(case, relpath, entries, comment=None):
    """Write (or, with no entries, remove) an options file of a case.

    The tutorial dictionaries end with '#includeIfPresent "<file>"', so
    entries written here override the defaults without editing the files
    under version control.  entries: {keyword: value or sub-dict}.
    """
    path = os.path.join(case, relpath)
    if not entries:
        if os.path.exists(path):
            os.remove(path)
        return path
    lines = [header_text("dictionary", os.path.basename(path),
                         os.path.dirname(relpath))]
    if comment:
        lines.append("// %s\n\n" % comment)
    lines.extend(_entries_text(entries))
    with open(path, "w") as f:
        f.write("".join(lines))
    return path


def _entries_text(entries, indent=""):
    """'key value;' lines; a dict value becomes a sub-dictionary."""
    lines = []
    for key, value in entries.items():
        if isinstance(value, dict):
            lines.append("%s%s\n%s{\n" % (indent, key, indent))
            lines.extend(_entries_text(value, indent + "    "))
            lines.append("%s}\n" % indent)
        else:
            lines.append("%s%-15s %s;\n" % (indent, key, value))
    return lines


def foam_set(case, relpath, entry, value):
    """Set (or add: -set does both) a dictionary entry with foamDictionary.

    entry uses '/' for sub-dictionaries, e.g. 'TOUCH/reconstruction'.
    Used on run copies only: foamDictionary rewrites the whole file.
    """
    run(["foamDictionary", relpath, "-entry", entry, "-set", str(value)],
        case, "foamDictionary")


def time_dirs(case):
    """{time value: folder name} of the time folders of a case."""
    times = {}
    for name in os.listdir(case):
        if os.path.isdir(os.path.join(case, name)):
            try:
                times[float(name)] = name
            except ValueError:
                pass
    return times


def time_dir(case, t, tol=1e-9):
    """Folder of the time nearest t; error if none within tol."""
    times = time_dirs(case)
    if not times:
        raise RunError("%s has no time folders" % case)
    best = min(times, key=lambda x: abs(x - t))
    if abs(best - t) > tol * max(1.0, abs(t)):
        raise RunError("%s: no time folder at t = %g (nearest %s)"
                       % (case, t, times[best]))
    return os.path.join(case, times[best])


def latest_time_dir(case):
    times = time_dirs(case)
    if not times:
        raise RunError("%s has no time folders" % case)
    return os.path.join(case, times[max(times)])


def project_dir():
    """The repository root (this file is bin/python/touchfoam/run.py)."""
    return os.path.abspath(os.path.join(os.path.dirname(__file__),
                                        "..", "..", ".."))


def tutorial_dir(name):
    return os.path.join(project_dir(), "tutorials", name)


def check_openfoam():
    """Raise a clear error when the OpenFOAM environment is missing."""
    if shutil.which("blockMesh") is None:
        raise RunError("OpenFOAM is not in the PATH: "
                       "source %s/etc/bashrc" % project_dir())


def have_solver():
    return shutil.which("touchFoam") is not None
