"""The report site's generated pages, figure captions and downloads (MyST Markdown).

:mod:`analysis.app.report` executes the notebooks and runs Sphinx; this module writes what
Sphinx reads besides the executed notebooks:

* ``index.md``: the front page, rendered from :func:`analysis.app.frontpage.front_page_data`;
* ``register.md``: the errata register (:func:`analysis.audit.register.render_markdown`);
* ``figures.md``: every figure the notebooks saved, grouped by notebook, with its caption;
* ``downloads.md``: the generated PLC programs and memory maps, the register CSVs, the
  Table 4 audit CSV, the executed notebooks (and the PDF when one was printed);

and it prepares each executed notebook for the site (:func:`prepare_notebook`): a figure
that a cell saved with :func:`analysis.app.plotting.save_figure` is shown as a numbered
figure with its caption and SVG/PNG links, in place of the inline image and the printed
file names; widget outputs, which need a kernel, become a note.

Figure captions come from data, never from file names (:func:`figure_captions`): the sidecar
``<stem>.json`` that ``save_figure(..., caption=...)`` writes, else the entry for the stem in
``docs/site/captions.toml``. A figure with neither is shown with a visible
"caption missing" notice (and the browser tests fail on it).
"""

from __future__ import annotations

import hashlib
import json
import re
import tomllib
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import nbformat
import pandas as pd

from analysis.app.frontpage import PaperVerdict, Verdict

__all__ = [
    "CAPTIONS_TOML",
    "MISSING_CAPTION",
    "Download",
    "downloads_md",
    "figure_captions",
    "figures_md",
    "front_page_md",
    "glance_html",
    "prepare_notebook",
    "register_md",
    "saved_stems",
    "static_explorer_html",
    "write_downloads",
]

PROJECT = Path(__file__).resolve().parents[3]
SITE = PROJECT / "docs" / "site"
CAPTIONS_TOML = SITE / "captions.toml"
CITATIONS_TOML = SITE / "citations.toml"
MISSING_CAPTION = "Caption missing: pass caption=... to save_figure() for"
WIDGET_MIME = "application/vnd.jupyter.widget-view+json"
WIDGET_NOTE = (
    "*Interactive controls (sliders, branch picker, FK mode). A static page has no Python "
    "kernel to drive them: run `make lab` and open `notebooks/{name}` to use them.*"
)
EXPLORER_NOTE = (
    "The explorer, here without a kernel: the same controls drive the arm through its "
    "closed form printed as JavaScript (`analysis.app.explore_js`, from the recording that "
    "the numpy and compiled solvers run; the browser tests hold it to Python within 1e-9). "
    "Drag the 3D view to rotate it, scroll to zoom. With a kernel (`make lab`, "
    "`notebooks/{name}`) it also shows the pulse error and the manipulability."
)
# what ``print(save_figure(fig, stem))`` prints: ['05-workspace-xz.svg', '05-workspace-xz.png']
_SAVED = re.compile(r"^\['(?P<stem>\d\d-[^'\s/]+)\.svg', '(?P=stem)\.png'\]\s*$", re.M)


# --------------------------------------------------------------------------------------------
# captions
# --------------------------------------------------------------------------------------------
def figure_captions(fig_dir: Path, fallback: Path | None = CAPTIONS_TOML) -> dict[str, str]:
    """Caption of every figure (``<stem>.png``) in ``fig_dir``; '' where none is recorded.

    The sidecar ``<stem>.json`` written by ``save_figure(..., caption=...)`` wins; else
    ``[captions]`` in ``fallback`` (TOML, stem = caption).
    """
    table: dict[str, str] = {}
    if fallback is not None and Path(fallback).exists():
        with Path(fallback).open("rb") as fh:
            table = {str(k): str(v) for k, v in tomllib.load(fh).get("captions", {}).items()}
    out = {}
    for png in sorted(Path(fig_dir).glob("*.png")):
        side = png.with_suffix(".json")
        caption = ""
        if side.exists():
            caption = str(json.loads(side.read_text(encoding="utf-8")).get("caption", ""))
        out[png.stem] = " ".join((caption or table.get(png.stem, "")).split())
    return out


def _code(text: str) -> str:
    """Text that can sit between single backticks (an inline literal)."""
    return " ".join(text.replace("`", "'").split())[:300]


def _role(text: str) -> str:
    """Link text inside a role (``{doc}`text <target>```): no backticks or angle brackets."""
    return " ".join(text.replace("`", "'").replace("<", "‹").replace(">", "›").split())


def _inline(text: str) -> str:
    """Plain text as MyST inline content (no markup, roles or maths triggered)."""
    return re.sub(r"([\\`*_\[\]<>{}$|#])", r"\\\1", text)


def _figure(stem: str, caption: str, *, name: bool, evidence: str | None = None) -> str:
    """A MyST figure: the PNG, its caption, SVG/PNG downloads, optionally where it comes from."""
    cap = _inline(caption) if caption else f"**{MISSING_CAPTION} `{stem}`.**"
    alt = caption.replace("\n", " ") if caption else f"figure {stem} (no caption recorded)"
    # the PNG is the preview on the page; the vector file is the one download
    links = f"{{download}}`SVG </figures/{stem}.svg>`"
    if evidence:
        links += f" · in {evidence}"
    lines = [
        f":::{{figure}} /figures/{stem}.png",
        *([f":name: fig-{stem}"] if name else []),
        f":alt: {alt}",
        "",
        f"{cap} ({links})",
        ":::",
        "",
    ]
    return "\n".join(lines)


# --------------------------------------------------------------------------------------------
# notebooks
# --------------------------------------------------------------------------------------------
def saved_stems(cell: nbformat.NotebookNode) -> list[str]:
    """Figure stems a code cell saved, from the names ``print(save_figure(...))`` printed."""
    stems: list[str] = []
    for o in cell.get("outputs", []):
        if o.get("output_type") == "stream":
            for m in _SAVED.finditer(o.get("text", "")):
                if m["stem"] not in stems:
                    stems.append(m["stem"])
    return stems


def prepare_notebook(
    nb: nbformat.NotebookNode,
    name: str,
    captions: dict[str, str],
    *,
    seconds: float | None = None,
    failure: str | None = None,
) -> tuple[nbformat.NotebookNode, list[str]]:
    """A copy of an executed notebook for the site, and the figure stems it places.

    * a code cell that saved figures (in ``captions``, i.e. found in the figure folder)
      loses the printed file names and its inline images (when there are no more images
      than saved figures: they are the same figures), and is followed by a Markdown cell
      with one captioned figure per stem, labelled ``fig-<stem>``;
    * every code cell is tagged ``hide-input``: its code is hidden behind MyST-NB's toggle
      ("Show code cell source") and never printed (``report.css``);
    * widget outputs become a note (a static page has no kernel), the explorer's becomes the
      explorer without a kernel (:func:`static_explorer_html`);
    * after the first heading, a note says the notebook was executed for this build and
      links the executed ``.ipynb``; if it raised (``failure``), an error box at the top says so.

    ``nb`` itself is not modified.
    """
    nb = nbformat.from_dict(json.loads(json.dumps(nb)))  # deep copy
    nb.metadata.pop("widgets", None)
    cells, placed = [], []
    for cell in nb.cells:
        cells.append(cell)
        if cell.cell_type != "code":
            continue
        tags = cell.metadata.setdefault("tags", [])
        if "hide-input" not in tags:  # code hidden by default: MyST-NB's "Show code" toggle
            tags.append("hide-input")
        for o in cell.get("outputs", []):
            data = o.get("data", {})
            if WIDGET_MIME in data:
                explorer = "Explorer of the" in "".join(data.get("text/plain", ""))
                o["data"] = (
                    {"text/html": static_explorer_html(name), "text/plain": "explorer"}
                    if explorer
                    else {"text/markdown": WIDGET_NOTE.format(name=name)}
                )
                o["metadata"] = {}
        stems = [s for s in saved_stems(cell) if s in captions and s not in placed]
        if not stems:
            continue
        images = [o for o in cell.outputs if "image/png" in o.get("data", {})]
        keep = []
        for o in cell.outputs:
            if o.get("output_type") == "stream":
                o["text"] = _SAVED.sub("", o["text"]).strip("\n")
                if o["text"]:
                    o["text"] += "\n"
                    keep.append(o)
            elif o in images and len(images) <= len(stems):
                continue
            else:
                keep.append(o)
        cell.outputs = keep
        cells.append(
            nbformat.v4.new_markdown_cell(
                "\n".join(_figure(s, captions[s], name=True) for s in stems)
            )
        )
        placed += stems
    for i, cell in enumerate(cells):
        if cell.cell_type == "markdown" and re.search(r"^# ", cell.source, re.M):
            took = f" in {seconds:.1f} s" if seconds is not None else ""
            note = (
                f":::{{note}}\nExecuted top to bottom in a fresh kernel for this build{took}. "
                f"The executed notebook: {{download}}`{name} </downloads/notebooks/{name}>`; "
                "the stored one in `notebooks/` is the nbval reference.\n:::\n"
            )
            cells.insert(i + 1, nbformat.v4.new_markdown_cell(note))
            break
    if failure:  # first thing on the page
        box = (
            ":::{error}\nThis notebook **failed** when executed for this build: "
            f"`{_code(failure)}`. The outputs below stop at the failing cell.\n:::\n"
        )
        cells.insert(0, nbformat.v4.new_markdown_cell(box))
    nb.cells = cells
    return nb, placed


def explorer_figure(arm) -> dict:
    """The page explorer's empty figure of ``arm`` as plotly JSON (arm and target traces kept,
    to be drawn in place by ``js/arm3d_view.js``; the title keeps its margin)."""
    from analysis.app.arm3d import arm_figure, workspace_box

    fig = arm_figure(
        arm, None, None, box=workspace_box(arm), keep_arm=True, height=480,
        title=arm.description.title,
    )
    return json.loads(fig.to_json()) | {"config": {"displaylogo": False, "responsive": True}}


def static_explorer_html(name: str, arms: Iterable[str] | None = None) -> str:
    """The explorer for a page without a kernel: a ``div.static-explorer`` that
    ``js/static_explorer.js`` (served from ``_static``) fills with the controls and the 3D
    view, and every arm that loads (:func:`~analysis.app.explore_logic.available_arms`) printed
    as JavaScript (:func:`~analysis.app.explore_js.arm_module_js`), each with its figure
    (:func:`explorer_figure`) and start target
    (:func:`~analysis.app.explore_logic.default_target`; Table 4 row 1 for the paper's arm)."""
    import numpy as np

    from analysis.app.explore_js import arm_module_js
    from analysis.app.explore_logic import available_arms, default_target
    from analysis.escape import js_json
    from analysis.kinematics.arm import load_arm

    names = list(arms) if arms is not None else list(available_arms()[0])
    scripts, figures, start, left = [], {}, {}, {}
    for arm_name in names:
        arm = load_arm(arm_name)
        try:
            scripts.append(f"analysisArms[{js_json(arm_name)}] = {arm_module_js(arm)};")
        except (ValueError, TypeError, AttributeError) as exc:  # not a D-H chain
            left[arm_name] = (
                f"left out of this page ({exc}; the page prints D-H chains only); "
                f"make lab, notebooks/{name} explores it with a kernel"
            )
            continue
        t = [100.0, 100.0, 600.0] if arm_name == "grabber" else default_target(arm).tolist()
        figures[arm_name] = explorer_figure(arm)
        start[arm_name] = [float(np.round(v, 9)) for v in t]
    first = "grabber" if "grabber" in figures else next(iter(figures))
    cfg = {"id": hashlib.sha1(name.encode()).hexdigest()[:8], "arm": first,
           "arms": list(figures), "figures": figures, "start": start, "left": left}
    return (
        f'<p class="explorer-note">{_html(EXPLORER_NOTE.format(name=name))}</p>\n'
        f"<div class=\"static-explorer\" data-explorer='{_html(json.dumps(cfg))}'>"
        "<noscript>The explorer needs JavaScript.</noscript></div>\n"
        "<script>window.analysisArms = window.analysisArms || {};\n"
        + "\n".join(scripts)
        + "</script>\n"
    )


def _html(text: str) -> str:
    import html

    return html.escape(text, quote=True).replace("`", "")


# --------------------------------------------------------------------------------------------
# pages
# --------------------------------------------------------------------------------------------
def _md_table(df: pd.DataFrame) -> str:
    """A GFM pipe table (MyST renders it, Sphinx search indexes it)."""
    show_index = df.index.name is not None
    cols = ([df.index.name] if show_index else []) + [str(c) for c in df.columns]

    def cell(v) -> str:
        return _inline(" ".join(str(v).split()))

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
                parts.append(f"notebook {_inline(stem)}")
                continue
            label = titles[stem]
            label = label if label.startswith(stem[:2]) else f"{stem[:2]} · {label}"
        parts.append(f"{{doc}}`{_role(label)} </{page}>`")
    return "**Evidence:** " + " · ".join(parts)


def citations() -> dict[str, dict]:
    """The four papers' full citations (``docs/site/citations.toml``), by register name."""
    with CITATIONS_TOML.open("rb") as fh:
        return {p["register"]: p for p in tomllib.load(fh)["paper"]}


def cite(paper: str) -> str:
    """One paper's citation as MyST inline text."""
    c = citations()[paper]
    return f"{_inline(c['authors'])}. *{_inline(c['title'])}*. {_inline(c['venue'])}."


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
    out = [f"({v.anchor})=", f"### Seed {v.seed}: {_inline(v.system)}", ""]
    if c:
        out += [f"{cite(v.paper)}", ""]
    if v.verdict:
        out += [":::{important}", f"**Verdict.** {v.verdict}", ":::", ""]
    else:
        out += [":::{note}", NO_SUMMARY, ":::", ""]
    take = [f"{{doc}}`{_role(label)} </{page}>`" for page, label in v.artefacts]
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
    out = ["# Audit of four robot-kinematics papers", ""]
    if papers:
        out += [glance_html(papers), ""]
    out += [intro, ""]
    if problems:
        out += [":::{error}", "**This build is incomplete.**", ""]
        for what, why in problems.items():
            where = (
                f"{{doc}}`{_role(titles[what])} </notebooks/{what}>`" if what in titles else what
            )
            out.append(f"- {where}: `{_code(why)}`")
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
                out.append(_figure(stem, captions[stem], name=False, evidence=where))
        out += [_evidence(s.evidence, titles), ""]
    if CITATIONS_TOML.exists():
        out += ["## The four papers", ""]
        for paper, c in citations().items():
            out.append(f"- **Seed {c['seed']}.** {cite(paper)} ({_inline(c['source'])})")
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
    by_nb: dict[str, list[str]] = {}
    for stem in captions:
        by_nb.setdefault(stem[:2], []).append(stem)
    for num, stems in sorted(by_nb.items()):
        nb = next((t for t in titles if t.startswith(num)), None)
        head = titles[nb] if nb else f"Notebook {num}"
        head = head if head.startswith(num) else f"{num} · {head}"
        out += [f"## {_inline(head)}", ""]
        for stem in stems:
            home = homes.get(stem)
            where = f"{{ref}}`notebook {num} <fig-{stem}>`" if home else None
            out.append(_figure(stem, captions[stem], name=False, evidence=where))
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
                f'<a class="reference download" href="{_html(name)}" download="{_html(name)}">'
                f'<code class="docutils literal notranslate">{_html(name)}</code></a>'
                if it.at_root
                else f"{{download}}`{name} </downloads/{it.path}>`"
            )
            out.append(
                f"| {link} | {_inline(it.what)} "
                f"| {len(data):,} | `{hashlib.sha256(data).hexdigest()}` "
                f"| {'`' + it.how + '`' if it.how else ''} |"
            )
        out.append("")
    return "\n".join(out)
