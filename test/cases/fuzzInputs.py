#!/usr/bin/python3
"""Random mutations of a valid tiny case end in a clear error or a run,
never in a signal or a hang, and never in a quiet run on an out-of-range
value.

    /usr/bin/python3 test/cases/fuzzInputs.py [-n 300] [-seed 31]

The base case is the swinging cube at 2 x 2 x 2 cells, 2 steps
(maxSteps 2), written at its end.  Each mutation changes one thing in one
of system/fvSolution, constant/mechanicalProperties, system/controlDict,
0/U and 0/F (the seeded random generator picks): a number made negative,
zero, 1e6 or 1e-6 times itself, 1e300 or a word; a word made a number or
misspelt; an entry deleted or duplicated; a keyword misspelt; a ';' or
a '}' removed; the file truncated at a random character.  touchFoam runs
on each with a timeout of 60 s.  Outcomes:
  refused  exit status 1 and a FOAM FATAL (IO) ERROR in the log
  warned   exit status 0 and a FOAM Warning
  ran      exit status 0, no warning (the mutation was harmless)
  signal   a negative status, > 128, or a stack trace (printStack)
  hang     the timeout expired
  quiet    a ran whose mutation put a declared entry out of its declared
           range (from touchFoam -listEntries)
  other    any other exit status
The test fails on any signal, hang, quiet or other, and reports the count
of each outcome.  The default is 300 mutations at seed 31 (-n, -seed for
more).  Work folders: test/runs/fuzzInputs/ (the failing mutations are
kept, the others removed).
"""

import argparse
import os
import random
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, testing  # noqa: E402

NAME = "fuzzInputs"
FILES = ["system/fvSolution", "constant/mechanicalProperties",
         "system/controlDict", "0/U", "0/F"]
TIMEOUT = 60
NUMBER = re.compile(r"(?<![\w.])-?\d+\.?\d*(?:[eE][-+]?\d+)?(?![\w.])")
WORD_VALUE = re.compile(r"^(\s*)(\w+)(\s+)([A-Za-z]\w*)(\s*;)", re.M)
ENTRY = re.compile(r"^[ \t]*\w+[ \t]+[^;{}\n]*;[ \t]*\n", re.M)
KEY = re.compile(r"^([ \t]*)([A-Za-z]\w*)(?=[ \t]+[^\n]*;)", re.M)


def body_start(text):
    """Mutations leave the FoamFile header alone"""
    m = re.search(r"FoamFile\s*\{[^}]*\}", text)
    return m.end() if m else 0


def declared_ranges():
    """{entry name: python expression of its range} from -listEntries"""
    out = subprocess.run(["touchFoam", "-listEntries"], capture_output=True,
                         text=True).stdout
    ranges = {}
    for line in out.splitlines():
        m = re.match(r"^    (\w+)\s+\[.*valid: (.*)$", line)
        if m and re.search(r"[<>]", m.group(2)):
            ranges[m.group(1)] = m.group(2).strip()
    return ranges


def in_range(expression, name, value):
    try:
        return eval(expression.replace(name, repr(value)), {})
    except Exception:
        return True


def mutate(text, rng):
    """One mutation of text: (new text, description, (entry, value) when a
    declared entry got a number)"""
    start = body_start(text)
    kinds = ["number", "number", "number", "word", "delete", "duplicate",
             "keyword", "semicolon", "brace", "truncate"]
    for _ in range(20):
        kind = rng.choice(kinds)
        if kind == "number":
            # Values only, not numbers in comments
            found = [m for m in NUMBER.finditer(text, start)
                     if "//" not in text[text.rfind("\n", 0, m.start()):
                                          m.start()]]
            if not found:
                continue
            m = rng.choice(found)
            old = float(m.group())
            new = rng.choice([-old if old else -1.0, 0.0, old*1e6, old*1e-6,
                              1e300, "abc", rng.randint(-3, 3)])
            line_start = text.rfind("\n", 0, m.start()) + 1
            key = re.match(r"\s*(\w+)", text[line_start:m.start()])
            entry = (key.group(1), new) if key and \
                not isinstance(new, str) else None
            return (text[:m.start()] + str(new) + text[m.end():],
                    "number %s -> %s at %d" % (m.group(), new, m.start()),
                    entry)
        if kind == "word":
            found = [m for m in WORD_VALUE.finditer(text, start)]
            if not found:
                continue
            m = rng.choice(found)
            value = m.group(4)
            new = rng.choice([value[:-1], value + "x", "1", "(1 2 3)"])
            return (text[:m.start(4)] + new + text[m.end(4):],
                    "word %s %s -> %s" % (m.group(2), value, new), None)
        if kind in ("delete", "duplicate"):
            found = [m for m in ENTRY.finditer(text, start)]
            if not found:
                continue
            m = rng.choice(found)
            new = "" if kind == "delete" else m.group() + m.group()
            return (text[:m.start()] + new + text[m.end():],
                    "%s %s" % (kind, m.group().strip()), None)
        if kind == "keyword":
            found = [m for m in KEY.finditer(text, start)]
            if not found:
                continue
            m = rng.choice(found)
            key = m.group(2)
            i = rng.randrange(len(key))
            new = key[:i] + key[i+1:] if len(key) > 1 else key + "x"
            return (text[:m.start(2)] + new + text[m.end(2):],
                    "keyword %s -> %s" % (key, new), None)
        if kind in ("semicolon", "brace"):
            char = ";" if kind == "semicolon" else "}"
            found = [i for i in range(start, len(text)) if text[i] == char]
            if not found:
                continue
            i = rng.choice(found)
            return text[:i] + text[i+1:], "removed %r at %d" % (char, i), None
        if kind == "truncate":
            i = rng.randrange(start, len(text))
            return text[:i], "truncated at %d of %d" % (i, len(text)), None
    return text, "none", None


def outcome(status, log, entry, ranges):
    if status is None:
        return "hang"
    if status < 0 or status > 128 or "printStack" in log \
            or "sigSegv" in log or "sigFpe" in log:
        return "signal"
    if status == 1 and "FOAM FATAL" in log:
        return "refused"
    if status != 0:
        return "other"
    if "FOAM Warning" in log or "--> FOAM Warning" in log:
        return "warned"
    if entry and entry[0] in ranges \
            and not in_range(ranges[entry[0]], entry[0], entry[1]):
        return "quiet"
    return "ran"


def body(args):
    root = testing.work_dir(NAME)
    base = cases.prepare("swingingCube", os.path.join(root, "base"), n=2,
                         touch={"reconstruction": "limitedLinear",
                                "CFL": 0.3},
                         control={"maxSteps": 2, "writeInterval": 1})
    ranges = declared_ranges()
    rng = random.Random(args.seed)
    counts = {}
    warnings = {}
    bad = []
    for i in range(args.n):
        case = os.path.join(root, "m%03d" % i)
        if os.path.exists(case):
            shutil.rmtree(case)
        shutil.copytree(base, case)
        name = rng.choice(FILES)
        path = os.path.join(case, name)
        with open(path) as f:
            text = f.read()
        new, what, entry = mutate(text, rng)
        with open(path, "w") as f:
            f.write(new)
        log = os.path.join(case, "log.touchFoam")
        with open(log, "w") as f:
            try:
                status = subprocess.call(["touchFoam"], cwd=case, stdout=f,
                                         stderr=subprocess.STDOUT,
                                         stdin=subprocess.DEVNULL,
                                         timeout=TIMEOUT,
                                         env=dict(os.environ, PWD=case))
            except subprocess.TimeoutExpired:
                status = None
        with open(log, errors="replace") as f:
            output = f.read()
        result = outcome(status, output, entry, ranges)
        if result == "warned":
            first = re.search(r"FOAM Warning :.*?\n(?:\s+(?:From|in file|"
                              r"Reading)[^\n]*\n)*\s*([^\n]{0,40})",
                              output, re.S)
            key = first.group(1) if first else "?"
            warnings[key] = warnings.get(key, 0) + 1
        counts[result] = counts.get(result, 0) + 1
        if result in ("signal", "hang", "quiet", "other"):
            bad.append("%s %s: %s (status %s, %s)"
                       % (name, what, result, status, case))
        else:
            shutil.rmtree(case)
    summary = "%d mutations at seed %d: %s" % (
        args.n, args.seed, ", ".join("%s %d" % (k, counts.get(k, 0))
                                     for k in ["refused", "warned", "ran",
                                               "signal", "hang", "quiet",
                                               "other"]))
    summary += "; warnings (first words: count): " + "; ".join(
        "%s: %d" % kv for kv in sorted(warnings.items(),
                                       key=lambda kv: -kv[1]))
    if bad:
        raise AssertionError(summary + "; " + "; ".join(bad[:20]))
    return summary


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("-n", type=int, default=300)
    parser.add_argument("-seed", type=int, default=31)
    arguments = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(arguments)))
