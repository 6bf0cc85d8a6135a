"""One record type for the findings of the companion-paper audits (seeds 001 and 002).

A :class:`Finding` is one printed statement judged against a derivation or a run:
``(id, location, printed, corrected, kind, evidence)`` plus a verdict. The papers' registers
(:mod:`analysis.audit.schema`) are built from them; a finding's kind is one of the schema's
:data:`~analysis.audit.schema.KINDS`.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

from analysis.audit.schema import KINDS

__all__ = ["KINDS", "VERDICTS", "Finding", "as_rows"]

VERDICTS: tuple[str, ...] = ("holds", "wrong", "undecidable")


@dataclass(frozen=True)
class Finding:
    """One printed item and its verdict.

    ``printed`` and ``corrected`` are short texts (SymPy syntax where they are formulas);
    ``evidence`` says how the verdict was reached, with the numbers of the run.
    """

    id: str
    location: str
    printed: str
    corrected: str
    kind: str
    evidence: str
    verdict: str = "wrong"

    def __post_init__(self) -> None:
        if self.kind and self.kind not in KINDS:
            raise ValueError(f"finding {self.id}: kind {self.kind!r} not in {KINDS}")
        if self.verdict not in VERDICTS:
            raise ValueError(f"finding {self.id}: verdict {self.verdict!r} not in {VERDICTS}")
        if self.verdict == "wrong" and not (self.kind and self.corrected):
            raise ValueError(f"finding {self.id}: a wrong item needs a kind and a correction")


def as_rows(findings) -> list[dict[str, str]]:
    """Findings as plain dicts (CSV/DataFrame rows)."""
    return [asdict(f) for f in findings]
