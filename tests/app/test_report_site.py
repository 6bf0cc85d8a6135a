"""Site content: figure captions from data, notebooks prepared for the site, generated pages."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import matplotlib.pyplot as plt
import nbformat
import pandas as pd
import pytest

from analysis.app import site_content as site
from analysis.app.frontpage import Verdict
from analysis.app.plotting import save_figure

PROJECT = Path(__file__).resolve().parents[2]


def _fig():
    fig, ax = plt.subplots()
    ax.plot([0, 1], [1, 0])
    return fig


def test_save_figure_writes_a_caption_sidecar_and_returns_the_same_names(tmp_path):
    fig = _fig()
    plain = save_figure(fig, "98-plain", folder=tmp_path)
    named = save_figure(fig, "98-named", folder=tmp_path, caption="  Error [mm]\n vs x [mm]. ")
    plt.close(fig)
    assert plain == ["98-plain.svg", "98-plain.png"]
    assert named == ["98-named.svg", "98-named.png"]  # printed by notebooks: nbval compares it
    assert not (tmp_path / "98-plain.json").exists()
    side = json.loads((tmp_path / "98-named.json").read_text())
    assert side == {"stem": "98-named", "caption": "Error [mm] vs x [mm]."}
    with pytest.raises(ValueError, match="empty caption"):
        save_figure(_fig(), "98-empty", folder=tmp_path, caption=" ")


def test_figure_captions_sidecar_wins_over_the_captions_file(tmp_path):
    for stem in ("01-a", "02-b", "03-c"):
        (tmp_path / f"{stem}.png").write_bytes(b"")
    (tmp_path / "01-a.json").write_text(json.dumps({"stem": "01-a", "caption": "from the sidecar"}))
    toml = tmp_path / "captions.toml"
    toml.write_text('[captions]\n"01-a" = "from the file"\n"02-b" = "file only"\n')
    assert site.figure_captions(tmp_path, toml) == {
        "01-a": "from the sidecar",
        "02-b": "file only",
        "03-c": "",
    }


def test_every_figure_a_notebook_saves_has_a_caption():
    """A figure saved by a notebook needs caption=... or an entry in docs/site/captions.toml."""
    with site.CAPTIONS_TOML.open("rb") as fh:
        table = tomllib.load(fh)["captions"]
    missing = []
    for path in sorted((PROJECT / "notebooks").glob("[0-9][0-9]_*.ipynb")):
        for cell in nbformat.read(path, as_version=4).cells:
            for call in re.findall(r"save_figure\(\s*\w+,\s*\"([^\"]+)\"([^)]*)\)", cell.source):
                stem, rest = call
                if "caption=" not in rest and not table.get(stem, "").strip():
                    missing.append(f"{path.name}: {stem}")
    assert not missing, (
        "figures without a caption (pass caption=... to save_figure, or add the stem to "
        f"docs/site/captions.toml): {missing}"
    )


def _executed_cell(stems, images=1, widget=False):
    text = "".join(f"['{s}.svg', '{s}.png']\n" for s in stems)
    outputs = [nbformat.v4.new_output("stream", name="stdout", text="result 1\n" + text)]
    outputs += [
        nbformat.v4.new_output(
            "display_data", data={"image/png": "iVBORw0KGgo=", "text/plain": "<Figure>"}
        )
        for _ in range(images)
    ]
    if widget:
        outputs.append(
            nbformat.v4.new_output(
                "display_data",
                data={site.WIDGET_MIME: {"model_id": "x"}, "text/plain": "VBox()"},
            )
        )
    return nbformat.v4.new_code_cell("...", outputs=outputs)


def test_prepare_notebook_shows_saved_figures_with_captions():
    nb = nbformat.v4.new_notebook(
        cells=[
            nbformat.v4.new_markdown_cell("# 05 · Title"),
            _executed_cell(["05-a", "05-b"], images=1),
            _executed_cell([], images=1, widget=True),
        ],
        metadata={"widgets": {"state": {}}},
    )
    before = json.dumps(nb, sort_keys=True)
    page, placed = site.prepare_notebook(
        nb, "05_x.ipynb", {"05-a": "Caption A [mm].", "05-b": ""}, seconds=1.5
    )
    assert json.dumps(nb, sort_keys=True) == before  # the executed notebook is untouched
    assert placed == ["05-a", "05-b"]
    assert "widgets" not in page.metadata
    kinds = [c.cell_type for c in page.cells]
    assert kinds == ["markdown", "markdown", "code", "markdown", "code"]
    assert "Executed top to bottom" in page.cells[1].source and "1.5 s" in page.cells[1].source
    saver = page.cells[2]
    assert [o.output_type for o in saver.outputs] == ["stream"]  # inline image replaced
    assert saver.outputs[0].text == "result 1\n"  # file names gone, other text kept
    figs = page.cells[3].source
    assert ":name: fig-05-a" in figs and "Caption A \\[mm\\]." in figs
    assert site.MISSING_CAPTION in figs  # 05-b has no caption: shown, not hidden
    other = page.cells[4]
    assert "image/png" in other.outputs[1]["data"]  # not a saved figure: kept
    assert "make lab" in other.outputs[2]["data"]["text/markdown"]


def test_front_page_renders_counts_tables_figures_and_evidence():
    v = Verdict(
        title="What the audit found",
        verdict="**3 of 4 hold.**",
        evidence=(("notebooks/03_t", "03"), ("register", "the register")),
        counts=(("checked", 4), ("hold", 3)),
        table=pd.DataFrame({"n": [1]}, index=pd.Index(["sign|x"], name="kind")),
        figures=("03-fig", "03-absent"),
    )
    md = site.front_page_md(
        [v],
        {"03-fig": "A caption [mm]."},
        {"03-fig": "notebooks/03_t"},
        {"03_t": "03 · Table 4"},
        "intro",
        {"Notebooks": ["notebooks/03_t"]},
    )
    assert '<span class="verdict-number">4</span><span class="verdict-label">checked</span>' in md
    assert "**3 of 4 hold.**" in md
    assert "| sign\\|x | 1 |" in md
    assert "/figures/03-fig.png" in md and "03-absent" not in md
    assert "{ref}`notebook 03 <fig-03-fig>`" in md
    assert "{doc}`03 · Table 4 </notebooks/03_t>`" in md and "{doc}`the register </register>`" in md
    assert "```{toctree}" in md and "notebooks/03_t" in md


def test_a_figure_has_one_number_on_every_page_and_in_the_pdf():
    """Figure numbers are the catalogue's (figures.md: by notebook, then saved order), written
    into the captions: the same figure has the same number on its notebook's page, the front
    page and the figures page (print.md, the PDF, is the front page and the figures page)."""
    import re

    import nbformat

    captions = {"05-b": "B.", "03-a": "A.", "05-a": "C.", "12-z": "Z."}
    assert site.figure_numbers(captions) == {"03-a": 1, "05-b": 2, "05-a": 3, "12-z": 4}
    number = re.compile(
        r"/figures/(\S+)\.png\n(?::name: \S+\n)?:alt: [^\n]*\n\n\*\*Figure (\d+)\.\*\*"
    )
    catalogue = site.figures_md(captions, {}, {})
    assert [(m[1], int(m[2])) for m in number.finditer(catalogue)] == [
        ("03-a", 1), ("05-b", 2), ("05-a", 3), ("12-z", 4)
    ]  # fmt: skip
    front = site.front_page_md(
        [Verdict(title="T", verdict="v", evidence=(), figures=("12-z", "05-a"))],
        captions, {}, {}, "intro", {},
    )  # fmt: skip
    assert [(m[1], int(m[2])) for m in number.finditer(front)] == [("12-z", 4), ("05-a", 3)]
    nb = nbformat.v4.new_notebook()
    nb.cells = [
        nbformat.v4.new_markdown_cell("# 05 · x"),
        nbformat.v4.new_code_cell(
            "save_figure()",
            outputs=[
                nbformat.v4.new_output(
                    "stream", text="['05-b.svg', '05-b.png']\n['05-a.svg', '05-a.png']\n"
                )
            ],
        ),
    ]
    # numbered in the order the notebook shows them, not the file names' order
    ordered = site.shown_order({"05-a": "C.", "05-b": "B."}, [nb])
    assert site.figure_numbers(ordered) == {"05-b": 1, "05-a": 2}
    page, placed = site.prepare_notebook(nb, "05_x.ipynb", captions)
    shown = [(m[1], int(m[2])) for c in page.cells for m in number.finditer(c.source)]
    assert placed == ["05-b", "05-a"] and shown == [("05-b", 2), ("05-a", 3)], shown
    assert "numfig = False" in (site.SITE / "conf.py").read_text()  # no second number


def test_inline_text_cannot_trigger_markup():
    assert site.md_inline("a*b_c [x] $y$ `z` |w|") == "a\\*b\\_c \\[x\\] \\$y\\$ \\`z\\` \\|w\\|"
