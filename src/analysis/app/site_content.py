"""The report site's generated pages (MyST Markdown) and its downloads.

:mod:`analysis.app.report` executes the notebooks and runs Sphinx; this module writes what
Sphinx reads besides the executed notebooks (those :mod:`analysis.app.site_notebooks`
prepares):

* ``index.md``: the front page, rendered from :func:`analysis.app.frontpage.front_page_data`;
* ``register.md``: the errata register (:func:`analysis.audit.register.render_markdown`);
* ``figures.md``: every figure the notebooks saved, grouped by notebook, with its caption;
* ``downloads.md``: the generated PLC programs and memory maps, the register CSVs, the
  Table 4 audit CSV, the executed notebooks (and the PDF when one was printed).

The names of :mod:`analysis.app.site_notebooks` (captions, notebook pages) and
:mod:`analysis.app.site_explorer` (the explorer without a kernel) are importable from here.
"""

from __future__ import annotations

import hashlib
import tomllib
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from analysis.app.frontpage import PaperVerdict, Verdict
from analysis.app.site_explorer import explorer_figure, static_explorer_html
from analysis.app.site_notebooks import (
    CAPTIONS_TOML,
    MISSING_CAPTION,
    WIDGET_MIME,
    figure_captions,
    figure_md,
    figure_numbers,
    md_code,
    md_inline,
    md_role,
    prepare_notebook,
    saved_stems,
    shown_order,
)
from analysis.escape import html_text

__all__ = [
    "CAPTIONS_TOML",
    "MISSING_CAPTION",
    "WIDGET_MIME",
    "Download",
    "downloads_md",
    "explorer_figure",
    "figure_captions",
    "figures_md",
    "front_page_md",
    "glance_html",
    "md_inline",
    "prepare_notebook",
    "register_md",
    "saved_stems",
    "shown_order",
    "static_explorer_html",
    "write_downloads",
]

PROJECT = Path(__file__).resolve().parents[3]
SITE = PROJECT / "docs" / "site"
CITATIONS_TOML = SITE / "citations.toml"


# --------------------------------------------------------------------------------------------
# pages
# --------------------------------------------------------------------------------------------
def _md_table(df: pd.DataFrame) -> str:
    """A GFM pipe table (MyST renders it, Sphinx search indexes it)."""
    show_index = df.index.name is not None
    cols = ([df.index.name] if show_index else []) + [str(c) for c in df.columns]

    def cell(v) -> str:
        return md_inline(" ".join(str(v).split()))

    rows = [
        ([cell(i)] if show_index else []) + [cell(v) for v in r]
        for i, r in zip(df.index, df.itertuples(index=False), strict=True)
    ]
    lines = ["| " + " | ".join(cell(c) for c in cols) + " |", "|" + "---|" * len(cols)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines) + "\n"


def _evidence(links: Iterable[tuple[str, str]], titles: dict[str, str]) -> str:
    parts = []
    for page, label in links:
        if page.startswith("notebooks/"):
            stem = page.split("/", 1)[1]
            if stem not in titles:  # not part of this build
                parts.append(f"notebook {md_inline(stem)}")
                continue
            label = titles[stem]
            label = label if label.startswith(stem[:2]) else f"{stem[:2]} · {label}"
        parts.append(f"{{doc}}`{md_role(label)} </{page}>`")
    return "**Evidence:** " + " · ".join(parts)


def citations() -> dict[str, dict]:
    """The four papers' full citations (``docs/site/citations.toml``), by register name."""
    with CITATIONS_TOML.open("rb") as fh:
        return {p["register"]: p for p in tomllib.load(fh)["paper"]}


def cite(paper: str) -> str:
    """One paper's citation as MyST inline text."""
    c = citations()[paper]
    return f"{md_inline(c['authors'])}. *{md_inline(c['title'])}*. {md_inline(c['venue'])}."


def _html_table(df: pd.DataFrame, wrong: pd.DataFrame | None = None, cls: str = "") -> str:
    """``df`` as an HTML table (index shown if named); cells where ``wrong`` is True get the
    class ``wrong-cell`` (highlighted), their rows ``wrong-row``. One line, so that MyST
    passes it through as a raw HTML block."""
    import html

    show_index = df.index.name is not None
    cols = ([df.index.name] if show_index else []) + [str(c) for c in df.columns]
    head = "".join(f"<th>{html.escape(c)}</th>" for c in cols)
    rows = []
    for k, (i, r) in enumerate(df.iterrows()):
        bad = wrong.iloc[k] if wrong is not None else None
        cells = [f"<th>{html.escape(str(i))}</th>"] if show_index else []
        for j, v in enumerate(r):
            attr = ' class="wrong-cell"' if bad is not None and bool(bad.iloc[j]) else ""
            text = html.escape(" ".join(str(v).split()))
            cells.append(f"<td{attr}>{text}</td>")
        attr = ' class="wrong-row"' if bad is not None and bool(bad.any()) else ""
        rows.append(f"<tr{attr}>{''.join(cells)}</tr>")
    return (
        f'<div class="table-wrapper verdict-table-wrap"><table class="verdict-table {cls}">'
        f"<thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table></div>\n"
    )


NO_SUMMARY = (
    "The register of this paper carries no `[summary]` yet: its verdict in words (what breaks "
    "the robot, what is cosmetic) and what to take away are register data (issue 20), shown "
    "here when they are there. Nothing on this page writes a verdict of its own."
)
NOT_RANKED = (
    "The register gives these causes no severities yet, so they are listed in its order, not "
    "ranked by consequence; each links to its row in the register."
)


SEVERITY_WORDS = {"breaks": "breaks", "wrong-result": "wrong result", "misleading": "misleads",
                  "cosmetic": "cosmetic"}  # fmt: skip
"""How the glance table heads each severity (the register's words, shortened to fit)."""


def glance_html(papers: list[PaperVerdict]) -> str:
    """The four verdicts at a glance, first on the front page and on page 1 of the PDF: one
    row per paper with its headline, its counted causes per severity, the worst consequence
    in numbers and a link to its section below (one line of HTML: a raw block for MyST)."""
    import html

    e = html.escape
    sev = [s for s, _ in papers[0].severities] if papers else []
    head = (
        "<thead><tr><th>paper</th><th>verdict</th>"
        + "".join(f'<th class="glance-n">{e(SEVERITY_WORDS.get(s, s))}</th>' for s in sev)
        + "<th>worst consequence</th></tr></thead>"
    )
    rows = []
    for v in papers:
        counts = "".join(
            f'<td class="glance-n glance-{e(s)}{" glance-zero" if n == 0 else ""}">{n}</td>'
            for s, n in v.severities
        )
        rows.append(
            f'<tr id="glance-{e(v.paper)}"><th><a class="reference internal" '
            f'href="#{e(v.anchor)}">Seed&nbsp;{e(v.seed)}</a>'
            f'<span class="glance-system">{e(v.system)}</span></th>'
            f'<td class="glance-verdict">{e(v.headline or "(no headline in the register)")}</td>'
            f"{counts}<td class=\"glance-worst\">{e(v.worst or '')}</td></tr>"
        )
    return (
        '<div class="table-wrapper glance-wrap"><table class="glance">'
        '<caption>The four papers at a glance: counted causes by severity (each cause once, '
        'however many places it shows in); the details follow below.</caption>'
        f"{head}<tbody>{''.join(rows)}</tbody></table></div>\n"
    )


def _paper_md(v: PaperVerdict, titles: dict[str, str]) -> list[str]:
    c = citations().get(v.paper)
    out = [f"({v.anchor})=", f"### Seed {v.seed}: {md_inline(v.system)}", ""]
    if c:
        out += [f"{cite(v.paper)}", ""]
    if v.verdict:
        out += [":::{important}", f"**Verdict.** {v.verdict}", ":::", ""]
    else:
        out += [":::{note}", NO_SUMMARY, ":::", ""]
    take = [f"{{doc}}`{md_role(label)} </{page}>`" for page, label in v.artefacts]
    out += [
        "**Take away:** " + (f"{v.take_away} " if v.take_away else "") + " · ".join(take),
        "",
    ]
    f = v.findings.copy()
    if not f.empty:
        f["cause"] = [f"{x}" for x in f["cause"]]
        if not v.ranked:
            out += [f"*{NOT_RANKED}*", ""]
            f = f.drop(columns=["severity", "consequence"])
        wrong = pd.DataFrame(False, index=f.index, columns=f.columns)
        if "severity" in f:
            wrong["severity"] = f["severity"].isin(["breaks", "wrong-result"])
        out += [_html_table(f.set_index("cause"), wrong.drop(columns="cause"), "findings"), ""]
    links = (("register", "the register"), (f"notebooks/{v.notebook}", v.notebook[:2]))
    out += [_evidence(links, titles), ""]
    return out


def front_page_md(
    sections: list[Verdict | PaperVerdict],
    captions: dict[str, str],
    homes: dict[str, str],
    titles: dict[str, str],
    intro: str,
    toc: dict[str, list[str]],
    problems: dict[str, str] | None = None,
) -> str:
    """``index.md``: title, intro, one section per :class:`Verdict`, then the contents.

    ``homes`` maps a figure stem to the notebook page that shows it (for the link back),
    ``titles`` a notebook stem to its title, ``toc`` a toctree caption to its documents,
    ``problems`` what failed in this build (shown first, in an error box).
    """
    papers = [s for s in sections if isinstance(s, PaperVerdict)]
    numbers = figure_numbers(captions)
    out = ["# Audit of four robot-kinematics papers", ""]
    if papers:
        out += [glance_html(papers), ""]
    out += [intro, ""]
    if problems:
        out += [":::{error}", "**This build is incomplete.**", ""]
        for what, why in problems.items():
            where = (
                f"{{doc}}`{md_role(titles[what])} </notebooks/{what}>`" if what in titles else what
            )
            out.append(f"- {where}: `{md_code(why)}`")
        out += [":::", ""]
    heads = [h for s in sections if isinstance(s, Verdict) for h in s.headline]
    if heads:
        out += ["## The strongest findings", "", *(f"- {h}" for h in heads), ""]
    if papers:
        out += ["## What is wrong, how bad, what to take away", ""]
        for v in papers:
            out += _paper_md(v, titles)
    for s in sections:
        if isinstance(s, PaperVerdict):
            continue
        out += [f"## {s.title}", ""]
        if s.counts:
            cards = "".join(
                f'<div class="verdict-count"><span class="verdict-number">{n:,}</span>'
                f'<span class="verdict-label">{label}</span></div>'
                for label, n in s.counts
            )
            out += [f'<div class="verdict-counts">{cards}</div>', ""]
        out += [s.verdict, ""]
        if s.table is not None:
            shown = _html_table(s.table, s.wrong) if s.wrong is not None else _md_table(s.table)
            out += [shown, ""]
        for stem in s.figures:
            if stem in captions:
                home = homes.get(stem)
                where = (
                    f"{{ref}}`notebook {home.split('/')[-1][:2]} <fig-{stem}>`" if home else None
                )
                out.append(
                    figure_md(
                        stem, captions[stem], name=False, number=numbers[stem], evidence=where
                    )
                )
        out += [_evidence(s.evidence, titles), ""]
    if CITATIONS_TOML.exists():
        out += ["## The four papers", ""]
        for paper, c in citations().items():
            out.append(f"- **Seed {c['seed']}.** {cite(paper)} ({md_inline(c['source'])})")
        out.append("")
    for caption, docs in toc.items():
        out += ["```{toctree}", f":caption: {caption}", ":maxdepth: 1", "", *docs, "```", ""]
    return "\n".join(out)


def register_md() -> str:
    """``register.md``: the README's audit block and every register row with its test."""
    from analysis.audit import register

    body = register.render_markdown().splitlines()
    if body and body[0].startswith("_Generated"):
        body = body[1:]
    out = [
        "# The errata register",
        "",
        "Each root cause the audit found is stated once, with every place it shows in the "
        "paper (its manifestations); each has the test that proves it. Long texts are "
        "shortened here; the CSV files on the {doc}`downloads page </downloads>` have them "
        "in full.",
        "",
        "## Root causes, paper by paper",
        *body,
        "",
    ]
    for paper in register.available():
        reg = register.load(paper)
        out += [
            f"## Every row of `data/errata/{paper}.csv` and its test",
            "",
            "A cause row has no *cause*; its manifestations name it. The test (a `pytest` "
            "node id) fails if the printed form were right.",
            "",
            _md_table(reg[["id", "cause", "status", "check"]].set_index("id")),
        ]
    return "\n".join(out)


def figures_md(captions: dict[str, str], homes: dict[str, str], titles: dict[str, str]) -> str:
    """``figures.md``: every saved figure, grouped by notebook number, with its caption."""
    out = [
        "# Figures",
        "",
        "Every figure the notebooks saved in this build, with its caption; SVG and PNG "
        "downloads under each.",
        "",
    ]
    numbers = figure_numbers(captions)  # the catalogue's order: these numbers in turn
    by_nb: dict[str, list[str]] = {}
    for stem in numbers:
        by_nb.setdefault(stem[:2], []).append(stem)
    for num, stems in sorted(by_nb.items()):
        nb = next((t for t in titles if t.startswith(num)), None)
        head = titles[nb] if nb else f"Notebook {num}"
        head = head if head.startswith(num) else f"{num} · {head}"
        out += [f"## {md_inline(head)}", ""]
        for stem in stems:
            home = homes.get(stem)
            where = f"{{ref}}`notebook {num} <fig-{stem}>`" if home else None
            out.append(
                figure_md(stem, captions[stem], name=False, number=numbers[stem], evidence=where)
            )
    return "\n".join(out)


# --------------------------------------------------------------------------------------------
# downloads
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Download:
    """A file offered on the downloads page (``path`` relative to the site source)."""

    path: str
    group: str
    what: str
    how: str = ""
    at_root: bool = False
    """Served at the site's root under its own name (``build/report/report.pdf``, a path that
    does not change between builds) instead of under ``_downloads/<hash>/``."""


def write_downloads(src: Path) -> list[Download]:
    """Write the PLC programs, memory maps and audit CSVs under ``src/downloads``."""
    import shutil

    from analysis.audit import register
    from analysis.audit.papers.grabber import table4
    from analysis.kinematics.arm import paper_arm
    from analysis.paths import data_dir
    from analysis.plc.generate import generate

    dl = src / "downloads"
    (dl / "plc").mkdir(parents=True, exist_ok=True)
    (dl / "data").mkdir(parents=True, exist_ok=True)
    items = []
    for dialect, kind in (("s7-200", "S7-200 STL (Micro/WIN text)"), ("s7-300", "S7-300 AWL")):
        prog, mmap = f"plc/ik_{dialect}.awl", f"plc/ik_{dialect}_map.json"
        text, mjson = generate(paper_arm(), dialect)
        (dl / prog).write_text(text, encoding="utf-8", newline="")
        (dl / mmap).write_text(mjson, encoding="utf-8")
        how = (
            f"python -m analysis stl --dialect {dialect} -o ik_{dialect}.awl "
            f"--map ik_{dialect}_map.json"
        )
        items += [
            Download(prog, "PLC programs", f"Corrected IK program (front-up), {kind}", how),
            Download(
                mmap,
                "PLC programs",
                f"Memory map of the {dialect.upper()} program: every input/output address "
                "(MAP.json)",
                how,
            ),
        ]
    for paper in register.available():
        name = f"{paper}.csv"
        shutil.copyfile(register.register_path(paper), dl / "data" / name)
        what = (
            f"The errata register of {register.register(paper).title}: each root cause, its "
            "manifestations beneath, every row with the test that proves it"
        )
        items.append(Download(f"data/{name}", "Audit tables", what, f"data/errata/{name}"))
    items_csv = data_dir() / "errata" / "grabber_items.csv"
    if items_csv.exists():
        shutil.copyfile(items_csv, dl / "data" / items_csv.name)
        items.append(
            Download(
                f"data/{items_csv.name}",
                "Audit tables",
                "Every audited printed item of seed 000 with its verdict (items that hold too)",
                f"data/errata/{items_csv.name}",
            )
        )
    table4.report_table().to_csv(dl / "data" / "table4_audit.csv")
    items.append(
        Download(
            "data/table4_audit.csv",
            "Audit tables",
            "Table 4 row by row: printed and corrected angles, FK error, verdict and cause",
            "analysis.audit.papers.grabber.table4.report_table()",
        )
    )
    return items


def downloads_md(src: Path, items: list[Download]) -> str:
    """``downloads.md``: one table per group, each file with its size and SHA-256."""
    out = [
        "# Downloads",
        "",
        "Everything below was generated by this build. Sizes in bytes; the SHA-256 digest "
        "lets you check a copy.",
        "",
    ]
    groups: dict[str, list[Download]] = {}
    for it in items:
        groups.setdefault(it.group, []).append(it)
    for group, rows in groups.items():
        out += [
            f"## {group}",
            "",
            "| file | what | bytes | SHA-256 | made by |",
            "|---|---|---|---|---|",
        ]
        for it in rows:
            f = src / "downloads" / it.path
            data = f.read_bytes()
            name = Path(it.path).name
            link = (
                f'<a class="reference download" href="{html_text(name)}" '
                f'download="{html_text(name)}">'
                f'<code class="docutils literal notranslate">{html_text(name)}</code></a>'
                if it.at_root
                else f"{{download}}`{name} </downloads/{it.path}>`"
            )
            out.append(
                f"| {link} | {md_inline(it.what)} "
                f"| {len(data):,} | `{hashlib.sha256(data).hexdigest()}` "
                f"| {'`' + it.how + '`' if it.how else ''} |"
            )
        out.append("")
    return "\n".join(out)
