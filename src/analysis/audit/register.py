"""The registers of every paper: build, write, check, render (the ``errata`` command).

Each paper's audit module provides ``register()`` returning a
:class:`~analysis.audit.schema.Register` (:data:`PAPERS`). This module writes them to
``data/errata/<paper>.csv`` (the schema of :mod:`analysis.audit.schema`), writes seed 000's
item-level audit to ``data/errata/grabber_items.csv``, and renders the README block between
``<!-- errata:begin -->`` and ``<!-- errata:end -->``: per paper a headline that counts
causes, and the causes with their manifestations beneath. ``check()`` names the files that
differ from what the audits generate (the CI keeps them current).
"""

from __future__ import annotations

import csv
import importlib
import importlib.util
import io
from functools import cache
from pathlib import Path

from analysis.audit.schema import COUNTED, STATUSES, Register, read_rows
from analysis.paths import PROJECT, data_dir

__all__ = [
    "BEGIN",
    "END",
    "PAPERS",
    "check",
    "load",
    "register",
    "register_path",
    "render_markdown",
    "write_all",
]

PAPERS: dict[str, str] = {
    "grabber": "analysis.audit.grabber_causes",
    "palletizer": "analysis.audit.palletizer_causes",
    "picker": "analysis.audit.picker_causes",
    "gr1": "analysis.audit.gr1_causes",
}
"""Paper name -> the module whose ``register()`` builds its register."""
BEGIN, END = "<!-- errata:begin -->", "<!-- errata:end -->"


def available() -> tuple[str, ...]:
    """Papers whose audit module exists in this checkout."""
    return tuple(p for p, m in PAPERS.items() if importlib.util.find_spec(m) is not None)


@cache
def register(paper: str) -> Register:
    """The register of one paper (built by its audit; cached)."""
    if paper not in PAPERS:
        raise ValueError(f"no paper {paper!r}; expected one of {', '.join(PAPERS)}")
    return importlib.import_module(PAPERS[paper]).register()


def register_path(paper: str) -> Path:
    return data_dir() / "errata" / f"{paper}.csv"


def load(paper: str = "grabber"):
    """A paper's register file as a validated DataFrame (for reports and notebooks)."""
    import pandas as pd

    from analysis.audit.schema import COLUMNS

    return pd.DataFrame(read_rows(register_path(paper)), columns=list(COLUMNS))


def _items_text() -> str:
    from analysis.audit.grabber_audit import AUDIT_COLUMNS, audit_table

    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(AUDIT_COLUMNS), lineterminator="\n")
    w.writeheader()
    w.writerows(audit_table())
    return buf.getvalue()


def _generated(papers=None) -> dict[Path, str]:
    """Every file the audits of ``papers`` generate (default: all): path -> content.

    The README block lists every paper, so it is generated only when all are selected: from
    some papers alone it would drop the others' rows."""
    papers = list(papers or available())
    out = {register_path(p): register(p).csv_text() for p in papers}
    if "grabber" in papers:
        out[data_dir() / "errata" / "grabber_items.csv"] = _items_text()
    if set(papers) >= set(available()):
        readme = PROJECT / "README.md"
        out[readme] = readme_text(readme)
    return out


def write_all(papers=None) -> list[str]:
    """Rewrite every register, the item audit and the README block; return what changed."""
    from analysis.app.safe_io import write_many_atomic

    files = _generated(papers)
    changed = {p: t for p, t in files.items() if not p.exists() or p.read_text("utf-8") != t}
    if changed:
        write_many_atomic(changed, make_parents=True)
    return sorted(str(p.relative_to(PROJECT)) for p in changed)


def check(papers=None) -> list[str]:
    """The generated files that are missing or out of date (empty: all current)."""
    files = _generated(papers)
    stale = [p for p, t in files.items() if not p.exists() or p.read_text("utf-8") != t]
    return sorted(str(p.relative_to(PROJECT)) for p in stale)


# ---------------------------------------------------------------------------------------------
# README
# ---------------------------------------------------------------------------------------------
def _md(s: str, limit: int | None = None) -> str:
    s = " ".join(str(s).split())
    if limit and len(s) > limit:
        s = s[: limit - 1] + "…"
    return s.replace("|", "\\|")


def _n(n: int, status: str) -> str:
    return f"{n} {_SINGULAR[status] if n == 1 else _PLURAL[status]}"


_SINGULAR = {
    "error": "error",
    "omission": "omission",
    "unsupported": "unsupported claim",
    "uncertain": "reading the extraction leaves uncertain",
    "notation": "notation variant",
    "extraction": "extraction artefact",
    "holds": "audited claim that holds",
}
_PLURAL = {
    "error": "errors",
    "omission": "omissions",
    "unsupported": "unsupported claims",
    "uncertain": "readings the extraction leaves uncertain",
    "notation": "notation variants",
    "extraction": "extraction artefacts",
    "holds": "audited claims that hold",
}


def headline(reg: Register) -> str:
    """The count of causes (by status) and of the places they show."""
    c = reg.counts()
    against = [_n(c[s], s) for s in COUNTED if c[s]]
    apart = [_n(c[s], s) for s in STATUSES if s not in COUNTED and c[s]]
    shown = sum(len(x.manifestations) for x in reg.causes if x.status in COUNTED)
    text = (
        f"**{sum(c[s] for s in COUNTED)} root causes against the paper** "
        f"({', '.join(against)}), shown in {shown} places."
    )
    if apart:
        text += " Listed apart, not counted: " + ", ".join(apart) + "."
    return text


def render_paper(reg: Register) -> str:
    lines = [
        f"### {reg.title}",
        "",
        headline(reg),
        f"Register: `data/errata/{reg.paper}.csv` (one row per cause, its manifestations "
        "beneath; every row names its test).",
        "",
        "| cause | status | kind | what | where |",
        "|---|---|---|---|---|",
    ]
    order = {s: i for i, s in enumerate(STATUSES)}
    for c in sorted(reg.causes, key=lambda c: order[c.status]):
        where = f"{len(c.manifestations)}: " + _md(c.locations, 90) if c.manifestations else ""
        lines.append(f"| `{c.id}` | {c.status} | {c.kind} | {_md(c.title, 140)} | {where} |")
    return "\n".join(lines) + "\n"


def render_markdown(papers=None) -> str:
    """The README block: each paper's headline and causes."""
    papers = papers or available()
    blocks = [
        "_Generated from the audits by `python -m analysis errata --write`; do not edit by hand._",
        "",
    ]
    for p in papers:
        blocks.append(render_paper(register(p)))
        if p == "grabber":  # its uncertain readings right under its table
            from analysis.papers import grabber as paper

            blocks += [
                "Left undecidable by the text extraction of seed 000 (`analysis.papers.grabber."
                "UNCERTAIN`):",
                "",
                *[f"- **{_md(k)}**: {_md(v)}" for k, v in paper.UNCERTAIN.items()],
                "",
            ]
    return "\n".join(blocks)


def readme_text(readme: Path | None = None, papers=None) -> str:
    """The README with its errata block regenerated."""
    path = readme or PROJECT / "README.md"
    text = path.read_text(encoding="utf-8")
    if BEGIN not in text or END not in text:
        raise ValueError(f"{path} has no '{BEGIN}' ... '{END}' block to fill")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    return f"{head}{BEGIN}\n{render_markdown(papers)}{END}{tail}"
