"""Every printed record checked, and every failure explained (issue 30, item 1).

A paper's printed records (``data/papers/<paper>.toml``: an equation, an expression, a
function, a matrix, a table, a listing, a claim) each carry a ``check``: the check kind of
:mod:`analysis.audit.kinds` and its parameters, the kind by default from the record's type
(:data:`DEFAULT_KIND`: a matrix is held cell by cell against a product, a table cell against its
recomputation at the printed decimals, an equation on sampled configurations, a claim as a
predicate over a domain through its ``reading``, a listing run on the PLC evaluator). The check
is the paper's, not the register's: it exists before any cause is written.

A record is split into the units its check decides (:func:`units`): the cells of a matrix, the
cells of a table's checked columns, the parts of an equation, else the record itself. Then
(:func:`audit`):

- a unit whose check fails must be explained by a register row that names it (its printed
  reference is the unit, the whole record, or a part of a listing): otherwise it is
  *unexplained* ("unexplained: palletizer eq. 2 (sec. 3): the printed form differs from the
  derivation");
- a unit whose check passes must not be named by a row that counts against the paper (an
  error, omission or unsupported claim): that row explains nothing.

A record whose data cannot be checked by anything the paper or the project holds says so:
``check = { given = "<why>" }`` (a vendor's datasheet value, a dimension only the paper
states); it is counted apart, never silently.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field

__all__ = ["DEFAULT_KIND", "PRINTED", "Finding", "Unit", "audit", "covers", "refs", "units"]

PRINTED = ("equation", "expression", "function", "matrix", "table", "listing", "claim")
"""The record types that print something a check can decide."""
DEFAULT_KIND = {
    "equation": "sampled", "expression": "matrix", "function": "matrix", "matrix": "matrix",
    "table": "table", "listing": "stl", "claim": "claim",
}  # fmt: skip
WHAT = {
    "equation": "the printed form differs from the derivation",
    "expression": "the printed form differs from the derivation",
    "function": "the printed form differs from the derivation",
    "matrix": "the printed cell differs from the product",
    "table": "the printed cell differs from its recomputation",
    "listing": "the listing does not compute what it should",
    "claim": "the claim does not hold",
}
_UNIT_KEYS = ("reading", "rows", "columns", "parts", "given")
"""Keys of a record's ``check`` that say how to split or read it, not parameters of a kind."""
COUNTED = ("error", "omission", "unsupported")


@dataclass(frozen=True)
class Unit:
    """What one check decides: ``ref`` (``@eq12[2,3]``, ``@table4[1].theta2_deg``,
    ``@eq3#2``, ``@accuracy``), the record, where it is printed, the text the check reads and
    the check's spec (None with ``given``: the reason nothing can check it)."""

    ref: str
    record: str
    type: str
    location: str
    text: str
    spec: Mapping | None = field(default=None, compare=False)
    given: str = ""


def _spec(rec, check: Mapping, **unit) -> dict:
    spec = {"kind": DEFAULT_KIND[rec.type]}
    spec.update({k: v for k, v in check.items() if k not in _UNIT_KEYS})
    spec.update(unit)
    return spec


def _text(rec) -> str:
    """The record's printed text (a listing without the transcription's '//' notes)."""
    try:
        text = rec.text
    except ValueError:  # a matrix or a many-part equation: no single text
        return ""
    if rec.type == "listing":
        text = "\n".join(ln.split("//")[0].rstrip() for ln in text.splitlines()).strip("\n")
    return text


def units(paper) -> Iterator[Unit]:
    """Every unit of every printed record of ``paper`` that carries a check, and, as a unit
    with no spec and no ``given``, every printed record that carries none."""
    for rec in paper.records.values():
        if rec.type not in PRINTED:
            continue
        check = rec.get("check")
        ref = f"@{rec.id}"
        if check is None or "given" in check:
            yield Unit(ref, rec.id, rec.type, rec.location, _text(rec), None,
                       (check or {}).get("given", ""))  # fmt: skip
            continue
        if rec.type == "matrix" and check.get("kind", "matrix") == "matrix":
            for i, row in enumerate(rec["rows"][: check.get("rows")], start=1):
                for j, cell in enumerate(row, start=1):
                    where = f"{rec.location} row {i} col {j}"
                    yield Unit(f"{ref}[{i},{j}]", rec.id, rec.type, where, cell,
                               _spec(rec, check, cells=[[i, j]]))  # fmt: skip
        elif rec.type == "table" and check.get("kind", "table") == "table":
            for row in paper.table_rows(rec.id):
                for col in check["columns"]:
                    yield Unit(f"{ref}[{row}].{col}", rec.id, rec.type,
                               f"{rec.location.split(',')[0]} row {row} {col}",
                               paper.cell(rec, row, col),
                               _spec(rec, check, table=rec.id, row=row, column=col))  # fmt: skip
        elif rec.type == "equation" and rec.get("parts") and "reading" not in check:
            over = check.get("parts", {})
            for k in range(1, len(rec["parts"]) + 1):
                text = paper.text(f"{rec.id}#{k}")
                yield Unit(f"{ref}#{k}", rec.id, rec.type, f"{rec.location} part {k}", text,
                           _spec(rec, {**check, **over.get(str(k), {})}))  # fmt: skip
        else:
            yield Unit(ref, rec.id, rec.type, rec.location, check.get("reading", _text(rec)),
                       _spec(rec, check))  # fmt: skip


_REF = re.compile(r"@([^\[\]:#',}\s\"]+)((?:\[[^\]]+\](?:\.\w+)?)|#\w+|:\d+-\d+)?")


def refs(source: str) -> list[tuple[str, str]]:
    """``(record, reference)`` of every reference into the paper a manifestation's printed
    source names (a reference, a list of them, an excerpt's ``of``, a network order)."""
    return [(m[1], m[0]) for m in _REF.finditer(source)]


def covers(reference: tuple[str, str], unit: Unit) -> bool:
    """Does a manifestation's reference name ``unit``: the unit itself, its whole record, or
    any part of a record that is one unit (a line range of a listing, a field, an excerpt)?"""
    rid, ref = reference
    return rid == unit.record and (ref == unit.ref or ref == f"@{rid}" or unit.ref == f"@{rid}")


@dataclass(frozen=True)
class Finding:
    """One record unit the audit cannot account for, and why (one line, naming it)."""

    paper: str
    unit: Unit
    message: str


def _names(unit: Unit, paper) -> set[str]:
    """The record ids a row may name ``unit`` by: its record, and the extracted runs the record
    says it is read from (``extracted = ["<run>", ...]`` naming records ``extracted.<run>``)."""
    out = {unit.record}
    for x in paper.record(unit.record).get("extracted") or ():
        if isinstance(x, str) and f"extracted.{x}" in paper.records:
            out.add(f"extracted.{x}")
    return out


def audit(paper, manifestations, holds) -> tuple[list[Finding], dict[str, int]]:
    """The units of ``paper`` against its register's ``manifestations``: the findings (a failing
    unit no row explains; a counted row that names only units whose checks pass; a printed
    record without a check) and the counts (units checked, passing, failing and explained,
    given). ``holds(unit)`` runs a unit's check on its text."""
    found, counts = [], {"units": 0, "pass": 0, "fail": 0, "explained": 0, "given": 0}
    passing: dict[str, bool] = {}
    named_by: dict[str, list] = {}
    for u in units(paper):
        where = f"{paper.id} {u.location} ({u.ref})"
        if u.spec is None:
            if u.given:
                counts["given"] += 1
            else:
                found.append(Finding(paper.id, u, f"unchecked: {where}: a printed {u.type} without a check"))  # noqa: E501
            continue
        counts["units"] += 1
        ids = _names(u, paper)
        by = [m for m in manifestations
              if any(covers((u.record, ref if rid == u.record else f"@{u.record}"), u)
                     for rid, ref in refs(m.source) if rid in ids)]  # fmt: skip
        for m in by:
            named_by.setdefault(m.id, []).append(u)
        passing[u.ref] = ok = holds(u)
        if ok:
            counts["pass"] += 1
            continue
        counts["fail"] += 1
        if any(m.status != "holds" for m in by):
            counts["explained"] += 1
        else:
            found.append(Finding(paper.id, u, f"unexplained: {where}: {WHAT[u.type]}"))
    for m in manifestations:
        us = named_by.get(m.id, [])
        if m.status in COUNTED and us and all(passing[u.ref] for u in us):
            where = ", ".join(f"{u.location} ({u.ref})" for u in us)
            found.append(Finding(paper.id, us[0], f"explains nothing: {m.id} names {paper.id} {where}, whose check passes"))  # noqa: E501
    return found, counts
