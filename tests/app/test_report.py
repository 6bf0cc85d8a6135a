"""The report builder executes notebooks, exports HTML and collects the saved figures."""

from __future__ import annotations

import nbformat

from analysis.app.report import build_report, notebook_paths


def _notebook(path, code: str, title: str) -> None:
    nb = nbformat.v4.new_notebook(
        cells=[nbformat.v4.new_markdown_cell(f"# {title}"), nbformat.v4.new_code_cell(code)],
        metadata={
            "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}
        },
    )
    nbformat.write(nb, path)


def test_build_report_executes_and_collects_figures(tmp_path):
    src = tmp_path / "nbs"
    src.mkdir()
    code = (
        "import matplotlib.pyplot as plt\n"
        "from analysis.app.plotting import save_figure, style\n"
        "with style():\n"
        "    fig, ax = plt.subplots()\n"
        "    ax.plot([0, 1], [0, 1])\n"
        "    print(save_figure(fig, '99-line'))\n"
        "print(6 * 7)\n"
    )
    _notebook(src / "99_demo.ipynb", code, "A demo notebook")
    index = build_report(tmp_path / "report", notebooks=[src / "99_demo.ipynb"])
    out = tmp_path / "report"
    assert index == out / "index.html"
    text = index.read_text()
    assert 'href="notebooks/99_demo.html"' in text and "A demo notebook" in text
    assert (out / "figures" / "99-line.svg").exists() and (out / "figures" / "99-line.png").exists()
    assert 'src="figures/99-line.png"' in text
    executed = nbformat.read(out / "notebooks" / "99_demo.ipynb", as_version=4)
    outputs = "".join(o.get("text", "") for o in executed.cells[1].outputs)
    assert "42" in outputs and "99-line.svg" in outputs
    # the source notebook is the nbval reference: it must not be modified
    assert nbformat.read(src / "99_demo.ipynb", as_version=4).cells[1].outputs == []
    # the audit tables travel with the report, as HTML and CSV
    assert "Table 4, row by row" in text and "Errata register" in text
    assert (out / "tables" / "table4_audit.csv").exists() and (
        out / "tables" / "errata.csv"
    ).exists()


def test_notebook_paths_lists_numbered_notebooks(tmp_path):
    for name in ("02_b.ipynb", "01_a.ipynb", "scratch.ipynb"):
        (tmp_path / name).write_text("{}")
    assert [p.name for p in notebook_paths(tmp_path)] == ["01_a.ipynb", "02_b.ipynb"]
