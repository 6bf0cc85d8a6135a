"""Build the HTML report: execute every notebook, collect its figures, write an index.

``python -m analysis report --out build/report`` (and ``make report``) writes::

    build/report/index.html            the entry page: notebooks, figures, audit summary
    build/report/notebooks/NN_*.html   each notebook, freshly executed, as HTML
    build/report/notebooks/NN_*.ipynb  the executed notebooks themselves
    build/report/figures/*.svg|png     every figure the notebooks saved (save_figure)
    build/report/tables/*.csv          Table 4 explained and the errata register

The stored notebooks in ``notebooks/`` are not modified: they are the nbval references.
"""

from __future__ import annotations

import html
import os
from pathlib import Path

import nbformat
from nbclient import NotebookClient
from nbconvert import HTMLExporter

__all__ = ["build_report", "notebook_paths"]

PROJECT = Path(__file__).resolve().parents[3]


def notebook_paths(folder: Path | None = None) -> list[Path]:
    """The numbered notebooks (``NN_name.ipynb``) in ``folder`` (default ``notebooks/``)."""
    folder = folder or PROJECT / "notebooks"
    paths = sorted(p for p in folder.glob("[0-9][0-9]_*.ipynb"))
    if not paths:
        raise FileNotFoundError(f"no numbered notebooks (NN_name.ipynb) in {folder}")
    return paths


def _title(nb: nbformat.NotebookNode, fallback: str) -> str:
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            for line in cell.source.splitlines():
                if line.startswith("#"):
                    return line.lstrip("#").strip()
    return fallback


def execute_notebook(path: Path, timeout: int = 1800) -> nbformat.NotebookNode:
    """Execute a notebook top to bottom in a fresh kernel, with its folder as cwd."""
    nb = nbformat.read(path, as_version=4)
    client = NotebookClient(
        nb,
        timeout=timeout,
        kernel_name="python3",
        resources={"metadata": {"path": str(path.parent)}},
    )
    client.execute()
    return nb


def build_report(out: str | Path = "build/report", notebooks: list[Path] | None = None) -> Path:
    """Execute the notebooks, export HTML and figures under ``out``; return index.html."""
    out = Path(out).resolve()
    nb_dir, fig_dir = out / "notebooks", out / "figures"
    nb_dir.mkdir(parents=True, exist_ok=True)
    fig_dir.mkdir(parents=True, exist_ok=True)
    paths = [Path(p).resolve() for p in notebooks] if notebooks else notebook_paths()
    previous = os.environ.get("ANALYSIS_FIGURE_DIR")
    os.environ["ANALYSIS_FIGURE_DIR"] = str(fig_dir)  # inherited by the kernels
    os.environ.setdefault("MPLBACKEND", "module://matplotlib_inline.backend_inline")
    exporter = HTMLExporter()
    entries = []
    try:
        for path in paths:
            print(f"executing {path.name} ...", flush=True)
            nb = execute_notebook(path)
            nbformat.write(nb, nb_dir / path.name)
            body, _ = exporter.from_notebook_node(nb)
            (nb_dir / f"{path.stem}.html").write_text(body, encoding="utf-8")
            entries.append((path.stem, _title(nb, path.stem)))
    finally:
        if previous is None:
            os.environ.pop("ANALYSIS_FIGURE_DIR", None)
        else:
            os.environ["ANALYSIS_FIGURE_DIR"] = previous
    index = out / "index.html"
    index.write_text(_index_html(entries, sorted(fig_dir.glob("*.png")), out), encoding="utf-8")
    return index


def _tables_html(out: Path) -> str:
    """Table 4 explained and the errata register, as HTML and as CSV files under tables/."""
    from analysis.audit import register as errata
    from analysis.audit import table4

    tables = out / "tables"
    tables.mkdir(exist_ok=True)
    t4 = table4.report_table()
    reg = errata.load()
    t4.to_csv(tables / "table4_audit.csv")
    reg.to_csv(tables / "errata.csv", index=False)
    return (
        '<h2>Table 4, row by row</h2>\n<p>(<a href="tables/table4_audit.csv">CSV</a>; '
        "details in notebook 03)</p>\n"
        + t4.to_html(escape=True, border=0, classes="errata")
        + '\n<h2>Errata register</h2>\n<p>(<a href="tables/errata.csv">CSV</a>; every row has '
        "the test that proves it, column <code>check</code>)</p>\n"
        + reg.to_html(index=False, escape=True, border=0, classes="errata")
    )


def _index_html(entries: list[tuple[str, str]], figures: list[Path], out: Path) -> str:
    items = "\n".join(
        f'<li><a href="notebooks/{stem}.html">{html.escape(stem)}</a>: {html.escape(title)}</li>'
        for stem, title in entries
    )
    figs = "\n".join(
        f'<figure><a href="{f.relative_to(out).with_suffix(".svg").as_posix()}">'
        f'<img src="{f.relative_to(out).as_posix()}" alt="{html.escape(f.stem)}"></a>'
        f"<figcaption>{html.escape(f.stem)}</figcaption></figure>"
        for f in figures
    )
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>Audit of Li Feng et al. (2016): material grabbing robot kinematics</title>
<style>
body {{ font-family: sans-serif; max-width: 70em; margin: 2em auto; line-height: 1.4; }}
figure {{ display: inline-block; margin: 0.5em; width: 30em; vertical-align: top; }}
figure img {{ width: 100%; }}
table.errata {{ border-collapse: collapse; font-size: 0.85em; }}
table.errata td, table.errata th {{ border: 1px solid #ccc; padding: 0.2em 0.4em;
  vertical-align: top; }}
</style></head><body>
<h1>Audit of Li Feng et al. (2016), a 3R material grabbing robot</h1>
<p>Every notebook below was executed top to bottom for this report; the figures are the
files the notebooks saved.</p>
<h2>Notebooks</h2>
<ul>
{items}
</ul>
<h2>Figures</h2>
{figs}
{_tables_html(out)}
</body></html>
"""
