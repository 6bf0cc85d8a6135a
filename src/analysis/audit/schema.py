"""One register schema for every paper: root causes, their manifestations, a test for each.

A :class:`Cause` is one thing the paper got wrong (or left out, or that the extraction makes
undecidable), stated once: a single-argument arctangent is one cause even where it shows up
in five equations, a figure and three table cells. Each place it shows is a
:class:`Manifestation` with the printed text, the corrected text and a ``verify`` predicate
that must reject the printed text and accept the corrected one. Each cause has a
``demonstrate`` function: its test, which fails if the printed form were right.

Statuses (:data:`STATUSES`)
---------------------------
``error``        the paper states something wrong
``omission``     the paper leaves out what its claim needs (a missing check, routine, step)
``unsupported``  a claim with no evidence in the paper
``uncertain``    the reading depends on how the extraction is put back together
``notation``     a variant of notation, not an error (counted apart)
``extraction``   damage done by the text extraction, not by the paper (counted apart)
``holds``        an audited claim that the checks confirm

Files: one CSV per paper, ``data/errata/<paper>.csv``, columns :data:`COLUMNS`. A cause row
has an empty ``cause`` column; its manifestation rows name it there. ``check`` is the test
node id (``tests/audit/test_register.py::test_cause[<id>]`` or ``::test_manifestation[<id>]``).
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

__all__ = [
    "COLUMNS",
    "KINDS",
    "STATUSES",
    "Cause",
    "Manifestation",
    "Register",
    "all_fail",
    "make_cause",
    "read_rows",
    "safe",
    "validate_rows",
]

STATUSES: tuple[str, ...] = (
    "error",
    "omission",
    "unsupported",
    "uncertain",
    "notation",
    "extraction",
    "holds",
)
COUNTED = ("error", "omission", "unsupported")
"""Statuses that count against the paper in a headline."""
KINDS: tuple[str, ...] = (
    "sign",
    "index",
    "label",
    "missing term",
    "branch/quadrant",
    "transcription",
    "unit",
    "cross-reference",
    "undefined symbol",
    "PLC semantics",
    "VB semantics",
    "implementation",
    "claim",
    "reasoning",
    "notation",
    "extraction",
)
COLUMNS: tuple[str, ...] = (
    "id",
    "cause",
    "status",
    "kind",
    "location",
    "printed",
    "corrected",
    "evidence",
    "check",
)
_ID = re.compile(r"^[a-z0-9][a-z0-9.-]*(/[a-z0-9][a-z0-9.-]*)?$")
_CHECK = re.compile(r"^tests/(\w+/)*test_\w+\.py::\w+(\[[^\]]+\])?$")
TEST_FILE = "tests/audit/test_register.py"


def _never(text: str) -> bool:
    return False


@dataclass(frozen=True)
class Manifestation:
    """One place a cause shows: a printed item, its correction and the check between them.

    ``verify(text)`` decides whether a text of the same notation is right; the register
    test asserts ``verify(printed)`` is False and ``verify(corrected)`` is True (for an
    ``uncertain`` cause: that the two readings differ).
    """

    id: str
    location: str
    printed: str
    corrected: str
    evidence: str
    verify: Callable[[str], bool] = field(default=_never, repr=False, compare=False)
    source: str = field(default="", compare=False)
    """The audit item it comes from, if any (seed 000's item audit)."""

    @property
    def check(self) -> str:
        return f"{TEST_FILE}::test_manifestation[{self.id}]"


@dataclass(frozen=True)
class Cause:
    """A root cause with its manifestations and the test that demonstrates it."""

    id: str
    title: str
    status: str
    kind: str
    evidence: str
    manifestations: tuple[Manifestation, ...] = ()
    demonstrate: Callable[[], bool] = field(default=lambda: False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if not _ID.match(self.id) or "/" in self.id:
            raise ValueError(f"cause id {self.id!r}: lowercase words joined by '-'")
        if self.status not in STATUSES:
            raise ValueError(f"cause {self.id}: status {self.status!r} not in {STATUSES}")
        if self.kind not in KINDS:
            raise ValueError(f"cause {self.id}: kind {self.kind!r} not in {KINDS}")
        for m in self.manifestations:
            if not m.id.startswith(self.id + "/") or not _ID.match(m.id):
                raise ValueError(f"manifestation {m.id!r} must be named {self.id}/<slug>")

    @property
    def check(self) -> str:
        return f"{TEST_FILE}::test_cause[{self.id}]"

    @property
    def locations(self) -> str:
        return "; ".join(dict.fromkeys(m.location for m in self.manifestations))


@dataclass(frozen=True)
class Register:
    """The causes found in one paper."""

    paper: str
    title: str
    causes: tuple[Cause, ...]

    def __post_init__(self) -> None:
        ids = [c.id for c in self.causes] + [m.id for c in self.causes for m in c.manifestations]
        dup = sorted({i for i in ids if ids.count(i) > 1})
        if dup:
            raise ValueError(f"register {self.paper}: duplicate ids {dup}")

    def cause(self, cause_id: str) -> Cause:
        for c in self.causes:
            if c.id == cause_id:
                return c
        raise ValueError(f"register {self.paper} has no cause {cause_id!r}")

    def manifestation(self, mid: str) -> Manifestation:
        cause = self.cause(mid.split("/")[0])
        for m in cause.manifestations:
            if m.id == mid:
                return m
        raise ValueError(f"register {self.paper} has no manifestation {mid!r}")

    def counts(self) -> dict[str, int]:
        """Causes per status (every status present, zero included)."""
        return {s: sum(c.status == s for c in self.causes) for s in STATUSES}

    @property
    def n_manifestations(self) -> int:
        return sum(len(c.manifestations) for c in self.causes)

    def rows(self) -> list[dict[str, str]]:
        """The CSV rows: each cause, then its manifestations."""
        out = []
        for c in self.causes:
            out.append(
                {
                    "id": c.id,
                    "cause": "",
                    "status": c.status,
                    "kind": c.kind,
                    "location": c.locations or "(the paper as a whole)",
                    "printed": "",
                    "corrected": "",
                    "evidence": f"{c.title} {c.evidence}".strip(),
                    "check": c.check,
                }
            )
            for m in c.manifestations:
                out.append(
                    {
                        "id": m.id,
                        "cause": c.id,
                        "status": c.status,
                        "kind": c.kind,
                        "location": m.location,
                        "printed": m.printed,
                        "corrected": m.corrected,
                        "evidence": m.evidence,
                        "check": m.check,
                    }
                )
        return out

    def csv_text(self) -> str:
        buf = io.StringIO()
        w = csv.DictWriter(buf, fieldnames=list(COLUMNS), lineterminator="\n")
        w.writeheader()
        w.writerows(self.rows())
        return buf.getvalue()


def read_rows(path: Path) -> list[dict[str, str]]:
    """Read and validate a register CSV (see :func:`validate_rows`)."""
    with path.open(newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        header = tuple(reader.fieldnames or ())
        rows = list(reader)
    if header != COLUMNS:
        raise ValueError(f"{path}: columns {list(header)}; expected {list(COLUMNS)}")
    validate_rows(rows, str(path))
    return rows


def validate_rows(rows: list[dict[str, str]], where: str = "register") -> None:
    """Raise ValueError naming the line for any row that breaks the schema."""
    causes: dict[str, str] = {}
    seen: set[str] = set()
    for n, r in enumerate(rows, start=2):
        if None in r or None in r.values():
            raise ValueError(f"{where} line {n}: {len(COLUMNS)} fields expected")
        rid = r["id"].strip()
        if not rid or rid in seen or not _ID.match(rid):
            raise ValueError(f"{where} line {n}: id {rid!r} is empty, malformed or duplicated")
        seen.add(rid)
        if r["status"] not in STATUSES:
            raise ValueError(f"{where} line {n} ({rid}): status {r['status']!r} not in {STATUSES}")
        if r["kind"] not in KINDS:
            raise ValueError(f"{where} line {n} ({rid}): kind {r['kind']!r} not in {KINDS}")
        if not _CHECK.match(r["check"]):
            raise ValueError(f"{where} line {n} ({rid}): check {r['check']!r} is not a test id")
        for col in ("location", "evidence"):
            if not r[col].strip():
                raise ValueError(f"{where} line {n} ({rid}): column {col!r} is empty")
        if r["cause"]:
            if r["cause"] not in causes:
                raise ValueError(f"{where} line {n} ({rid}): cause {r['cause']!r} not above it")
            if not rid.startswith(r["cause"] + "/") or r["status"] != causes[r["cause"]]:
                raise ValueError(f"{where} line {n} ({rid}): not consistent with its cause")
            if not (r["printed"].strip() and r["corrected"].strip()):
                raise ValueError(f"{where} line {n} ({rid}): a manifestation needs both texts")
        else:
            if "/" in rid:
                raise ValueError(f"{where} line {n} ({rid}): a cause id has no '/'")
            causes[rid] = r["status"]


# --- building registers ------------------------------------------------------------------
def safe(fn):
    """A verify predicate that answers False instead of raising on a malformed text."""

    def wrapped(text: str) -> bool:
        try:
            return bool(fn(text))
        except Exception:  # a text the predicate cannot read is not a right text
            return False

    return wrapped


def all_fail(ms) -> bool:
    """The printed texts fail and the corrections pass every manifestation's check."""
    return all(not m.verify(m.printed) and m.verify(m.corrected) for m in ms)


def make_cause(cid, title, status, kind, evidence, ms, demo=None) -> Cause:
    """A :class:`Cause` whose demonstration is ``demo`` or, by default, :func:`all_fail` of
    its manifestations."""
    ms = tuple(ms)
    return Cause(cid, title, status, kind, evidence, ms, demo or (lambda: all_fail(ms)))
