"""One register schema for every paper: root causes, where each shows, the check of each.

A :class:`Cause` is one thing the paper got wrong (or left out, or cannot be decided), stated
once; each place it shows is a :class:`Manifestation` with the printed text (a reference into
``analysis.papers``), the corrected text and ``verify(text) -> bool``, a shared check kind
(:mod:`analysis.audit.kinds`) that decides a text by computation. ``demonstrate()`` is the
cause's test: the printed forms fail their checks and the corrections pass; it fails once the
printed texts are replaced by the corrected ones. An ``uncertain`` cause demonstrates the
ambiguity instead: its readings differ in what they imply (one is right, one is not).

Statuses (:data:`STATUSES`): ``error`` the paper states something wrong; ``omission`` it leaves
out what its claim needs; ``unsupported`` a claim with no evidence in the paper; ``uncertain``
what cannot be decided without what the extraction lost; ``notation`` a variant of notation;
``extraction`` damage done by the text extraction; ``holds`` what the checks confirm.

Severity of a counted cause (:data:`SEVERITIES`): ``breaks`` the robot or program does not work
(no motion, a crash, nonsense commands); ``wrong-result`` it works and gives wrong numbers;
``misleading`` a claim or reasoning a reader would act on wrongly; ``cosmetic`` a slip a reader
corrects without consequence.
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

__all__ = [
    "COLUMNS", "COUNTED", "COUNTING_RULE", "HEADLINE_WORDS", "KINDS", "SEVERITIES", "STATUSES",
    "SUMMARY_KEYS", "Cause", "Manifestation", "Register", "check_summary", "read_rows",
    "validate_rows",
]  # fmt: skip

STATUSES = ("error", "omission", "unsupported", "uncertain", "notation", "extraction", "holds")
COUNTED = ("error", "omission", "unsupported")
"""Statuses that count against the paper."""
SEVERITIES = ("breaks", "wrong-result", "misleading", "cosmetic")
KINDS = (
    "sign", "index", "label", "missing term", "branch/quadrant", "transcription", "unit",
    "cross-reference", "undefined symbol", "PLC semantics", "VB semantics", "implementation",
    "claim", "reasoning", "notation", "extraction",
)  # fmt: skip
COUNTING_RULE = (
    "A root cause is counted once, however many places it shows in.",
    "A table cell or figure that follows from another cause is a manifestation of that cause.",
    "A sub-point of a cause is one of its manifestations, not a cause of its own.",
    "What a paper does not list but any reader would take from a library (a vendor's "
    "subroutine, a standard formula) is not an omission.",
    "What cannot be decided without data the extraction lost is uncertain, not counted.",
    "The item table and the register are one source (the items are the register's "
    "manifestations and the checks that hold) and never disagree.",
)
"""The one counting rule for every paper (shown in the README block and on the site)."""
SUMMARY_KEYS = ("headline", "worst", "verdict", "take_away")
"""A register's ``[summary]``: ``headline`` the verdict at a glance (at most
:data:`HEADLINE_WORDS` words, no numbers typed in), ``worst`` the single worst consequence in
numbers (a template: the numbers come from the checks, ``{facts.*}`` or
``{m[<manifestation id>].printed.*}``), ``verdict`` what breaks, what gives wrong numbers, what
misleads and what is cosmetic, ``take_away`` the corrected artefacts."""
HEADLINE_WORDS = 15


def check_summary(paper: str, raw: Mapping) -> None:
    """ValueError naming the key unless the raw ``[summary]`` of ``paper`` has exactly
    :data:`SUMMARY_KEYS`, each a non-empty string; the headline at most
    :data:`HEADLINE_WORDS` words with no digit; the worst consequence with a ``{...}`` field."""
    keys = set(raw)
    if keys != set(SUMMARY_KEYS):
        extra, missing = sorted(keys - set(SUMMARY_KEYS)), sorted(set(SUMMARY_KEYS) - keys)
        raise ValueError(
            f"register {paper}: [summary] " + "; ".join(
                [f"unknown key {k!r}" for k in extra] + [f"missing key {k!r}" for k in missing]
            ) + f" (expected {', '.join(SUMMARY_KEYS)})"
        )  # fmt: skip
    for k in SUMMARY_KEYS:
        if not isinstance(raw[k], str) or not raw[k].strip():
            raise ValueError(f"register {paper}: [summary] {k} must be a non-empty string")
    words = raw["headline"].split()
    if len(words) > HEADLINE_WORDS:
        raise ValueError(
            f"register {paper}: [summary] headline has {len(words)} words, at most "
            f"{HEADLINE_WORDS}"
        )
    if re.search(r"\d", raw["headline"]):
        raise ValueError(
            f"register {paper}: [summary] headline {raw['headline']!r} types a number; numbers "
            "go in 'worst', filled from the checks"
        )
    if not re.search(r"\{[^{}]+\}", raw["worst"]):
        raise ValueError(
            f"register {paper}: [summary] worst names no computed number ({{facts.*}} or "
            "{m[<manifestation>].printed.*})"
        )


COLUMNS = (
    "id", "cause", "status", "kind", "severity", "location", "printed", "reading", "corrected",
    "alternatives", "rests_on", "evidence", "check", "tolerance",
)  # fmt: skip
"""The register CSV's columns, in order (outside checks read them: a new column is appended).
``tolerance``: the tolerance a max/min claim's check applies to the corrected value
(:func:`analysis.audit.kinds.claim.evaluate_claim`: stated, or half a unit of the last decimal,
at most 5e-4 of the value, 1e-9 at 0); empty where the check compares exactly."""
_ID = re.compile(r"^[a-z0-9][a-z0-9.-]*(/[a-z0-9][a-z0-9.-]*)?$")
TEST = "tests/audit/test_registers.py"


@dataclass(frozen=True)
class Manifestation:
    """One place a cause shows. ``verify(text)`` is True only when ``text`` states what the
    paper should have printed, decided by the check kind ``spec`` (never by the register's
    words). ``reading``: the printed item put in the check's notation, where the print is not
    already in it (a claim as a predicate); ``readings``: the readings an uncertain print allows."""

    id: str
    cause: str
    status: str
    location: str
    printed: str
    corrected: str
    evidence: str = ""
    reading: str = ""
    readings: tuple[str, ...] = ()
    alternatives: tuple[str, ...] = ()
    rests_on: tuple[str, ...] = ()
    equivalent: tuple[str, ...] = ()
    source: str = ""
    """The reference(s) into the paper the printed text comes from (``@eq12[2,2]``)."""
    spec: Mapping = field(default_factory=dict, repr=False, compare=False)
    result: Callable = field(default=lambda text: None, repr=False, compare=False)
    agrees: Callable = field(default=lambda text: False, repr=False, compare=False)
    """``agrees(text)``: the text is the same statement as the correction (or as one the
    register declares ``equivalent``), :func:`analysis.audit.equivalence.same`."""

    @property
    def tolerance(self) -> str:
        """The tolerance the check applies to the correction's value, for a max/min claim (the
        check's result on :attr:`corrected`, three significant digits); else ''."""
        if self.spec.get("kind") != "claim" or not re.match(r"(max|min) ", self.corrected.strip()):
            return ""
        res = self.result(self.corrected)
        tol = None if res is None else res.values.get("tol")
        return "" if tol is None else f"{float(tol):.3g}"

    def holds(self, text: str) -> bool:
        """Is ``text`` true of the paper's model? The check kind's computation alone (a
        tautology is true: :meth:`verify` is the question a correction answers)."""
        return bool(self.result(text))

    def verify(self, text: str) -> bool:
        """Does ``text`` state what the paper should have printed: the same statement as the
        correction, and true by the check's computation?"""
        return bool(self.agrees(text)) and self.holds(text)

    @property
    def checked(self) -> str:
        """The text in the check's notation that stands for what the paper prints."""
        return self.reading or self.printed

    @property
    def check(self) -> str:
        return f"{TEST}::test_manifestation[{self.id}]"


@dataclass(frozen=True)
class Cause:
    """A root cause, its manifestations and its demonstration."""

    id: str
    title: str
    status: str
    kind: str
    evidence: str
    manifestations: tuple[Manifestation, ...] = ()
    severity: str = ""
    consequence: str = ""
    rests_on: tuple[str, ...] = ()
    extra: Callable = field(default=lambda: True, repr=False, compare=False)
    decided_by: tuple[str, ...] = ()
    """Uncertain: the paper's records of what it lacks (type ``lost``) that would decide
    between the readings (counting rule 5): lost in extraction, or never printed (the record's
    ``provenance``, :data:`analysis.papers.data.PROVENANCE`)."""

    def __post_init__(self) -> None:
        if (self.status == "uncertain") != bool(self.decided_by):
            raise ValueError(f"cause {self.id}: an uncertain cause, and only one, names the lost "
                             f"data that would decide it (decided_by)")  # fmt: skip
        if not _ID.match(self.id) or "/" in self.id:
            raise ValueError(f"cause id {self.id!r}: lowercase words joined by '-'")
        if self.status not in STATUSES:
            raise ValueError(f"cause {self.id}: status {self.status!r} not in {STATUSES}")
        if self.kind not in KINDS:
            raise ValueError(f"cause {self.id}: kind {self.kind!r} not in {KINDS}")
        if self.status in COUNTED and (self.severity not in SEVERITIES or not self.consequence):
            raise ValueError(f"cause {self.id}: a counted cause needs a severity and consequence")
        for m in self.manifestations:
            if not m.id.startswith(self.id + "/") or not _ID.match(m.id):
                raise ValueError(f"manifestation {m.id!r} must be named {self.id}/<slug>")

    @property
    def check(self) -> str:
        return f"{TEST}::test_cause[{self.id}]"

    @property
    def locations(self) -> str:
        return "; ".join(dict.fromkeys(m.location for m in self.manifestations))

    def demonstrate(self, texts: Mapping[str, str] | None = None) -> bool:
        """The cause's test, on the printed texts (or on ``texts``: manifestation id -> text in
        place of the printed one). A finding: every printed text fails and every correction
        passes. Uncertain: each manifestation's readings differ in verdict. Holds: every printed
        text passes."""
        texts = texts or {}
        ms = self.manifestations
        if self.status == "holds":
            return all(m.holds(texts.get(m.id, m.checked)) for m in ms) and self.extra()
        if self.status == "uncertain":  # the print's readings differ (with a text printed: one)
            return all(
                len({m.holds(t) for t in ((texts[m.id],) if m.id in texts else m.readings)}) == 2
                for m in ms
            ) and self.extra()
        return (
            bool(ms)
            and all(not m.holds(texts.get(m.id, m.checked)) and m.verify(m.corrected) for m in ms)
            and self.extra()
        )


@dataclass(frozen=True)
class Register:
    """The causes found in one paper, its summary and the changes against earlier versions."""

    paper: str
    title: str
    causes: tuple[Cause, ...]
    summary: Mapping = field(default_factory=dict)
    changes: tuple[Mapping, ...] = ()
    findings: tuple[str, ...] = ()
    """What the records' audit cannot account for, one line each (a failing record no cause
    explains, a passing one a counted cause names, a printed record without a check):
    :func:`analysis.audit.records.audit`. Empty when the register explains the paper."""
    record_counts: Mapping = field(default_factory=dict)
    """Units of the paper's printed records checked, passing, failing, explained, given."""

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
        for m in self.cause(mid.split("/")[0]).manifestations:
            if m.id == mid:
                return m
        raise ValueError(f"register {self.paper} has no manifestation {mid!r}")

    @property
    def manifestations(self) -> tuple[Manifestation, ...]:
        return tuple(m for c in self.causes for m in c.manifestations)

    def counts(self) -> dict[str, int]:
        """Causes per status (every status present, zero included)."""
        return {s: sum(c.status == s for c in self.causes) for s in STATUSES}

    @property
    def n_manifestations(self) -> int:
        return sum(len(c.manifestations) for c in self.causes if c.status != "holds")

    def rows(self) -> list[dict[str, str]]:
        """The CSV rows: each cause, then its manifestations (the checks that hold are the
        item table's, not rows here)."""
        out = []
        for c in self.causes:
            if c.status == "holds" and len(c.manifestations) > 3:
                shown = ()
            else:
                shown = c.manifestations
            out.append({
                "id": c.id, "cause": "", "status": c.status, "kind": c.kind,
                "severity": c.severity, "location": c.locations or "(the paper as a whole)",
                "printed": "", "reading": "", "corrected": "", "alternatives": "",
                "rests_on": "; ".join(c.rests_on), "evidence": f"{c.title} {c.evidence}".strip(),
                "check": c.check, "tolerance": "",
            })  # fmt: skip
            for m in shown:
                out.append({
                    "id": m.id, "cause": c.id, "status": c.status, "kind": c.kind,
                    "severity": c.severity, "location": m.location, "printed": m.printed,
                    "reading": m.reading, "corrected": m.corrected,
                    "alternatives": " | ".join(m.alternatives), "rests_on": "; ".join(m.rests_on),
                    "evidence": m.evidence, "check": m.check, "tolerance": m.tolerance,
                })  # fmt: skip
        return out

    def csv_text(self) -> str:
        buf = io.StringIO()
        w = csv.DictWriter(buf, fieldnames=list(COLUMNS), lineterminator="\n")
        w.writeheader()
        w.writerows(self.rows())
        return buf.getvalue()


def read_rows(path) -> list[dict[str, str]]:
    """Read and validate a register CSV (see :func:`validate_rows`)."""
    with open(path, newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        header = tuple(reader.fieldnames or ())
        rows = list(reader)
    if header != COLUMNS:
        raise ValueError(f"{path}: columns {list(header)}; expected {list(COLUMNS)}")
    validate_rows(rows, str(path))
    return rows


def validate_rows(rows: list[dict[str, str]], where: str = "register") -> None:
    """Raise ValueError naming the line of a row that breaks the schema."""
    causes: dict[str, str] = {}
    seen: set[str] = set()
    for n, r in enumerate(rows, start=2):
        if None in r or None in r.values():
            raise ValueError(f"{where} line {n}: {len(COLUMNS)} fields expected")
        rid = r["id"].strip()
        if not rid or rid in seen or not _ID.match(rid):
            raise ValueError(f"{where} line {n}: id {rid!r} is empty, malformed or duplicated")
        seen.add(rid)
        if r["status"] not in STATUSES or r["kind"] not in KINDS:
            raise ValueError(f"{where} line {n} ({rid}): status or kind not in the schema")
        if r["status"] in COUNTED and r["severity"] not in SEVERITIES:
            raise ValueError(f"{where} line {n} ({rid}): severity {r['severity']!r}")
        if not r["check"].startswith(TEST + "::") or not r["location"].strip():
            raise ValueError(f"{where} line {n} ({rid}): no test id or no location")
        if r["cause"]:
            if r["cause"] not in causes or not rid.startswith(r["cause"] + "/"):
                raise ValueError(f"{where} line {n} ({rid}): not under its cause")
            if r["status"] != causes[r["cause"]] or not r["printed"] or not r["corrected"]:
                raise ValueError(f"{where} line {n} ({rid}): status or texts missing")
        elif "/" in rid:
            raise ValueError(f"{where} line {n} ({rid}): a cause id has no '/'")
        else:
            causes[rid] = r["status"]
