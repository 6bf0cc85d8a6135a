"""The papers as data (see :mod:`analysis.papers`): records, the one parser, the loader."""


from __future__ import annotations

import csv
import io
import keyword
import re
import tokenize
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

import sympy as sp

from analysis.papers.catalog import names, paper_path, raw

__all__ = [
    "FUNCTIONS", "PROVENANCE", "REQUIRED", "TYPES", "Paper", "Record", "legacy", "load",
    "load_file", "parse", "validate",
]  # fmt: skip

TYPES: tuple[str, ...] = (
    "equation", "expression", "function", "matrix", "table", "listing", "claim", "statement",
    "display", "cross-reference", "reference", "section", "extracted", "lost", "uncertain",
    "source",
)  # fmt: skip
REQUIRED: dict[str, tuple[str, ...]] = {
    "equation": (),  # lhs and rhs, or parts, or text (checked in validate())
    "expression": ("text",),
    "function": ("text",),
    "matrix": ("rows",),
    "lost": ("text",),
    "uncertain": ("text",),
    "section": ("text",),
}
"""Fields a record of a type must have (besides ``id``, ``type``, ``location``)."""
PROVENANCE: tuple[str, ...] = ("lost in extraction", "not printed")
"""Why a ``lost`` record's data is missing (its ``provenance``, default the first): the
extraction lost what the paper printed, or the paper never printed it. Only the first leaves a
row uncertain that a better copy of the paper could decide."""
FUNCTIONS: dict[str, object] = {
    "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "atan": sp.atan, "atan2": sp.atan2,
    "asin": sp.asin, "acos": sp.acos, "sqrt": sp.sqrt, "Abs": sp.Abs, "exp": sp.exp,
    "pi": sp.pi, "Piecewise": sp.Piecewise, "Derivative": sp.Derivative, "Subs": sp.Subs,
    "Eq": sp.Eq,
}  # fmt: skip
"""The one set of functions every paper's expressions may use."""
_META = ("id", "type", "group", "key")
_REF = re.compile(
    r"^(?P<id>[^\[\]:#]+)(?:#(?P<part>\d+)|#(?P<field>[a-z_]+)|\[(?P<cell>[^\]]+)\](?:\.(?P<col>\w+))?|:(?P<a>\d+)-(?P<b>\d+))?$"
)


@dataclass(frozen=True)
class Record:
    """One printed item: ``id``, ``type``, ``location`` and the fields of its type."""

    paper: str
    id: str
    type: str
    location: str
    fields: Mapping = field(repr=False)

    def __getitem__(self, key: str):
        return self.fields[key]

    def get(self, key: str, default=None):
        return self.fields.get(key, default)

    @property
    def text(self) -> str:
        """The item in its notation: ``lhs = rhs`` for an equation, the text of a listing or
        statement, the printed sentence of a claim."""
        f = self.fields
        if "lhs" in f and "rhs" in f:
            return f"{f['lhs']} = {f['rhs']}"
        for key in ("text", "printed"):
            if isinstance(f.get(key), str):
                return f[key]
        if f.get("runs"):  # an extracted item: its verbatim runs
            return "\n".join(f["runs"])
        raise ValueError(f"{self.paper}:{self.id} ({self.type}) has no single text; name a part")


@dataclass(frozen=True)
class Paper:
    """A paper's records, its symbols and the parser of its expressions."""

    id: str
    title: str
    source: str
    records: Mapping[str, Record] = field(repr=False)
    meta: Mapping = field(repr=False)

    def record(self, rid: str) -> Record:
        if rid not in self.records:
            raise ValueError(f"paper {self.id} has no record {rid!r}")
        return self.records[rid]

    def symbols(self, namespace: str = "main") -> dict[str, object]:
        key = (self.id, namespace)
        if key not in _SYMBOLS:
            spec = self.meta["symbols"]
            _SYMBOLS[key] = _symbols(spec if namespace == "main" else spec[namespace])
        return _SYMBOLS[key]

    def parse(self, text: str, namespace: str = "main") -> sp.Expr:
        """Parse SymPy text over the paper's symbols and :data:`FUNCTIONS`; ``ValueError``
        naming the text if it does not parse or uses an unknown name (memoized: SymPy
        expressions are immutable)."""
        key = (self.id, namespace, text)
        if key not in _PARSED:
            try:
                _PARSED[key] = parse(text, self.symbols(namespace))
            except ValueError as exc:
                _PARSED[key] = exc
        out = _PARSED[key]
        if isinstance(out, ValueError):
            raise ValueError(*out.args)
        return out

    def matrix(self, rid: str) -> sp.Matrix:
        """A printed matrix (record id, or its key in the group ``MATRICES``) in SymPy."""
        rec = self.records.get(rid)
        if rec is None or rec.type != "matrix":
            keyed = [r for r in self.records.values() if r.type == "matrix" and r.get("key") == rid]
            rec = keyed[0] if keyed else self.record(rid)
        if rec.type != "matrix":
            raise ValueError(f"{self.id}:{rid} is a {rec.type}, not a matrix")
        return sp.Matrix([[self.parse(e) for e in row] for row in rec["rows"]])

    def text(self, ref: str) -> str:
        """The printed text a reference points at (see the module docstring)."""
        m = _REF.match(ref.strip())
        if not m:
            raise ValueError(f"malformed reference {ref!r}")
        rec = self.record(m["id"])
        if m["part"]:
            p = rec["parts"][int(m["part"]) - 1]
            return f"{p['lhs']} = {p['rhs']}"
        if m["field"]:  # a named field: what the extraction gives where the record reads it
            return str(rec[m["field"]])
        if m["a"]:
            lines = rec["text"].splitlines()
            a, b = int(m["a"]), int(m["b"])
            if not 1 <= a <= b <= len(lines):
                raise ValueError(f"{ref}: lines {a}-{b} outside 1-{len(lines)}")
            return "\n".join(lines[a - 1 : b])
        if m["cell"]:
            if rec.type == "matrix":
                i, j = (int(v) for v in m["cell"].split(","))
                return rec["rows"][i - 1][j - 1]
            return self.cell(rec, m["cell"], m["col"])
        return rec.text

    def cell(self, rec: Record, row: str, col: str) -> str:
        """A table cell as printed (text): rows from the record or from its ``file``."""
        rows = self.table_rows(rec.id)
        if row not in rows or col not in rows[row]:
            raise ValueError(f"{self.id}:{rec.id} has no cell [{row}].{col}")
        return str(rows[row][col]) or rec.get("blank", "")

    def table_rows(self, rid: str) -> dict[str, dict[str, str]]:
        """A table as ``{row key: {column: cell}}`` (cells as printed)."""
        rec = self.record(rid)
        if "file" in rec.fields:
            from analysis.paths import data_dir

            with (data_dir() / rec["file"]).open(newline="", encoding="utf-8") as fh:
                return {r[rec["key_column"]]: r for r in csv.DictReader(fh)}
        rows, cols = rec["rows"], rec.get("columns")
        if isinstance(rows, Mapping):
            return {k: dict(zip(cols, v, strict=True)) for k, v in rows.items()}
        if cols and rows and not isinstance(rows[0], Mapping):  # a list of rows, as printed
            return {str(i): dict(zip(cols, r, strict=True)) for i, r in enumerate(rows, start=1)}
        return {str(i): dict(r) for i, r in enumerate(rows, start=1)}

    def group(self, name: str):
        """A group of records in the shape of the former module constant ``name``."""
        return _frozen(self._group(name))

    def _group(self, name: str):
        shape = self.meta["groups"].get(name)
        if shape is None:
            raise AttributeError(f"paper {self.id} has no group {name!r}")
        recs = [r for r in self.records.values() if r.get("group") == name]
        plain = [
            {k.removeprefix("_") if k[1:] in _META else k: v for k, v in r.fields.items()
             if k not in _META} for r in recs
        ]  # fmt: skip
        if shape == "object":
            return plain[0]
        if shape == "str":
            return recs[0]["text"]
        if shape == "rows":
            return recs[0]["rows"]
        if shape == "list":
            return plain
        kind = shape.partition(":")[2]
        value = {"text": lambda r, p: r["text"], "runs": lambda r, p: tuple(r["runs"])}.get(
            kind, lambda r, p: p
        )
        return {r["key"]: value(r, p) for r, p in zip(recs, plain, strict=True)}


def _frozen(v):
    """Lists as tuples and digit keys as ints, throughout (TOML keys are strings; the module
    views are read-only data, as the constants they stand for were)."""
    if isinstance(v, dict):
        ints = bool(v) and all(isinstance(k, str) and k.isdigit() for k in v)
        return {(int(k) if ints else k): _frozen(x) for k, x in v.items()}
    if isinstance(v, list):
        return tuple(_frozen(x) for x in v)
    return v


@cache
def _globals() -> dict:
    """SymPy's namespace for parse_expr, built once (parse_expr would exec 'from sympy import
    *' on every call without it)."""
    g: dict = {}
    exec("from sympy import *", g)
    return g


_TOKENS = {"+", "-", "*", "/", "**", "(", ")", ",", "<", ">", "<=", ">=", "~", "&", "|"}


def _plain(text: str) -> bool:
    """Is ``text`` an expression and nothing else: names (no Python keyword), numbers and the
    operators of :data:`_TOKENS`? (No comment, conditional, lambda, attribute or subscript:
    Python's parser behind ``parse_expr`` would take ``x # note`` as ``x``.)"""
    try:
        toks = list(tokenize.generate_tokens(io.StringIO(text.strip()).readline))
    except (tokenize.TokenError, IndentationError, SyntaxError):
        return False
    for t in toks:
        if t.type in (tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER, tokenize.NUMBER):
            continue
        if t.type == tokenize.NAME and not keyword.iskeyword(t.string):
            continue
        if t.type == tokenize.OP and t.string in _TOKENS:
            continue
        return False
    return True


def parse(text: str, names: Mapping[str, object]) -> sp.Expr:
    """Parse SymPy ``text`` with ``names`` and :data:`FUNCTIONS` only (ValueError naming it):
    an expression of names, numbers and arithmetic, comparison and logical operators, nothing
    else (:func:`_plain`)."""
    if not isinstance(text, str) or "__" in text or len(text) > 4000 or not _plain(text):
        raise ValueError(f"cannot parse {text!r}: not an expression of the transcription")
    try:
        with warnings.catch_warnings():  # Python's SyntaxWarning for text like "(a)(b)"
            warnings.simplefilter("ignore", SyntaxWarning)
            expr = sp.parse_expr(text, local_dict={**names, **FUNCTIONS}, global_dict=_globals(),
                                 evaluate=True)  # fmt: skip
    except Exception as exc:  # sympy raises many types for bad syntax
        raise ValueError(f"cannot parse transcribed expression {text!r}: {exc}") from None
    if not isinstance(expr, sp.Basic):
        raise ValueError(f"{text!r} is not an expression")
    unknown = {s.name for s in expr.free_symbols} - set(names)
    if unknown:
        raise ValueError(f"expression {text!r} uses unknown name(s) {sorted(unknown)}")
    return expr


_SYMBOLS: dict[tuple[str, str], dict[str, object]] = {}
_PARSED: dict[tuple[str, str, str], object] = {}


def _symbols(spec: Mapping) -> dict[str, object]:
    out: dict[str, object] = {}
    for assumption in ("real", "positive"):
        for name in spec.get(assumption, "").split():
            out[name] = sp.Symbol(name, **{assumption: True})
    for name in spec.get("functions", ()):
        out[name] = sp.Function(name)
    for name, same in spec.get("aliases", {}).items():  # a name the paper states equal to another
        if same not in out:
            raise ValueError(f"alias {name} = {same}: {same} is not a symbol of the paper")
        out[name] = out[same]
    return out


@cache
def load(name: str) -> Paper:
    """The paper ``name`` (one of :func:`names`), validated, cached."""
    if name not in names():
        raise ValueError(f"no paper {name!r}; expected one of {', '.join(names())}")
    return load_file(paper_path(name))


@cache
def load_file(path: Path) -> Paper:
    """The paper in the data file ``path`` (anywhere: a paper being added, a test's example),
    validated, cached."""
    doc = raw(Path(path))
    meta = doc["paper"]
    recs = {}
    for r in doc.get("record", ()):
        rec = Record(meta["id"], r["id"], r["type"], r.get("location", ""), r)
        if rec.id in recs:
            raise ValueError(f"{path}: duplicate record id {rec.id!r}")
        recs[rec.id] = rec
    paper = Paper(meta["id"], meta["title"], meta["source"], recs, meta)
    validate(paper)
    return paper


def validate(paper: Paper) -> None:
    """Raise ValueError naming the record that breaks the schema (types, locations, fields,
    expressions that do not parse)."""
    for rec in paper.records.values():
        where = f"{paper.id}:{rec.id}"
        if rec.type not in TYPES:
            raise ValueError(f"{where}: type {rec.type!r} not in {TYPES}")
        if not rec.location.strip():
            raise ValueError(f"{where}: no location")
        missing = [k for k in REQUIRED.get(rec.type, ()) if k not in rec.fields]
        if missing:
            raise ValueError(f"{where}: a {rec.type} needs {missing}")
        if rec.type == "listing" and not ({"text", "printed", "rungs"} & set(rec.fields)):
            raise ValueError(f"{where}: a listing needs its text")
        ns = rec.get("namespace", "main")
        if rec.type == "equation":
            parts = rec.get("parts") or ([rec.fields] if "lhs" in rec.fields else [])
            if not parts and not ({"text", "printed"} & set(rec.fields)):
                raise ValueError(f"{where}: an equation needs lhs/rhs, parts or text")
            for p in parts:
                for side in ("lhs", "rhs"):
                    if not re.search(r"\b[tT]\d\d\b|^matrix:", str(p[side])):
                        paper.parse(p[side], ns)
        if rec.type == "matrix":
            paper.matrix(rec.id)
        if rec.type == "lost" and rec.get("provenance", PROVENANCE[0]) not in PROVENANCE:
            raise ValueError(f"{where}: provenance {rec['provenance']!r} not in {PROVENANCE}")


def legacy(name: str, **extra):
    """``__getattr__`` for the module view of a paper: its groups by their former constant
    names (``FIGURE_STL``, ``EQUATIONS``, ...), ``SYMBOLS``, ``parse`` and ``matrix``."""

    def __getattr__(attr: str):
        paper = load(name)
        if attr in extra:
            return extra[attr]() if attr.isupper() else extra[attr]
        if attr == "SYMBOLS":
            return paper.symbols()
        if attr == "parse":
            return paper.parse
        if attr == "matrix":
            return paper.matrix
        if attr == "SOURCE" and "SOURCE" not in paper.meta["groups"]:
            return paper.source
        if attr.isupper() and attr in paper.meta["groups"]:
            return paper.group(attr)
        raise AttributeError(f"module analysis.papers.{name} has no attribute {attr!r}")

    return __getattr__
