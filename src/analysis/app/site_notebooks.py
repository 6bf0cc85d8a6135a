"""The executed notebooks as the report site's pages (MyST-NB reads them): each figure a cell
saved with :func:`analysis.app.plotting.save_figure` shown as a numbered figure with its
caption and SVG link in place of the inline image and the printed file names
(:func:`prepare_notebook`), widget outputs, which need a kernel, as a note or the explorer
without a kernel (:func:`analysis.app.site_explorer.static_explorer_html`), and the MyST
helpers the generated pages share (:func:`md_inline`, :func:`md_code`, :func:`md_role`,
:func:`figure_md`).

Figure captions come from data, never from file names (:func:`figure_captions`): the sidecar
``<stem>.json`` that ``save_figure(..., caption=...)`` writes, else the entry for the stem in
``docs/site/captions.toml``. A figure with neither is shown with a visible
"caption missing" notice (and the browser tests fail on it).
"""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import nbformat

from analysis.app.site_explorer import static_explorer_html

__all__ = [
    "CAPTIONS_TOML",
    "MISSING_CAPTION",
    "figure_captions",
    "figure_md",
    "figure_numbers",
    "md_code",
    "md_inline",
    "md_role",
    "prepare_notebook",
    "saved_stems",
    "shown_order",
]

PROJECT = Path(__file__).resolve().parents[3]
SITE = PROJECT / "docs" / "site"
CAPTIONS_TOML = SITE / "captions.toml"
MISSING_CAPTION = "Caption missing: pass caption=... to save_figure() for"
WIDGET_MIME = "application/vnd.jupyter.widget-view+json"
WIDGET_NOTE = (
    "*Interactive controls (sliders, branch picker, FK mode). A static page has no Python "
    "kernel to drive them: run `make lab` and open `notebooks/{name}` to use them.*"
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


def md_code(text: str) -> str:
    """Text that can sit between single backticks (an inline literal)."""
    return " ".join(text.replace("`", "'").split())[:300]


def md_role(text: str) -> str:
    """Link text inside a role (``{doc}`text <target>```): no backticks or angle brackets."""
    return " ".join(text.replace("`", "'").replace("<", "‹").replace(">", "›").split())


def md_inline(text: str) -> str:
    """Plain text as MyST inline content (no markup, roles or maths triggered)."""
    return re.sub(r"([\\`*_\[\]<>{}$|#])", r"\\\1", text)


def shown_order(captions: dict[str, str], notebooks) -> dict[str, str]:
    """``captions`` in the order the executed ``notebooks`` show their figures (notebook by
    notebook, cell by cell), then any figure no notebook shows: what :func:`figure_numbers`
    numbers (the file names' alphabetical order put a notebook's third figure first)."""
    shown = [
        stem
        for nb in notebooks
        for cell in nb.cells
        if cell.cell_type == "code"
        for stem in saved_stems(cell)
        if stem in captions
    ]
    return {stem: captions[stem] for stem in dict.fromkeys([*shown, *captions])}


def figure_numbers(captions: dict[str, str]) -> dict[str, int]:
    """Each figure's one number, on every page of the site and in the PDF: its place in the
    catalogue (``figures.md``: by notebook number, then in the order of ``captions``, which
    :func:`shown_order` puts in the order the notebook shows them). Sphinx's ``numfig``
    numbers a figure where it stands, so the same figure had one number on its notebook's
    page, another on the front page and the figures page and a third in the PDF (which
    starts from its own front page); ``docs/site/conf.py`` has ``numfig`` off and
    :func:`figure_md` writes this number into the caption."""
    order = sorted(captions, key=lambda stem: stem[:2])  # stable: the saved order kept
    return {stem: k for k, stem in enumerate(order, 1)}


def figure_md(
    stem: str, caption: str, *, name: bool, number: int, evidence: str | None = None
) -> str:
    """A MyST figure: the PNG, its caption after its number (:func:`figure_numbers`),
    SVG/PNG downloads, optionally where it comes from."""
    cap = md_inline(caption) if caption else f"**{MISSING_CAPTION} `{stem}`.**"
    cap = f"**Figure {number}.** {cap}"
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
        numbers = figure_numbers(captions)
        cells.append(
            nbformat.v4.new_markdown_cell(
                "\n".join(figure_md(s, captions[s], name=True, number=numbers[s]) for s in stems)
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
            f"`{md_code(failure)}`. The outputs below stop at the failing cell.\n:::\n"
        )
        cells.insert(0, nbformat.v4.new_markdown_cell(box))
    nb.cells = cells
    return nb, placed
