#!/usr/bin/python3
"""Every dictionary entry touchFoam reads is declared once, and the
documentation is generated from the declarations.

    /usr/bin/python3 test/cases/entryDeclarations.py

  - `touchFoam -listEntries` runs without a case and lists every declared
    entry; each required one shows an example, each optional one its
    default;
  - doc/entries.md is `touchFoam -listEntries -markdown` to the byte (a
    stale page fails: regenerate it with that command);
  - the sources (src/, applications/solvers/) read no dictionary entry by a
    literal keyword outside the declarations: every `get<T>("key")`,
    `getOrDefault`, `readIfPresent`, `lookup`, `found("key")`,
    `subDict("key")`, `Function1::New("key", ...)` names a declared entry or
    one of the few structural keywords listed below with the reason;
    a control proves the scan finds such a read;
  - every declaration object is used (read through, or its name() taken):
    a declaration nobody reads would document an entry that does nothing;
  - the declared keywords appear in the list: removing one from the source
    (and reading the key directly) makes this test fail twice over.
"""

import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import testing  # noqa: E402

NAME = "entryDeclarations"
TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PAGE = os.path.join(TOP, "doc", "entries.md")

# Literal keys read outside the declarations, and why they need none
STRUCTURAL = {
    "TOUCH": "the sub-dictionary of system/fvSolution that holds the"
             " declared solver controls",
    "type": "OpenFOAM's patch field type, named in an error message",
    "value": "OpenFOAM's patch field value entry",
    "boundaryField": "OpenFOAM's field file structure: the patch"
                     " conditions, checked to be solid ones before"
                     " OpenFOAM reads the field",
    "outOfBounds": "a Function1 table's own coefficient (OpenFOAM's),"
                   " read again to integrate the wall's table",
    "interpolationScheme": "a Function1 table's own coefficient"
                           " (OpenFOAM's), as above",
    "writeControl": "OpenFOAM's Time control in system/controlDict, read"
                    " again so that touchFoam lands its steps on the write"
                    " times counted from t = 0",
    "writeInterval": "OpenFOAM's Time control, as above",
    "listEntries": "a command-line option, not a dictionary entry",
    "markdown": "a command-line option, not a dictionary entry",
}

READ = re.compile(
    r"\.(get|getOrDefault|lookupOrDefault|getCheck|readIfPresent|lookup|"
    r"found|subDict|isDict|subOrEmptyDict)\s*(<[^>]*>)?\s*\(\s*\"(\w+)\""
    r"|Function1\s*<[^>]*>\s*::\s*New\s*\(\s*(?:[^,()]+,\s*)?\"(\w+)\"")
DECLARED = re.compile(
    r"static const (?:declaredEntry\s*<[^>]*>|describedEntry)\s+(\w+)\s*\(")
#: (file, key) of reads from files OpenFOAM writes itself, not the user:
#: the last step's deltaT from a restart's uniform/time
SKIP_READ = {(os.path.join("applications", "solvers", "touchFoam",
                           "touchFoam.C"), "deltaT")}


def sources():
    for top in ("src", os.path.join("applications", "solvers")):
        for root, dirs, files in os.walk(os.path.join(TOP, top)):
            dirs[:] = [d for d in dirs
                       if d != "lnInclude" and not d.startswith("linux64")]
            for name in files:
                if name.endswith((".C", ".H")):
                    yield os.path.join(root, name)


def literal_reads(path, text):
    """(file:line, key) of every dictionary read by a literal keyword."""
    reads = []
    for number, line in enumerate(text.split("\n"), 1):
        code = line.split("//")[0]
        for match in READ.finditer(code):
            key = match.group(3) or match.group(4)
            reads.append(("%s:%d" % (os.path.relpath(path, TOP), number),
                          key))
    return reads


def listed_entries(text):
    """The keywords of `touchFoam -listEntries`, by place."""
    entries, where = [], None
    for line in text.split("\n"):
        if line and not line.startswith(" "):
            where = line.strip()
        elif line.startswith("    ") and not line.startswith("        "):
            entries.append((where, line.split()[0], line))
    return entries


def body():
    failures, lines = [], []

    # Outside any case (PWD matching the folder: OpenFOAM warns otherwise)
    env = dict(os.environ, PWD=TOP)
    listing = subprocess.run(["touchFoam", "-listEntries"], cwd=TOP,
                             env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
    if listing.returncode != 0:
        raise AssertionError("touchFoam -listEntries failed outside a case:"
                             "\n" + listing.stdout[-2000:])
    entries = listed_entries(listing.stdout)
    keys = {key for _, key, _ in entries}
    for where, key, line in entries:
        if "default:" not in line and "required (example:" not in line:
            failures.append("%s %s shows neither a default nor an example"
                            % (where, key))
    lines.append("-listEntries: %d entries in %d places" % (
        len(entries), len({w for w, _, _ in entries})))

    markdown = subprocess.run(["touchFoam", "-listEntries", "-markdown"],
                              cwd=TOP, env=env, stdout=subprocess.PIPE,
                              text=True)
    page = open(PAGE).read() if os.path.exists(PAGE) else ""
    if markdown.stdout != page:
        failures.append("doc/entries.md is not `touchFoam -listEntries"
                        " -markdown` (regenerate it)")
    rows = [r for r in page.split("\n") if r.startswith("| `")]
    if len(rows) != len(entries):
        failures.append("doc/entries.md has %d rows for %d entries"
                        % (len(rows), len(entries)))
    lines.append("doc/entries.md: %d rows, %s" % (
        len(rows), "current" if markdown.stdout == page else "STALE"))

    # The sources: literal reads outside declarations, unused declarations
    undeclared, unused, declarations = [], [], 0
    for path in sources():
        text = open(path).read()
        for where, key in literal_reads(path, text):
            if key in keys or key in STRUCTURAL \
                    or (os.path.relpath(path, TOP), key) in SKIP_READ:
                continue
            undeclared.append("%s reads '%s'" % (where, key))
        # (the entries classes' own headers show declarations as examples)
        in_entries = os.sep + "entries" + os.sep in path
        for match in ([] if in_entries else DECLARED.finditer(text)):
            declarations += 1
            name = match.group(1)
            if not re.search(r"\b%s\s*\.\s*(read|name)\s*\(" % name, text):
                unused.append("%s: %s" % (os.path.relpath(path, TOP), name))
    if undeclared:
        failures.append("entries read by a literal keyword without a"
                        " declaration: " + "; ".join(undeclared))
    if unused:
        failures.append("declarations nobody reads: " + ", ".join(unused))
    if declarations != len(entries):
        failures.append("%d declarations in the sources, %d listed"
                        % (declarations, len(entries)))
    lines.append("sources: %d declarations, %d undeclared literal reads,"
                 " %d unused declarations" % (declarations, len(undeclared),
                                               len(unused)))

    # Control: the scan finds a read that bypasses the declarations
    control = ('    const scalar CFL = controls.get<scalar>("CFL");\n'
               '    const word w(dict.getOrDefault<word>("undeclaredKey",'
               ' "x"));\n'
               '    auto f = Function1<vector>::New("wallSpeed", dict);\n')
    found = [key for _, key in literal_reads(os.path.join(TOP, "control.C"),
                                             control)]
    if found != ["CFL", "undeclaredKey", "wallSpeed"]:
        failures.append("the scan's control found %s" % found)
    flagged = [k for k in found if k not in keys and k not in STRUCTURAL]
    if flagged != ["undeclaredKey", "wallSpeed"]:
        failures.append("the control's undeclared reads were not flagged:"
                        " %s" % flagged)
    lines.append("control: a raw read of %s flagged" % ", ".join(flagged))

    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
