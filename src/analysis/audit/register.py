"""The registers of every paper, built from their data files, and what is generated from them.

``data/registers/<paper>.toml`` holds a paper's causes, manifestations, statuses, kinds, check
specs, evidence templates and its ``[summary]``; :func:`register` builds the
:class:`~analysis.audit.schema.Register` (each manifestation's ``verify`` is its check kind,
:mod:`analysis.audit.kinds`; each template filled from what the checks and the paper's facts
computed). Generated from the registers: ``data/errata/<paper>.csv``, seed 000's item table
``data/errata/grabber_items.csv``, the README block between ``<!-- errata:begin -->`` and
``<!-- errata:end -->`` (:func:`render_markdown`) and the site's tables. :func:`check` names the
generated files that differ; a cache keyed by the hash of every input (the data files, the
package's source) answers it without building the registers when nothing changed.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import re
import tomllib
from functools import cache
from pathlib import Path

from analysis.audit import records
from analysis.audit.render import headline, render_paper
from analysis.audit.schema import (
    COUNTING_RULE,
    Cause,
    Manifestation,
    Register,
    check_summary,
)
from analysis.paths import PROJECT, build_dir, data_dir

__all__ = [
    "BEGIN",
    "END",
    "answers",
    "audit_file",
    "available",
    "build",
    "cached_answers",
    "changed_inputs",
    "check",
    "check_is_cached",
    "compare",
    "coverage",
    "each_cells",
    "findings",
    "generated",
    "headline",
    "items_table",
    "load",
    "markdown",
    "register",
    "register_path",
    "render_markdown",
    "source_path",
    "write_all",
]  # fmt: skip

BEGIN, END = "<!-- errata:begin -->", "<!-- errata:end -->"
ITEM_COLUMNS = ("id", "location", "verdict", "kind", "printed", "derived", "evidence", "check",
                "tolerance")  # appended: outside checks read the columns in order
VERDICT = {"error": "wrong", "omission": "wrong", "unsupported": "wrong", "holds": "holds"}


def available() -> tuple[str, ...]:
    """Papers (:func:`analysis.papers.names`) whose register ``data/registers/<paper>.toml``
    exists in this checkout, in the papers' order."""
    from analysis.papers import names

    return tuple(p for p in names() if source_path(p).is_file())


def register_path(paper: str) -> Path:
    """The generated CSV of ``paper``'s register."""
    return data_dir() / "errata" / f"{paper}.csv"


def source_path(paper: str) -> Path:
    """The register's data file, ``data/registers/<paper>.toml``."""
    return data_dir() / "registers" / f"{paper}.toml"


class _Namespace:
    """``{facts.name}`` in a template: the paper's computed facts, by name."""

    def __init__(self, get):
        self._get = get

    def __getattr__(self, name):
        return self._get(name)


class _Checked:
    """``{m[<manifestation id>].printed.value}`` in a summary template: what a manifestation's
    check computed on the printed text (``printed``) and on the correction (``corrected``)."""

    def __init__(self, causes) -> None:
        self._ms = {m.id: m for c in causes for m in c.manifestations}

    def __getitem__(self, mid: str):
        if mid not in self._ms:
            raise KeyError(f"no manifestation {mid!r}")
        m = self._ms[mid]
        return _Namespace({"printed": m.result(m.checked), "corrected": m.result(m.corrected)}
                          .__getitem__)  # fmt: skip


def _printed(spec, paper) -> str:
    """The printed text a manifestation names: a reference, references, a network order."""
    if isinstance(spec, str):
        if not spec.startswith("@"):
            raise ValueError(f"printed {spec!r}: a reference into the paper ('@id') expected")
        text = paper.text(spec[1:])
        rec = paper.record(spec[1:].split("[")[0].split(":")[0].split("#")[0])
        if rec.type == "listing":  # the transcription's '//' notes are not printed
            text = "\n".join(ln.split("//")[0].rstrip() for ln in text.splitlines())
        if rec.type == "extracted":  # nor are the extraction's pinyin glosses, e.g. 運(yùn)
            text = re.sub(r"\([a-zāáǎàēéěèīíǐìōóǒòūúǔùǖǘǚǜü]+\)", "", text)
        return text.strip("\n")
    if isinstance(spec, list):
        return "\n".join(_printed(s, paper) for s in spec)
    if "excerpt" in spec:
        if spec["excerpt"] not in _printed(spec["of"], paper):
            raise ValueError(f"{spec['excerpt']!r} is not printed in {spec['of']}")
        return spec["excerpt"]
    if "order" in spec:
        return "network order " + ", ".join(r.removeprefix("@figure") for r in spec["order"])
    raise ValueError(f"printed {spec!r} is not a reference")


def _location(spec, paper, given: str | None) -> str:
    if given:
        return given
    if isinstance(spec, dict) and "of" in spec:
        spec = spec["of"]
    refs = [spec] if isinstance(spec, str) else spec if isinstance(spec, list) else spec["order"]
    out = []
    for r in refs:
        m = re.match(r"@([^\[\]:#]+)(?:\[(\d+),(\d+)\]|\[(\w+)\]\.(\w+))?", r)
        loc = paper.record(m[1]).location
        if m[2]:
            loc = f"{loc} row {m[2]} col {m[3]}"
        elif m[4]:
            loc = f"{loc.split(',')[0].split(' ')[0]} {loc.split(' ')[1]} row {m[4]} {m[5]}"
        out.append(loc)
    return "; ".join(dict.fromkeys(out))


def _manifestation(cause: dict, m: dict, ctx, check, by_ref=None) -> Manifestation:
    """A manifestation of ``cause``: its own ``check``, or the check its printed unit carries
    in the paper (``by_ref``: unit reference -> :class:`~analysis.audit.records.Unit`), the
    reading too."""
    paper = ctx.paper
    unit = (by_ref or {}).get(m["printed"]) if isinstance(m["printed"], str) else None
    if "check" not in m:
        if unit is None or unit.spec is None:
            raise ValueError(f"{cause['id']}/{m['id']}: no check, and {m['printed']!r} is no "
                             "checked unit of the paper")  # fmt: skip
        m = {**m, "check": dict(unit.spec)}
        if "reading" not in m and unit.text != paper.text(m["printed"][1:]):
            m["reading"] = unit.text  # the record's check reads the print this way
    spec = m["check"]
    printed = _printed(m["printed"], paper)
    holds = cause["status"] == "holds"
    corrected = m.get("corrected", (m.get("reading") or printed) if holds else "")
    memo: dict[str, object] = {}

    def result(text: str):
        if text not in memo:
            memo[text] = check(spec, text, ctx)
        return memo[text]

    from analysis.audit.equivalence import same

    declared = (corrected, *m.get("equivalent", ()))

    def agrees(text: str) -> bool:
        return any(same(text, ref, spec, ctx) for ref in declared if ref)

    readings = tuple(m.get("readings", ()))
    mm = Manifestation(
        id=f"{cause['id']}/{m['id']}", cause=cause["id"], status=cause["status"],
        location=_location(m["printed"], paper, m.get("location")), printed=printed,
        corrected=corrected, reading=m.get("reading", ""), readings=readings,
        alternatives=tuple(m.get("alternatives", ())),
        rests_on=tuple(m.get("rests_on", cause.get("rests_on", ()))),
        equivalent=tuple(m.get("equivalent", ())), source=repr(m["printed"]) if not
        isinstance(m["printed"], str) else m["printed"], spec=spec, result=result, agrees=agrees,
    )  # fmt: skip
    ns = {
        "printed": result(mm.checked), "corrected": result(corrected),
        "facts": _Namespace(ctx.fact), "readings": [result(t) for t in readings],
    }  # fmt: skip
    try:
        evidence = m.get("evidence", "").format_map(ns)
        rests_on = tuple(t.format_map(ns) for t in mm.rests_on)
    except (AttributeError, KeyError, IndexError, TypeError, ValueError) as exc:
        raise ValueError(
            f"{mm.id}: evidence template needs {exc!r}; printed check gave {ns['printed']}, "
            f"corrected {ns['corrected']}"
        ) from None
    return _with(mm, evidence=evidence, rests_on=rests_on)


def _with(m: Manifestation, **changes) -> Manifestation:
    from dataclasses import replace

    return replace(m, **changes)


def each_cells(e: dict, paper):
    """(slug, reference, location, cell spec) of every cell a ``[[cause.each]]`` names: the
    cells of a printed matrix, or the given columns of every row of a printed table."""
    if "matrix" in e:
        rec = paper.record(e["matrix"])
        for i, row in enumerate(rec["rows"][: e.get("rows", 4)], start=1):
            for j in range(1, len(row) + 1):
                yield (f"{rec.id.lower().replace('_', '-')}-r{i}c{j}", f"@{rec.id}[{i},{j}]",
                       f"{rec.location} row {i} col {j}", {"cells": [[i, j]]})  # fmt: skip
    else:
        rec = paper.record(e["table"])
        for r in paper.table_rows(rec.id):
            for c in e["columns"]:
                yield (f"{rec.id.replace('_', '-')}-r{r}-{c.replace('_', '-')}", f"@{rec.id}[{r}].{c}",  # noqa: E501
                       f"{rec.location.split(',')[0]} row {r} {c}", {"row": r, "column": c})


def _each(cause: dict, e: dict, ctx, check, explained: set[str], by_ref) -> list[Manifestation]:
    """The printed cells a ``holds`` cause's ``[[cause.each]]`` names: one manifestation per
    cell, but for the cells another cause explains (its manifestations name them,
    ``explained``). A cell that fails its check and that no cause explains is an error naming
    the cell: none is dropped."""
    out = []
    for slug, ref, where, cell in each_cells(e, ctx.paper):
        if ref in explained:
            continue
        m = {"id": slug, "printed": ref, "location": where}
        if "check" in e:
            m["check"] = {**e["check"], **cell}
        mm = _manifestation(cause, m, ctx, check, by_ref)
        if not mm.holds(mm.printed):
            raise ValueError(
                f"unexplained: {ctx.paper.id} {where} ({ref}): the printed cell fails its check "
                f"({cause['id']}, [[cause.each]]) and no cause explains it"
            )
        out.append(mm)
    return out


def _also(cause: dict, ctx, check):
    """The cause's further demonstration: claims over its paper that must hold."""
    specs = cause.get("also", ())

    def extra() -> bool:
        return all(check({"kind": "claim"}, s, ctx).ok for s in specs)

    return extra


@cache
def register(paper: str) -> Register:
    """The register of ``paper``, built from its data file (cached; takes seconds). A paper of
    ``data/papers`` without a register file has an empty one: its failing records are
    unexplained (:attr:`Register.findings`)."""
    from analysis.audit.context import context
    from analysis.papers import names

    if paper not in names():
        raise ValueError(f"no paper {paper!r}; expected one of {', '.join(names())}")
    path = source_path(paper)
    raw = tomllib.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}
    return build(context(paper), raw)


def audit_file(paper_path, register_path=None) -> Register:
    """The register of a paper outside ``data/`` (a paper being added, a test's example): its
    data file, and its register file if there is one yet; checked by the shared kinds."""
    from analysis.audit.context import Context, bespoke
    from analysis.papers import load_file

    paper = load_file(Path(paper_path).resolve())
    raw = tomllib.loads(Path(register_path).read_text(encoding="utf-8")) if register_path else {}
    return build(Context(paper, bespoke(paper.id, paper)), raw)


def build(ctx, raw: dict) -> Register:
    """The register of the paper of context ``ctx`` from its register data ``raw`` (the parsed
    ``data/registers/<paper>.toml``; ``{}``: no cause written yet), every printed record held
    against it (:func:`analysis.audit.records.audit`)."""
    from analysis.audit.kinds import check

    paper = ctx.paper.id
    causes = []
    by_ref = {u.ref: u for u in records.units(ctx.paper)}
    named = {c["id"]: [_manifestation(c, m, ctx, check, by_ref) for m in c.get("manifestation", ())]
             for c in raw.get("cause", ())}  # fmt: skip
    explained = {m.source for ms in named.values() for m in ms}
    for c in raw.get("cause", ()):
        ms = named[c["id"]] + [x for e in c.get("each", ()) for x in _each(c, e, ctx, check, explained, by_ref)]  # noqa: E501
        ns = {"facts": _Namespace(ctx.fact)}
        if ms:  # a cause's template may name its first manifestation's checks
            ns.update(printed=ms[0].result(ms[0].checked), corrected=ms[0].result(ms[0].corrected))
        try:
            title, evidence, consequence = (c[k].format_map(ns) if k in c else ""
                                            for k in ("title", "evidence", "consequence"))
            rests_on = tuple(t.format_map(ns) for t in c.get("rests_on", ()))
        except (AttributeError, KeyError, IndexError, TypeError, ValueError) as exc:
            raise ValueError(f"{c['id']}: evidence template needs {exc!r}; {ns}") from None
        causes.append(
            Cause(
                id=c["id"], title=title, status=c["status"], kind=c["kind"],
                evidence=evidence, manifestations=tuple(ms),
                severity=c.get("severity", ""), consequence=consequence,
                rests_on=rests_on, extra=_also(c, ctx, check),
                decided_by=tuple(c.get("decided_by", ())),
            )
        )
    summary: dict = {}
    if "summary" in raw:  # a register being written may have none yet (its tests ask for one)
        check_summary(paper, raw["summary"])
        ns = {"facts": _Namespace(ctx.fact), "m": _Checked(causes)}
        try:
            summary = {k: v.format_map(ns) for k, v in raw["summary"].items()}
        except (AttributeError, KeyError, IndexError, TypeError, ValueError) as exc:
            raise ValueError(f"register {paper}: [summary] template needs {exc!r}") from None
    title = raw.get("register", {}).get("title", ctx.paper.title)
    memo: dict = {}

    def holds(u) -> bool:
        key = (repr(sorted(u.spec.items())), u.text)
        if key not in memo:
            memo[key] = check(u.spec, u.text, ctx).ok
        return memo[key]

    findings, counts = records.audit(ctx.paper, [m for c in causes for m in c.manifestations], holds)  # noqa: E501
    return Register(paper, title, tuple(causes), summary, tuple(raw.get("change", ())),
                    tuple(f.message for f in findings), counts)  # fmt: skip


def manifestations():
    """Every manifestation of every paper's register (the audit API, a contract)."""
    for p in available():
        yield from register(p).manifestations


def load(paper: str = "grabber"):
    """A paper's register file as a validated DataFrame (for reports and notebooks)."""
    import pandas as pd

    from analysis.audit.schema import COLUMNS, read_rows

    return pd.DataFrame(read_rows(register_path(paper)), columns=list(COLUMNS))


# --- the item table: every printed item checked, from the register --------------------------
def items_table(paper: str = "grabber") -> list[dict[str, str]]:
    """Every checked printed item of a paper: the manifestations of its causes (verdict from
    the cause's status) and the checks that hold; one source with the register."""
    reg = register(paper)
    return [
        {"id": m.id, "location": m.location, "verdict": VERDICT.get(c.status, c.status),
         "kind": c.kind, "printed": m.printed, "derived": m.corrected,
         "evidence": m.evidence or c.title, "check": m.check, "tolerance": m.tolerance}
        for c in reg.causes
        for m in c.manifestations
    ]


def compare(paper: str, *records: str):
    """The checked items printed in the given records (``"eq12"``, ``"T3"``: every manifestation
    whose printed text is a reference into one of them), printed beside corrected, with the
    verdict and the evidence: a DataFrame indexed by manifestation id (for notebooks)."""
    import pandas as pd

    def refs(src: str) -> set[str]:
        return {m[1] for m in re.finditer(r"@([^\[\]:#',}]+)", src)}

    rows = [dict(r, cause=r["id"].split("/")[0]) for r, m in
            zip(items_table(paper), register(paper).manifestations, strict=True)
            if refs(m.source) & set(records)]  # fmt: skip
    cols = ["cause", "verdict", "printed", "derived", "evidence"]
    return pd.DataFrame(rows, columns=["id", *cols]).set_index("id")


def coverage(paper: str = "grabber"):
    """Items per verdict, and wrong items per kind of cause (two DataFrames)."""
    import pandas as pd

    rows = items_table(paper)
    order = ["holds", "wrong", "uncertain", "notation", "extraction"]
    verdicts = pd.Series([r["verdict"] for r in rows]).value_counts().reindex(order, fill_value=0)
    kinds = pd.Series([r["kind"] for r in rows if r["verdict"] == "wrong"]).value_counts()
    return verdicts.rename("items").to_frame(), kinds.rename("wrong items").to_frame()


def _csv(rows, columns) -> str:
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(columns), lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
    return buf.getvalue()


# --- generated files, and the cache that answers errata --------------------------------------
def _inputs() -> dict[str, str]:
    """Every input of the generated files, each with its hash: the package's source, ``data/``
    (without the generated errata) and the README outside the block."""
    src = Path(__file__).resolve().parents[1]
    files = sorted(src.rglob("*.py")) + sorted(
        p for p in data_dir().rglob("*") if p.is_file() and "errata" not in p.parts
    )
    out = {str(p.relative_to(PROJECT) if p.is_relative_to(PROJECT) else p):
           hashlib.sha256(p.read_bytes()).hexdigest() for p in files}  # fmt: skip
    readme = PROJECT / "README.md"
    if readme.exists():
        out["README.md (outside the block)"] = hashlib.sha256(
            _outside_block(readme.read_text(encoding="utf-8")).encode()).hexdigest()  # fmt: skip
    return out


def _inputs_hash(inputs: dict[str, str] | None = None) -> str:
    h = hashlib.sha256()
    for k, v in sorted((inputs or _inputs()).items()):
        h.update(f"{k}\0{v}\0".encode())
    return h.hexdigest()


def _outside_block(text: str) -> str:
    head, _, rest = text.partition(BEGIN)
    return head + rest.partition(END)[2]


def generated(papers=None) -> dict[Path, str]:
    """Every file the registers of ``papers`` generate (default: all): path -> content. The
    README block lists every paper, so it is generated only when all are selected."""
    papers = list(papers or available())
    out = {register_path(p): register(p).csv_text() for p in papers}
    if "grabber" in papers:
        out[data_dir() / "errata" / "grabber_items.csv"] = _csv(items_table(), ITEM_COLUMNS)
    if set(papers) >= set(available()):
        readme = PROJECT / "README.md"
        out[readme] = readme_text(readme)
    return out


_KEEP = 32
"""Answers kept per data folder (one per selection of papers and state of the inputs)."""


def _cache_dir() -> Path:
    """The answers' cache, one per data folder (a test's copy of data/ keeps its own, so that
    what changed is said against the same folder's last build)."""
    key = hashlib.sha256(str(data_dir().resolve()).encode()).hexdigest()[:12]
    return build_dir() / "errata-cache" / key


def _audited(papers) -> list[str]:
    """The papers whose records a selection audits: the selection, or with every register
    selected, every paper of data/papers (one without a register has all to explain)."""
    from analysis.papers import names

    return list(names()) if set(papers) >= set(available()) else list(papers)


def _answers(papers, inputs: dict[str, str], files: dict[Path, str] | None = None) -> dict:
    """What ``errata`` answers for ``papers`` (built now): the generated files' digests, the
    records' findings and the README block; stored under the hash of ``inputs``."""
    files = generated(papers) if files is None else files
    out = {
        "digests": {str(p): hashlib.sha256(t.encode()).hexdigest() for p, t in files.items()},
        "findings": [f for p in _audited(papers) for f in register(p).findings],
        "markdown": render_markdown(papers),
    }
    d = _cache_dir()
    d.mkdir(parents=True, exist_ok=True)
    key = f"{_inputs_hash(inputs)}-{'-'.join(papers)}"
    (d / f"{key}.json").write_text(json.dumps(out, ensure_ascii=False), encoding="utf-8")
    (d / "inputs.json").write_text(json.dumps(inputs), encoding="utf-8")
    stored = sorted((p for p in d.glob("*-*.json")), key=lambda p: p.stat().st_mtime)
    for old in stored[:-_KEEP]:  # bounded: the newest answers only
        old.unlink(missing_ok=True)
    return out


def cached_answers(papers=None) -> dict | None:
    """The stored answers for ``papers`` if no input changed since they were built, else None
    (reads files and hashes them: well under a second)."""
    papers = list(papers or available())
    path = _cache_dir() / f"{_inputs_hash()}-{'-'.join(papers)}.json"
    return json.loads(path.read_text(encoding="utf-8")) if path.exists() else None


def changed_inputs() -> list[str]:
    """The inputs that changed since the registers were last built (what a rebuild is for)."""
    last = _cache_dir() / "inputs.json"
    if not last.exists():
        return ["(no earlier build from this data folder)"]
    before = json.loads(last.read_text(encoding="utf-8"))
    now = _inputs()
    return sorted(k for k in before.keys() | now.keys() if before.get(k) != now.get(k))


def answers(papers=None) -> dict:
    """The answers for ``papers``: stored, or built now (see :func:`changed_inputs`)."""
    papers = list(papers or available())
    return cached_answers(papers) or _answers(papers, _inputs())


def write_all(papers=None) -> list[str]:
    """Rewrite every register CSV, the item table and the README block; what changed."""
    from analysis.safe_io import write_many_atomic

    papers = list(papers or available())
    files = generated(papers)
    changed = {p: t for p, t in files.items() if not p.exists() or p.read_text("utf-8") != t}
    if changed:
        write_many_atomic(changed, make_parents=True)
    _answers(papers, _inputs(), files)  # the README is an input: hashed after it is written
    return sorted(str(p.relative_to(PROJECT)) for p in changed)


def check_is_cached(papers=None) -> bool:
    """Can :func:`check` answer from the cache (no input changed since the last build)?"""
    return cached_answers(papers) is not None


def check(papers=None) -> list[str]:
    """The generated files that are missing or out of date (empty: all current). Answered
    from the cache when every input is unchanged since the registers were last built."""
    stale = []
    for p, d in answers(papers)["digests"].items():
        path = Path(p)
        if not path.exists() or hashlib.sha256(path.read_bytes()).hexdigest() != d:
            stale.append(str(path.relative_to(PROJECT)))
    return sorted(stale)


def findings(papers=None) -> list[str]:
    """What the records' audit cannot account for in ``papers`` (empty: every printed record
    checked, every failure explained), from the cache when no input changed."""
    return list(answers(papers)["findings"])


def markdown(papers=None) -> str:
    """The README block of ``papers``, from the cache when no input changed."""
    return answers(papers)["markdown"]


def render_markdown(papers=None) -> str:
    """The README block: the counting rule, then each paper's headline, summary and causes."""
    papers = papers or available()
    blocks = [
        "_Generated from `data/registers/` by `python -m analysis errata --write`; do not edit "
        "by hand._",
        "",
        "**Counting rule** (every paper): " + " ".join(COUNTING_RULE),
        "",
    ]
    blocks += [render_paper(register(p)) for p in papers]
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
