"""The errata register: every printed item of the paper checked by machine.

:func:`audit` holds each printed item of :mod:`analysis.papers.grabber` against its derivation
(:mod:`analysis.kinematics.dh`, :mod:`analysis.kinematics.arm`, :mod:`analysis.audit.table4`,
:mod:`analysis.plc.stl_eval`; the checks themselves are in :mod:`analysis.audit.grabber_checks` and
:mod:`analysis.audit.grabber_stl`) and returns one :class:`Item` per printed statement with a
computed verdict: ``simplify(printed - derived) == 0`` for symbolic items, a numeric
counterexample (or its absence over seeded samples) for formulas with inverse
trigonometric functions, recomputation for tables, evaluation for STL.

Every item carries a ``verify(text) -> bool`` predicate: the register test
(``tests/audit/test_register.py::test_erratum[<id>]``) asserts that the *corrected* text of a
register row passes it and the *printed* text fails it, so a wrong correction fails.

Files
-----
``data/errata.csv``
    The register, one row per discrepancy: ``id, location, printed, corrected, kind,
    check``. Rows whose id starts with ``paper-`` are generated here; any other rows
    (``plc-...`` from the PLC audit) are kept as they are by :func:`write_all`.
``data/paper_audit.csv``
    Every audited item with its verdict (coverage: items that hold are listed too).

Command line: ``python -m analysis.audit.register --write`` rewrites both files and the README
block between ``<!-- errata:begin -->`` and ``<!-- errata:end -->``; ``--check`` exits 1
if any of them differs from what the audit generates.
"""

from __future__ import annotations

import argparse
import csv
import io
import re
import sys
from functools import cache
from pathlib import Path

import numpy as np
import sympy as sp

from analysis.audit.grabber_checks import (
    KINDS,
    OWN_PREFIX,
    PXYZ,
    TH,
    Item,
    _parse_eq,
    all_items,
    derived_matrices,
)
from analysis.audit.grabber_checks import S as S
from analysis.kinematics.params import data_dir, paper_params
from analysis.papers import grabber as paper

__all__ = [
    "COLUMNS",
    "KINDS",
    "OWN_PREFIX",
    "Item",
    "audit",
    "audit_table",
    "closed_form_ik",
    "compare",
    "corrected_closed_form",
    "coverage",
    "derived_matrices",
    "item",
    "load",
    "load_register",
    "register_rows",
    "render_markdown",
    "write_all",
]


COLUMNS: tuple[str, ...] = ("id", "location", "printed", "corrected", "kind", "check")
AUDIT_COLUMNS = ("id", "location", "verdict", "kind", "printed", "derived", "evidence", "check")
_CHECK_RE = re.compile(r"^tests/(\w+/)*test_\w+\.py::\w+(\[[^\]]+\])?$")
BEGIN, END = "<!-- errata:begin -->", "<!-- errata:end -->"


@cache
def audit() -> tuple[Item, ...]:
    """Every printed item with its verdict, in paper order (cached; takes seconds).

    See :mod:`analysis.audit.grabber_checks` for the checks; raises ``RuntimeError`` on duplicate
    ids.
    """
    items = all_items()
    ids = [it.id for it in items]
    if len(set(ids)) != len(ids):
        raise RuntimeError(
            "duplicate audit ids: " + ", ".join(sorted({i for i in ids if ids.count(i) > 1}))
        )
    return tuple(items)


def item(item_id: str) -> Item:
    """One audit item by id (raises ``ValueError`` for an unknown id)."""
    for it in audit():
        if it.id == item_id:
            return it
    raise ValueError(f"no audit item {item_id!r}")


def corrected_closed_form() -> dict[str, sp.Expr]:
    """The corrected IK of eqs. 6, 10, 19 as SymPy expressions in Px, Py, Pz, L1..L3.

    Built from the register's corrected texts (items ``paper-eq6``, ``paper-eq10``,
    ``paper-eq19``): theta1 substituted into eq. 10, theta1 and theta3 into eq. 19.
    """

    def rhs(item_id: str) -> sp.Expr:
        return _parse_eq(item(item_id).corrected)[1]

    t1 = rhs("paper-eq6")
    t3 = rhs("paper-eq10").subs(TH[0], t1)
    t2 = rhs("paper-eq19").subs({TH[0]: t1, TH[2]: t3})
    return {"theta1": t1, "theta2": t2, "theta3": t3}


def closed_form_ik(p, params=None) -> np.ndarray:
    """Evaluate :func:`corrected_closed_form` for targets (..., 3) [mm] -> (..., 3) [rad].

    theta2 is wrapped to (-pi, pi] like :meth:`analysis.kinematics.arm.Arm.solve`; NaN outside the
    reach (acos of a value beyond +-1). Vectorised through ``sympy.lambdify``.
    """
    prm = params or paper_params()
    p = np.asarray(p, dtype=float)
    cf = corrected_closed_form()
    args = (*PXYZ, S["L1"], S["L2"], S["L3"])
    vals = (p[..., 0], p[..., 1], p[..., 2], prm.L1, prm.L2, prm.L3)
    with np.errstate(invalid="ignore"):
        out = [
            np.asarray(sp.lambdify(args, cf[k], "numpy")(*vals), dtype=float)
            * np.ones(p.shape[:-1])
            for k in ("theta1", "theta2", "theta3")
        ]
    out[1] = np.mod(out[1] + np.pi, 2 * np.pi) - np.pi
    out[1] = np.where(out[1] == -np.pi, np.pi, out[1])
    return np.stack(out, axis=-1)


def compare(*selectors: str):
    """Printed beside derived, with verdict and evidence, as a DataFrame (for notebooks).

    Each selector is an item id or an id prefix (``"paper-eq12"`` selects all eq. 12 items).
    """
    import pandas as pd

    rows = [it for it in audit() if any(it.id == s or it.id.startswith(s + "-") for s in selectors)]
    if not rows:
        raise ValueError(f"no audit item matches {selectors!r}")
    return pd.DataFrame(
        [
            {
                "location": it.location,
                "printed": it.printed,
                "derived": it.derived,
                "verdict": it.verdict,
                "evidence": it.evidence,
            }
            for it in rows
        ],
        index=pd.Index([it.id for it in rows], name="id"),
    )


def coverage():
    """Counts of items per verdict and of wrong items per kind (two DataFrames)."""
    import pandas as pd

    items = audit()
    verdicts = (
        pd.Series([it.verdict for it in items])
        .value_counts()
        .reindex(["holds", "wrong", "undecidable"], fill_value=0)
    )
    kinds = (
        pd.Series([it.kind for it in items if it.verdict == "wrong"])
        .value_counts()
        .reindex(list(KINDS), fill_value=0)
    )
    return verdicts.rename("items").to_frame(), kinds.rename("wrong items").to_frame()


# --------------------------------------------------------------------------------------------
# files
# --------------------------------------------------------------------------------------------
def register_rows() -> list[dict[str, str]]:
    """The register rows this module owns (``paper-*``), one per wrong item."""
    return [
        {
            "id": it.id,
            "location": it.location,
            "printed": it.printed,
            "corrected": it.corrected,
            "kind": it.kind,
            "check": it.check,
        }
        for it in audit()
        if it.verdict == "wrong"
    ]


def audit_table() -> list[dict[str, str]]:
    """Every audited item as a row of ``data/paper_audit.csv``."""
    return [
        {
            "id": it.id,
            "location": it.location,
            "verdict": it.verdict,
            "kind": it.kind,
            "printed": it.printed,
            "derived": it.derived,
            "evidence": it.evidence,
            "check": it.check,
        }
        for it in audit()
    ]


def _read_csv(path: Path) -> list[dict[str, str]]:
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _csv_text(rows: list[dict[str, str]], columns) -> str:
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(columns), lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
    return buf.getvalue()


def load_register(path: str | Path | None = None) -> list[dict[str, str]]:
    """Read and validate ``data/errata.csv`` (own and foreign rows alike).

    Raises ``ValueError`` naming the row for: wrong columns, duplicate or empty ids, an
    empty field, a ``kind`` outside :data:`KINDS`, a ``check`` that is not a pytest node
    id (``tests/test_<name>.py::<test>[<param>]``).
    """
    path = Path(path) if path is not None else data_dir() / "errata.csv"
    with path.open(newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        if tuple(reader.fieldnames or ()) != COLUMNS:
            raise ValueError(f"{path}: columns {reader.fieldnames}; expected {list(COLUMNS)}")
        rows = list(reader)
    seen = set()
    for n, row in enumerate(rows, start=2):
        rid = (row.get("id") or "").strip()
        if not rid or rid in seen:
            raise ValueError(f"{path} line {n}: id {rid!r} is empty or duplicated")
        seen.add(rid)
        for col in COLUMNS:
            if not (row.get(col) or "").strip():
                raise ValueError(f"{path} line {n} ({rid}): column {col!r} is empty")
        if row["kind"] not in KINDS:
            raise ValueError(
                f"{path} line {n} ({rid}): kind {row['kind']!r} is not one of {list(KINDS)}"
            )
        if not _CHECK_RE.match(row["check"]):
            raise ValueError(
                f"{path} line {n} ({rid}): check {row['check']!r} is not a test node id "
                "like tests/audit/test_register.py::test_erratum[paper-eq5]"
            )
    return rows


def load(path: str | Path | None = None):
    """The register ``data/errata.csv`` as a validated DataFrame (columns :data:`COLUMNS`).

    For reports; see :func:`load_register` for the checks (raises ``ValueError``).
    """
    import pandas as pd

    return pd.DataFrame(load_register(path), columns=list(COLUMNS))


def register_text(path: str | Path | None = None) -> str:
    """What ``data/errata.csv`` must contain: own rows regenerated, foreign rows kept."""
    path = Path(path) if path is not None else data_dir() / "errata.csv"
    foreign = (
        [r for r in _read_csv(path) if not r["id"].startswith(OWN_PREFIX)] if path.exists() else []
    )
    return _csv_text(
        register_rows() + [{c: r.get(c, "") for c in COLUMNS} for r in foreign], COLUMNS
    )


def _md(s: str, limit: int | None = None) -> str:
    s = str(s).replace("\n", " ")
    if limit and len(s) > limit:
        s = s[: limit - 1] + "…"
    return s.replace("|", "\\|")


def render_markdown(register_path: str | Path | None = None) -> str:
    """The README's "What the audit found" block, generated from the audit and the register.

    Long printed/corrected texts are shortened here (the register has them in full).
    """
    items = audit()
    n = len(items)
    by_verdict = {
        v: sum(it.verdict == v for it in items) for v in ("holds", "wrong", "undecidable")
    }
    path = Path(register_path) if register_path else data_dir() / "errata.csv"
    rows = load_register(path) if path.exists() else register_rows()
    own = [r for r in rows if r["id"].startswith(OWN_PREFIX)]
    kinds = {
        k: (sum(r["kind"] == k for r in own), sum(r["kind"] == k for r in rows)) for k in KINDS
    }
    groups = {}
    for it in items:
        g = (
            it.location.split(" row ")[0].split(" (")[0]
            if it.location.startswith(("eq.", "Table", "sec."))
            else it.location
        )
        groups.setdefault(g, [0, 0])
        groups[g][0] += 1
        groups[g][1] += it.verdict == "holds"
    lines = [
        "_Generated from `data/errata.csv` and `data/paper_audit.csv` by "
        "`python -m analysis.audit.register --write`; do not edit by hand._",
        "",
        f"**{by_verdict['holds']} of {n} printed items hold; {by_verdict['wrong']} are wrong"
        + (f", {by_verdict['undecidable']} undecidable" if by_verdict["undecidable"] else "")
        + ".** "
        f"An item is one matrix entry, equation, table cell, claim in the text or STL finding. "
        f"The register (`data/errata.csv`) has {len(rows)} rows ({len(own)} from the paper audit"
        + (
            f", {len(rows) - len(own)} from the PLC execution checks"
            if len(rows) > len(own)
            else ""
        )
        + "), each with the test that proves it.",
        "",
        "| kind | paper audit | all register rows |",
        "|---|---|---|",
        *[f"| {k} | {a} | {b} |" for k, (a, b) in kinds.items() if b],
        "",
        "| id | location | printed | corrected | kind |",
        "|---|---|---|---|---|",
        *[
            f"| {_md(r['id'])} | {_md(r['location'])} | `{_md(r['printed'], 70)}` | `{_md(r['corrected'], 70)}` "  # noqa: E501
            f"| {_md(r['kind'])} |"
            for r in rows
        ],
        "",
        "Left undecidable by the text extraction (see `analysis.papers.grabber.UNCERTAIN`):",
        "",
        *[f"- **{_md(k)}**: {_md(v)}" for k, v in paper.UNCERTAIN.items()],
    ]
    return "\n".join(lines) + "\n"


def readme_text(readme: str | Path | None = None) -> tuple[str, str]:
    """(current README text, README text with the errata block regenerated)."""
    path = Path(readme) if readme is not None else data_dir().parent / "README.md"
    text = path.read_text(encoding="utf-8")
    if BEGIN not in text or END not in text:
        raise ValueError(f"{path} has no '{BEGIN}' ... '{END}' block to fill")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    return text, f"{head}{BEGIN}\n{render_markdown()}{END}{tail}"


def write_all(*, readme: bool = True) -> list[str]:
    """Rewrite ``data/errata.csv``, ``data/paper_audit.csv`` and (optionally) the README block.

    Returns the names of the files that changed.
    """
    changed = []
    reg = data_dir() / "errata.csv"
    new = register_text(reg)
    if not reg.exists() or reg.read_text(encoding="utf-8") != new:
        reg.write_text(new, encoding="utf-8")
        changed.append("data/errata.csv")
    aud = data_dir() / "paper_audit.csv"
    new = _csv_text(audit_table(), AUDIT_COLUMNS)
    if not aud.exists() or aud.read_text(encoding="utf-8") != new:
        aud.write_text(new, encoding="utf-8")
        changed.append("data/paper_audit.csv")
    if readme:
        old, new = readme_text()
        if old != new:
            (data_dir().parent / "README.md").write_text(new, encoding="utf-8")
            changed.append("README.md")
    return changed


def main(argv: list[str] | None = None) -> int:
    """``python -m analysis.audit.register [--write | --write-readme | --check]``."""
    ap = argparse.ArgumentParser(
        prog="python -m analysis.audit.register", description=__doc__.splitlines()[0]
    )
    g = ap.add_mutually_exclusive_group()
    g.add_argument(
        "--write",
        action="store_true",
        help="rewrite errata.csv, paper_audit.csv and the README block",
    )
    g.add_argument("--write-readme", action="store_true", help="rewrite only the README block")
    g.add_argument(
        "--check", action="store_true", help="exit 1 if any generated file is out of date"
    )
    args = ap.parse_args(argv)
    try:
        if args.write:
            print("\n".join(write_all()) or "up to date")
        elif args.write_readme:
            old, new = readme_text()
            if old != new:
                (data_dir().parent / "README.md").write_text(new, encoding="utf-8")
            print("README.md " + ("rewritten" if old != new else "up to date"))
        elif args.check:
            stale = []
            reg = data_dir() / "errata.csv"
            if not reg.exists() or reg.read_text(encoding="utf-8") != register_text(reg):
                stale.append("data/errata.csv")
            aud = data_dir() / "paper_audit.csv"
            if not aud.exists() or aud.read_text(encoding="utf-8") != _csv_text(
                audit_table(), AUDIT_COLUMNS
            ):
                stale.append("data/paper_audit.csv")
            old, new = readme_text()
            if old != new:
                stale.append("README.md")
            if stale:
                print("out of date: " + ", ".join(stale), file=sys.stderr)
                return 1
            print("up to date")
        else:
            print(render_markdown(), end="")
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
