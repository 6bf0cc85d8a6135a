"""The report builder executes notebooks, collects their figures and builds the Sphinx site."""

from __future__ import annotations

import json
import re
import time
from pathlib import Path

import nbformat
import pytest

from analysis.app.report import NotebookFailed, build_report, execute_notebook, notebook_paths

# sphinx-book-theme 1.4 still touches an attribute Sphinx 11 will remove
pytestmark = [
    pytest.mark.filterwarnings("ignore:.*HandleFootnoteTransform.app"),
    pytest.mark.slow,  # seconds per test: run first (tests/conftest.py)
]


def _notebook(path, code: str, title: str) -> None:
    nb = nbformat.v4.new_notebook(
        cells=[nbformat.v4.new_markdown_cell(f"# {title}"), nbformat.v4.new_code_cell(code)],
        metadata={
            "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}
        },
    )
    nbformat.write(nb, path)


@pytest.fixture(scope="module")
def demo_site(tmp_path_factory):
    """A site built from one small notebook that saves a captioned figure and prints maths."""
    tmp = tmp_path_factory.mktemp("report")
    src = tmp / "nbs"
    src.mkdir()
    code = (
        "import matplotlib.pyplot as plt\n"
        "import sympy as sp\n"
        "from IPython.display import display\n"
        "from analysis.app.plotting import save_figure, style\n"
        "with style():\n"
        "    fig, ax = plt.subplots()\n"
        "    ax.plot([0, 1], [0, 1])\n"
        "    cap = 'A straight line: y [mm] against x [mm].'\n"
        "    print(save_figure(fig, '99-line', caption=cap))\n"
        "plt.show()\n"
        "display(sp.Matrix([[sp.Symbol('theta_1'), 0], [0, 1]]))\n"
        "print(6 * 7)\n"
        "from ipykernel.kernelapp import IPKernelApp\n"
        "print('transport', IPKernelApp.instance().transport)\n"
    )
    _notebook(src / "99_demo.ipynb", code, "99 · A demo notebook")
    # a notebook that raises, with a stale stored output after the failing cell
    broken = nbformat.v4.new_notebook(
        cells=[
            nbformat.v4.new_markdown_cell("# 98 · A broken notebook"),
            nbformat.v4.new_code_cell("raise ValueError('boom')"),
            nbformat.v4.new_code_cell(
                "print('after')",
                outputs=[nbformat.v4.new_output("stream", name="stdout", text="STALE OUTPUT\n")],
            ),
        ],
        metadata={"kernelspec": {"name": "python3", "display_name": "Python 3"}},
    )
    nbformat.write(broken, src / "98_broken.ipynb")
    with pytest.raises(NotebookFailed, match="98_broken: ValueError: boom") as failed:
        build_report(
            tmp / "report", notebooks=[src / "98_broken.ipynb", src / "99_demo.ipynb"], pdf=False
        )
    assert "the site was built" in str(failed.value)
    return tmp, src, tmp / "report" / "index.html"


def test_build_report_writes_the_site(demo_site):
    tmp, _, index = demo_site
    out = tmp / "report"
    assert index == out / "index.html"
    for page in ("index", "register", "figures", "downloads", "search", "notebooks/99_demo"):
        assert (out / f"{page}.html").exists(), page
    text = index.read_text()
    assert 'href="notebooks/99_demo.html"' in text and "A demo notebook" in text
    # front page: the verdicts, recomputed
    assert "root causes against the paper" in text and "Table 4, recomputed" in text
    assert "The PLC program, executed" in text
    # MathJax is local, never a CDN (Sphinx adds it to the pages with maths)
    page = (out / "notebooks" / "99_demo.html").read_text()
    assert "_static/mathjax/tex-chtml.js" in page and "cdn.jsdelivr" not in page
    assert (out / "_static" / "mathjax" / "tex-chtml.js").exists()


def test_notebook_page_has_the_captioned_figure_and_maths(demo_site):
    tmp, _, _ = demo_site
    page = (tmp / "report" / "notebooks" / "99_demo.html").read_text()
    assert "A straight line: y [mm] against x [mm]." in page
    assert "<figcaption>" in page and "99-line.png" in page
    # the printed file names are replaced by the figure; the SymPy output is maths
    assert "[&#39;99-line.svg&#39;, &#39;99-line.png&#39;]" not in page
    assert "$\\displaystyle" not in page and "math notranslate" in page
    assert "42" in page


def test_executed_notebook_and_figures_are_downloads(demo_site):
    tmp, src, _ = demo_site
    out = tmp / "report"
    executed = nbformat.read(
        tmp / "report-src" / "site" / "downloads" / "notebooks" / "99_demo.ipynb", 4
    )
    outputs = "".join(o.get("text", "") for o in executed.cells[1].outputs)
    assert "42" in outputs and "99-line.svg" in outputs
    assert "transport ipc" in outputs  # Unix sockets, no TCP port to race for
    # the source notebook is the nbval reference: it must not be modified
    assert nbformat.read(src / "99_demo.ipynb", as_version=4).cells[1].outputs == []
    downloads = (out / "downloads.html").read_text()
    for name in (
        "ik_s7-200.awl",
        "ik_s7-200_map.json",
        "ik_s7-300.awl",
        "ik_s7-300_map.json",
        "grabber.csv",
        "grabber_items.csv",
        "table4_audit.csv",
        "99_demo.ipynb",
    ):
        assert name in downloads, name
        assert list(out.glob(f"_downloads/*/{name}")), name
    awl = next(out.glob("_downloads/*/ik_s7-200.awl")).read_text()
    assert "ORGANIZATION_BLOCK" in awl
    json.loads(next(out.glob("_downloads/*/ik_s7-300_map.json")).read_text())
    assert list(out.glob("_downloads/*/99-line.svg")) and list(out.glob("_images/99-line.png"))


def _text(html: str) -> str:
    """What a reader sees of an HTML page, roughly: tags dropped, spaces collapsed."""
    return " ".join(re.sub(r"<[^>]+>", " ", html).split())


def test_a_failing_notebook_is_shown_not_hidden(demo_site):
    tmp, _, index = demo_site
    front = _text(index.read_text())
    assert "This build is incomplete." in front and "ValueError: boom" in front
    page = _text((tmp / "report" / "notebooks" / "98_broken.html").read_text())
    assert "This notebook failed when executed for this build: ValueError: boom" in page
    assert "STALE OUTPUT" not in page  # nothing stored survives a failing cell


def test_execute_notebook_shuts_its_kernel_down(tmp_path):
    _notebook(tmp_path / "01_pid.ipynb", "import os\nprint(os.getpid())", "01 · pid")
    nb = execute_notebook(tmp_path / "01_pid.ipynb")
    pid = int(nb.cells[1].outputs[0]["text"])
    for _ in range(50):  # the kernel process is gone (and reaped) once execution returns
        if not Path(f"/proc/{pid}").exists():
            break
        time.sleep(0.1)
    assert not Path(f"/proc/{pid}").exists()


def test_rebuild_refuses_a_foreign_folder(tmp_path):
    (tmp_path / "report").mkdir()
    (tmp_path / "report" / "precious.txt").write_text("not a report")
    with pytest.raises(FileExistsError):
        build_report(tmp_path / "report", notebooks=[tmp_path / "none.ipynb"], pdf=False)
    assert (tmp_path / "report" / "precious.txt").exists()


def test_notebook_paths_lists_numbered_notebooks(tmp_path):
    for name in ("02_b.ipynb", "01_a.ipynb", "scratch.ipynb"):
        (tmp_path / name).write_text("{}")
    assert [p.name for p in notebook_paths(tmp_path)] == ["01_a.ipynb", "02_b.ipynb"]


def test_warning_counter_counts_what_sphinx_counts(tmp_path):
    """The build's warning count comes from the warning stream (public API), one per line
    Sphinx writes; Sphinx's own private counter is the reference here."""
    import io

    from sphinx.application import Sphinx
    from sphinx.util.docutils import docutils_namespace

    from analysis.app.report import _WarningCounter

    src = tmp_path / "src"
    src.mkdir()
    (src / "conf.py").write_text("project = 't'\n")
    (src / "index.rst").write_text(
        "Title\n=====\n\nSee :ref:`no-such-label` and :doc:`missing`.\n\n.. no-such-directive::\n"
    )
    sink = io.StringIO()
    counter = _WarningCounter(sink)
    with docutils_namespace():
        app = Sphinx(str(src), str(src), str(tmp_path / "out"), str(tmp_path / "dt"), "html",
                     status=None, warning=counter, freshenv=True)  # fmt: skip
        app.build(force_all=True)
    assert counter.count == app._warncount == 3, sink.getvalue()
    assert sink.getvalue().count("WARNING") + sink.getvalue().count("ERROR") == 3


def test_the_site_ships_only_the_static_files_its_pages_load(demo_site):
    """MathJax: tex-chtml.js, its fonts and the TeX extensions it autoloads; the theme
    without fontawesome.js (icons come from the web fonts) and without its translations."""
    out = demo_site[0] / "report"
    static = out / "_static"
    mj = static / "mathjax"
    assert (mj / "input/tex/extensions/color.js").exists()  # \colorbox autoloads it
    assert list((mj / "output/chtml/fonts/woff-v2").glob("*.woff"))
    for gone in ("tex-svg.js", "input/tex-full.js", "ui/menu.js", "a11y/sre.js", "output/svg.js",
                 "input/tex/extensions/all-packages.js"):  # fmt: skip
        assert not (mj / gone).exists(), gone
    assert not (static / "scripts/fontawesome.js").exists()
    assert not (static / "locales").exists()
    assert list((static / "vendor/fontawesome/webfonts").glob("*.woff2"))
    for page in out.glob("*.html"):
        assert "fontawesome.js" not in page.read_text(), page.name


def test_prune_static_refuses_a_page_that_loads_a_removed_file(tmp_path):
    from analysis.app.report_files import prune_static as _prune_static

    static = tmp_path / "_static"
    (static / "scripts").mkdir(parents=True)
    (static / "scripts" / "fontawesome.js").write_text("x" * 10)
    (tmp_path / "index.html").write_text('<script src="_static/scripts/fontawesome.js">')
    with pytest.raises(RuntimeError, match=r"index\.html loads _static/scripts/fontawesome\.js"):
        _prune_static(static, tmp_path)


def test_preview_png_is_the_same_picture_in_a_palette(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from PIL import Image

    from analysis.app.report import preview_png

    fig, ax = plt.subplots()
    ax.imshow(np.linspace(0, 1, 400).reshape(20, 20), cmap="viridis")
    ax.plot([0, 19], [0, 19], "r-")
    path = tmp_path / "99-x.png"
    fig.savefig(path, dpi=150)
    plt.close(fig)
    full = np.asarray(Image.open(path).convert("RGBA"), dtype=float)
    before, after = preview_png(path)
    assert after < before and path.stat().st_size == after
    with Image.open(path) as im:
        assert im.mode == "P" and im.size == full.shape[1::-1]
        small = np.asarray(im.convert("RGBA"), dtype=float)
    assert np.abs(small - full).mean() < 2.0  # of 255: the same picture
    # the gradient keeps its levels (no banding into a few dozen steps)
    assert len(np.unique(small.reshape(-1, 4), axis=0)) > 150
    with pytest.raises(ValueError, match="colours=300"):
        preview_png(path, colours=300)


def test_executing_a_notebook_leaves_no_socket_to_the_garbage_collector(tmp_path):
    """make report runs under the CLI's warnings.simplefilter("default"): a kernel's zmq sockets
    left open were ~130 lines of ResourceWarning in its output."""
    import gc
    import warnings

    path = tmp_path / "one.ipynb"
    _notebook(path, "1 + 1", "One cell")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("default")
        execute_notebook(path)
        gc.collect()
    leaks = [str(w.message) for w in caught if issubclass(w.category, ResourceWarning)]
    assert not leaks, leaks[:3]


def test_third_party_noise_is_kept_out_and_the_projects_warnings_are_not():
    """What the build ignores (THIRD_PARTY_NOISE) is the dependency's warning only: under the
    CLI's warnings.simplefilter("default") a warning of the project still shows."""
    import warnings

    from sphinx.deprecation import RemovedInSphinx11Warning

    from analysis.app.report import _quiet_dependencies

    noise = "'sphinx_book_theme._transforms.HandleFootnoteTransform.app' is deprecated."
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("default")
        with _quiet_dependencies():
            warnings.warn(noise, RemovedInSphinx11Warning, stacklevel=1)
            warnings.warn("analysis: a warning of the project", UserWarning, stacklevel=1)
            warnings.warn("another RemovedInSphinx11Warning", RemovedInSphinx11Warning,
                          stacklevel=1)  # fmt: skip
    assert [str(w.message) for w in caught] == [
        "analysis: a warning of the project", "another RemovedInSphinx11Warning"
    ]
