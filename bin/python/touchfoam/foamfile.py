"""Read and write OpenFOAM ASCII files: fields, lists and simple dictionaries.

Fields (vol*Field, point*Field, surface*Field) are read into a FoamField
that keeps the text around the internal field verbatim (header,
dimensions, boundaryField), so a template such as 0.orig/F can be given new
internal values and written back with its boundary conditions untouched.

Only the ASCII format is supported; binary files are refused with a clear
message (set 'writeFormat ascii;' in system/controlDict).
"""

import gzip
import os
import re

import numpy as np

#: number of components of each primitive type
NCOMP = {
    "scalar": 1,
    "label": 1,
    "vector": 3,
    "symmTensor": 6,
    "tensor": 9,
    "sphericalTensor": 1,
}

#: field class name -> primitive type ("volVectorField" -> "vector")
_CLASS_RE = re.compile(
    r"^(vol|point|surface|volInternal)(Scalar|Vector|Tensor|SymmTensor|"
    r"SphericalTensor)Field$")

_COMMENT_RE = re.compile(r"/\*.*?\*/|//[^\n]*", re.S)
_NUMBER_RE = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


class FoamFileError(RuntimeError):
    """A file that this module cannot read, with the reason."""


def read_text(path):
    """Text of path, or of path.gz when only the compressed file exists."""
    if not os.path.exists(path) and os.path.exists(path + ".gz"):
        with gzip.open(path + ".gz", "rt") as f:
            return f.read()
    with open(path) as f:
        return f.read()


def strip_comments(text):
    """Text without C and C++ comments (enough for OpenFOAM data files)."""
    return _COMMENT_RE.sub(" ", text)


def _matching(text, start, open_ch, close_ch):
    """Index of the bracket closing the one at text[start]."""
    depth = 0
    for i in range(start, len(text)):
        c = text[i]
        if c == open_ch:
            depth += 1
        elif c == close_ch:
            depth -= 1
            if depth == 0:
                return i
    raise FoamFileError("unbalanced '%s' at offset %d" % (open_ch, start))


def read_header(text):
    """Entries of the FoamFile header as a dict of strings ({} if none)."""
    m = re.search(r"\bFoamFile\s*\{", text)
    if not m:
        return {}
    end = _matching(text, m.end() - 1, "{", "}")
    header = {}
    for key, value in re.findall(r"(\w+)\s+([^;]*);", text[m.end():end]):
        header[key] = value.strip().strip('"')
    return header


def _check_ascii(header, path):
    if header.get("format", "ascii") != "ascii":
        raise FoamFileError(
            "%s is written in '%s' format; only ascii is supported "
            "(set 'writeFormat ascii;' in system/controlDict and re-run, or "
            "convert with 'foamFormatConvert')"
            % (path, header.get("format")))


def primitive_type(field_class):
    """'volTensorField' -> 'tensor'."""
    m = _CLASS_RE.match(field_class)
    if not m:
        raise FoamFileError("not a field class: %r" % field_class)
    t = m.group(2)
    return t[0].lower() + t[1:]


def parse_numbers(body, dtype=float):
    """All numbers of a list body '(1 2 3) (4 5 6)' as a flat array."""
    flat = body.replace("(", " ").replace(")", " ").split()
    try:
        return np.array(flat, dtype=dtype)
    except ValueError as err:
        raise FoamFileError("cannot parse list entries: %s" % err)


def parse_list(text, pos, ncomp, dtype=float):
    """Parse an OpenFOAM list starting at text[pos].

    Accepts 'N ( ... )', 'N{value}' and '( ... )' (size from the contents).
    Returns (array, end) where end is the index after the list; array has
    shape (N,) for ncomp == 1 else (N, ncomp).
    """
    m = re.compile(r"\s*(\d*)\s*([({])").match(text, pos)
    if not m:
        raise FoamFileError("no list at: %r" % text[pos:pos + 60])
    size = int(m.group(1)) if m.group(1) else None
    if m.group(2) == "{":
        # Uniform short form N{value}
        close = _matching(text, m.end() - 1, "{", "}")
        value = parse_numbers(text[m.end():close], dtype)
        arr = np.tile(value, (size, 1)) if ncomp > 1 else np.full(
            size, value[0], dtype=dtype)
        return arr, close + 1
    start = m.end() - 1
    if size == 0 or ncomp == 1:
        close = text.index(")", start + 1)
    else:
        # Entries '(a b c)' do not nest, so the list ends at the first ')'
        # followed by another ')' (a regex is far faster than a char loop).
        end = re.compile(r"\)\s*\)").search(text, start + 1)
        if not end:
            raise FoamFileError("unterminated list at offset %d" % start)
        close = end.end() - 1
    values = parse_numbers(text[start + 1:close], dtype)
    if size is None:
        size = values.size // ncomp
    if values.size != size * ncomp:
        raise FoamFileError(
            "list of %d entries of %d components holds %d numbers"
            % (size, ncomp, values.size))
    if ncomp > 1:
        values = values.reshape(size, ncomp)
    return values, close + 1


def format_value(value):
    """Full-precision ASCII of a scalar or a 1-D sequence: '1.5' or '(1 2 3)'.

    repr() of a Python float is the shortest string that reads back to the
    same double, so nothing is lost in a round trip.
    """
    if np.ndim(value) == 0:
        return repr(float(value))
    return "(" + " ".join(repr(float(v)) for v in value) + ")"


class FoamField:
    """An ASCII OpenFOAM field file.

    Attributes
        header      dict of the FoamFile entries (class, object, ...)
        type        primitive type: scalar, vector, symmTensor, tensor
        uniform     True when the internal field is 'uniform value'
        values      internal values, shape (n,) or (n, ncomp); for a uniform
                    field, the single value (float or 1-D array)
        prefix, suffix
                    the file text before and after the internalField entry
                    (kept verbatim when writing)
    """

    def __init__(self, path=None):
        self.path = path
        self.header = {}
        self.type = None
        self.uniform = True
        self.values = None
        self.prefix = ""
        self.suffix = ""
        if path is not None:
            self._read(path)

    # -- reading ------------------------------------------------------------

    def _read(self, path):
        text = read_text(path)
        self.header = read_header(text)
        _check_ascii(self.header, path)
        if "class" not in self.header:
            raise FoamFileError("%s has no FoamFile header" % path)
        self.type = primitive_type(self.header["class"])
        ncomp = NCOMP[self.type]

        # The top-level internalField keyword: skip any occurrence inside
        # a comment or a sub-dictionary (brace depth must be zero).
        clean = _blank_comments(text)
        for m in re.finditer(r"\binternalField\b", clean):
            depth = clean.count("{", 0, m.start()) - clean.count(
                "}", 0, m.start())
            if depth == 0:
                break
        else:
            raise FoamFileError("%s has no internalField" % path)
        self.prefix = text[:m.start()]
        pos = m.end()
        km = re.compile(r"\s*(uniform|nonuniform)\b").match(clean, pos)
        if not km:
            raise FoamFileError(
                "%s: internalField is neither uniform nor nonuniform" % path)
        pos = km.end()
        if km.group(1) == "uniform":
            self.uniform = True
            end = clean.index(";", pos)
            vals = parse_numbers(clean[pos:end])
            if vals.size != ncomp:
                raise FoamFileError(
                    "%s: uniform %s value has %d numbers"
                    % (path, self.type, vals.size))
            self.values = float(vals[0]) if ncomp == 1 else vals
        else:
            self.uniform = False
            lm = re.compile(r"\s*List<(\w+)>").match(clean, pos)
            if not lm:
                raise FoamFileError("%s: expected List<type>" % path)
            if lm.group(1) != self.type:
                raise FoamFileError(
                    "%s: List<%s> in a %s field"
                    % (path, lm.group(1), self.header["class"]))
            self.values, end = parse_list(clean, lm.end(), ncomp)
            end = clean.index(";", end)
        self.suffix = text[end + 1:]

    # -- access ---------------------------------------------------------------

    def internal(self, n=None):
        """Internal values as an array; a uniform field is expanded to n."""
        if not self.uniform:
            return self.values
        if n is None:
            raise ValueError("uniform field: give the number of values")
        ncomp = NCOMP[self.type]
        if ncomp == 1:
            return np.full(n, float(self.values))
        return np.tile(np.asarray(self.values, float), (n, 1))

    def set_internal(self, values):
        """Replace the internal field by a nonuniform list."""
        values = np.asarray(values, dtype=float)
        ncomp = NCOMP[self.type]
        expected = (len(values),) if ncomp == 1 else (len(values), ncomp)
        if values.shape != expected:
            raise ValueError(
                "%s values need shape %s, got %s"
                % (self.type, expected, values.shape))
        self.uniform = False
        self.values = values

    def set_uniform(self, value):
        self.uniform = True
        self.values = value if np.ndim(value) == 0 else np.asarray(
            value, float)

    def boundary_patches(self):
        """{patch name: patch dictionary text} of the boundaryField."""
        clean = _blank_comments(self.suffix)
        m = re.search(r"\bboundaryField\s*\{", clean)
        if not m:
            return {}
        end = _matching(clean, m.end() - 1, "{", "}")
        body = clean[m.end():end]
        patches = {}
        pos = 0
        entry = re.compile(r"\s*(\"[^\"]*\"|[^\s{;]+)\s*\{")
        while True:
            em = entry.match(body, pos)
            if not em:
                break
            close = _matching(body, em.end() - 1, "{", "}")
            patches[em.group(1).strip('"')] = body[em.end():close]
            pos = close + 1
        return patches

    def patch_types(self):
        """{patch name: type} of the boundaryField."""
        types = {}
        for name, text in self.boundary_patches().items():
            m = re.search(r"\btype\s+([^;\s]+)\s*;", text)
            types[name] = m.group(1) if m else None
        return types

    # -- writing --------------------------------------------------------------

    def internal_text(self):
        """The 'internalField ...;' entry with full-precision values."""
        if self.uniform:
            return "internalField   uniform %s;" % format_value(self.values)
        lines = [
            "internalField   nonuniform List<%s> " % self.type,
            str(len(self.values)),
            "(",
        ]
        lines.extend(format_value(v) for v in self.values)
        lines.append(")")
        lines.append(";")
        return "\n".join(lines)

    def write(self, path=None):
        path = path or self.path
        with open(path, "w") as f:
            f.write(self.prefix)
            f.write(self.internal_text())
            f.write(self.suffix)


def _blank_comments(text):
    """Comments replaced by spaces of the same length (offsets preserved)."""
    return _COMMENT_RE.sub(lambda m: " " * len(m.group(0)), text)


def read_field(path):
    return FoamField(path)


BANNER = r"""/*--------------------------------*- C++ -*----------------------------------*\
| =========                 |                                                 |
| \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox           |
|  \\    /   O peration     | Version:  v1912                                 |
|   \\  /    A nd           | Website:  www.openfoam.com                      |
|    \\/     M anipulation  |                                                 |
\*---------------------------------------------------------------------------*/
"""


def header_text(cls, obj, location=None):
    """Banner and FoamFile header of a new ASCII file."""
    lines = [
        BANNER.rstrip("\n"),
        "FoamFile",
        "{",
        "    version     2.0;",
        "    format      ascii;",
        "    class       %s;" % cls,
    ]
    if location:
        lines.append('    location    "%s";' % location)
    lines.append("    object      %s;" % obj)
    lines.append("}")
    lines.append("// " + "* " * 37 + "//")
    return "\n".join(lines) + "\n\n"


def new_field(cls, obj, dimensions, boundary, location="0"):
    """A FoamField with a given boundaryField.

    boundary: {patch: {key: value text}}, e.g.
        {"X0": {"type": "calculated", "value": "uniform 0"}}
    """
    fld = FoamField()
    fld.header = {"class": cls, "object": obj, "format": "ascii"}
    fld.type = primitive_type(cls)
    fld.prefix = (header_text(cls, obj, location)
                  + "dimensions      %s;\n\n" % dimensions)
    lines = ["", "", "boundaryField", "{"]
    for patch, entries in boundary.items():
        lines.append("    %s" % patch)
        lines.append("    {")
        for key, value in entries.items():
            lines.append("        %-15s %s;" % (key, value))
        lines.append("    }")
    lines.append("}")
    lines.append("")
    lines.append("// " + "*" * 73 + " //")
    fld.suffix = "\n".join(lines) + "\n"
    return fld


# -- simple dictionaries ------------------------------------------------------

_TOKEN_RE = re.compile(r'"[^"]*"|[{}();]|[^\s{}();"]+')


def read_dict(path, _depth=0):
    """A dictionary file as nested Python dicts of entries.

    Values are strings (a number is returned as a float when it is the only
    token of the entry; lists as the raw text). '#include' and
    '#includeIfPresent' are followed relative to the file, later entries
    override earlier ones as in OpenFOAM.  Enough for controlDict,
    fvSolution, mechanicalProperties, decomposeParDict; not a full parser.
    """
    text = strip_comments(read_text(path))
    tokens = _TOKEN_RE.findall(text)
    result, _ = _parse_dict(tokens, 0, os.path.dirname(path), _depth)
    result.pop("FoamFile", None)
    return result


def _parse_dict(tokens, i, folder, depth):
    d = {}
    while i < len(tokens):
        tok = tokens[i]
        if tok == "}":
            return d, i + 1
        if tok in ("#include", "#includeIfPresent", "#includeEtc"):
            name = tokens[i + 1].strip('"')
            inc = os.path.join(folder, name)
            if tok != "#includeEtc" and os.path.exists(inc) and depth < 10:
                d.update(read_dict(inc, depth + 1))
            elif tok == "#include":
                raise FoamFileError("cannot include %s" % inc)
            i += 2
            continue
        if tok.startswith("#"):
            # Other directives (#inputMode, #remove ...) are not needed here
            i += 2
            continue
        key = tok.strip('"')
        if i + 1 < len(tokens) and tokens[i + 1] == "{":
            d[key], i = _parse_dict(tokens, i + 2, folder, depth)
            continue
        j = i + 1
        level = 0
        while j < len(tokens) and not (tokens[j] == ";" and level == 0):
            level += {"(": 1, ")": -1}.get(tokens[j], 0)
            j += 1
        value = tokens[i + 1:j]
        if len(value) == 1 and _NUMBER_RE.match(value[0]):
            d[key] = float(value[0])
        else:
            d[key] = " ".join(value).replace("( ", "(").replace(" )", ")")
        i = j + 1
    return d, i
