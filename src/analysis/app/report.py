"""Build the report site: execute every notebook, then render it with Sphinx + MyST-NB.

``python -m analysis report --out build/report`` (and ``make report``) writes a static site::

    build/report/index.html            front page: the verdicts, each linking to its evidence
    build/report/notebooks/NN_*.html   each notebook, executed for this build
    build/report/register.html         the errata register
    build/report/figures.html          every saved figure with its caption
    build/report/downloads.html        PLC programs, memory maps, CSVs, executed notebooks, PDF
    build/report/search.html           full-text search (Sphinx's index, no server needed)
    build/report/report.pdf            the whole report without code, printed by Chromium (if
                                       installed; one stable path, linked from downloads.html)

and keeps its sources in ``build/report-src`` (the staged Sphinx source folder). The stored
notebooks in ``notebooks/`` are never modified: they are the nbval references. Each one is
executed top to bottom in a fresh kernel by :func:`execute_notebook` (nbclient), with
``ANALYSIS_FIGURE_DIR`` pointing at the staged ``figures/`` so that ``save_figure`` puts
its SVG/PNG (and caption sidecar) there; progress goes to the console (notebook i/n,
seconds, total elapsed).

Why Sphinx + MyST-NB + sphinx-book-theme (the engine of Jupyter Book 1, used directly)
----------------------------------------------------------------------------------------
* It gives what the report lacked without custom web code: a contents sidebar, previous/
  next links, the start page first in the sidebar, a search page whose index is a static
  file, per-page contents, a "print to PDF" button and print styles, numbered figures with
  captions, MathJax for the SymPy (``text/latex``) outputs.
* All of it installs from PyPI at pinned versions and builds offline. MathJax 3 is served
  from the site itself (``docs/site/conf.py``): nothing is fetched at build or view time.
* MyST-NB renders notebooks without executing them (``nb_execution_mode = "off"``), so
  execution stays here, with our progress, timeouts and figure collection.
* Jupyter Book 1 (``jupyter-book`` 1.0.4) is a thin wrapper around the same packages; it is
  in maintenance mode and pins Sphinx 7 and an older theme, so its engine is used directly
  at current versions. Jupyter Book 2 / mystmd need Node and download their site theme at
  build time, which this project does not allow. nbconvert's HTML (the previous report)
  has no navigation and loads MathJax from a CDN; Quarto needs its own binary.
"""

from __future__ import annotations

import contextlib
import functools
import http.server
import io
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import nbformat
from jupyter_client.manager import KernelManager
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

from analysis.app.plotting import figure_dir

__all__ = [
    "NotebookFailed",
    "build_report",
    "execute_notebook",
    "notebook_paths",
    "preview_png",
    "print_pdf",
    "serve",
]

PROJECT = Path(__file__).resolve().parents[3]
CONF_DIR = PROJECT / "docs" / "site"
CHROMIUM = "/usr/bin/chromium"
# flags for Debian's Chromium on a machine without a display or outside network
CHROMIUM_FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
)
_MARKER = ".analysis-report"
NB_BACKEND = "module://matplotlib_inline.backend_inline"


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
                if line.startswith("# "):
                    return line.lstrip("#").strip()
    return fallback


class NotebookFailed(RuntimeError):
    """A notebook raised; the site was still built, with the failure shown on its pages."""


def execute_notebook(
    path: Path,
    timeout: int = 1800,
    *,
    on_cell: Callable[[int, int], None] | None = None,
    into: nbformat.NotebookNode | None = None,
    env: dict[str, str] | None = None,
) -> nbformat.NotebookNode:
    """Execute a notebook top to bottom in a fresh kernel, with its folder as cwd.

    Returns the executed notebook; the file at ``path`` is only read. ``on_cell(i, n)`` is
    called after each code cell (i of n code cells). ``into``: the notebook read from
    ``path``, executed in place (so that a caller still has its outputs up to the failing
    cell when execution raises ``nbclient.exceptions.CellExecutionError``). ``env``: the
    kernel's environment (default this process's).
    """
    nb = into if into is not None else nbformat.read(path, as_version=4)
    for cell in nb.cells:  # no stored output survives, even after a failing cell
        if cell.cell_type == "code":
            cell.outputs = []
            cell.execution_count = None
    n_code = sum(c.cell_type == "code" for c in nb.cells)
    done = 0

    def hook(**_):
        nonlocal done
        done += 1
        if on_cell is not None:
            on_cell(done, n_code)

    # The kernel talks over Unix sockets in a private folder (IPC), not TCP: no free-port race
    # with other kernels starting at the same time (see tests/nbval_kernel.py for the race).
    with tempfile.TemporaryDirectory(prefix="analysis-kernel-") as ipc:
        km = KernelManager(
            kernel_name="python3",
            transport="ipc",
            ip=os.path.join(ipc, "k"),
            connection_file=os.path.join(ipc, "k.json"),
        )
        client = NotebookClient(
            nb,
            km=km,
            timeout=timeout,
            kernel_name="python3",
            resources={"metadata": {"path": str(path.parent)}},
            on_cell_executed=hook,
            shutdown_kernel="immediate",
        )
        try:
            # cleanup_kc: nbclient stops the client's channels and closes the manager's sockets
            # even though the manager is ours (else every notebook left four zmq sockets to the
            # garbage collector: ~130 "ResourceWarning: Unclosed socket" lines in make report)
            client.execute(cleanup_kc=True, **({"env": dict(env)} if env is not None else {}))
        finally:  # if nbclient could not (a failure before its cleanup)
            if km.has_kernel:
                km.shutdown_kernel(now=True)
            km.cleanup_resources()
    return nb


@contextlib.contextmanager
def _env(**values: str) -> Iterator[None]:
    old = {k: os.environ.get(k) for k in values}
    os.environ.update(values)
    try:
        yield
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def _refuse_foreign(path: Path) -> None:
    """FileExistsError if ``path`` is a non-empty folder this module did not write: only its
    marker file says so (an ``index.html`` may be anyone's web site)."""
    if path.exists():
        ours = (path / _MARKER).is_file()
        if any(path.iterdir()) and not ours:
            raise FileExistsError(f"{path} is not empty and not a report build: not deleting it")


def _fresh_dir(path: Path) -> None:
    """Empty ``path`` for a new build; refuse a non-empty folder this module did not write."""
    if path.exists():
        _refuse_foreign(path)
        shutil.rmtree(path)
    path.mkdir(parents=True)
    (path / _MARKER).write_text("written by analysis.app.report; deleted on the next build\n")


def _sphinx(
    src: Path, out: Path, doctrees: Path, builder: str = "html", overrides: dict | None = None
) -> int:
    """Run Sphinx in this process; return the number of warnings."""
    from sphinx.application import Sphinx
    from sphinx.util.console import nocolor
    from sphinx.util.docutils import docutils_namespace, patch_docutils

    if not sys.stderr.isatty():
        nocolor()
    warnings = _WarningCounter(sys.stderr)
    with patch_docutils(CONF_DIR), docutils_namespace(), _quiet_dependencies():
        app = Sphinx(
            str(src),
            str(CONF_DIR),
            str(out),
            str(doctrees),
            builder,
            status=None,  # our own progress lines instead of Sphinx's per-file log
            warning=warnings,
            freshenv=False,
            confoverrides=overrides or {},
            verbosity=0,
        )
        app.build(force_all=True)
        if app.statuscode:
            raise RuntimeError(f"sphinx-build ({builder}) failed with status {app.statuscode}")
        return warnings.count


THIRD_PARTY_NOISE = (
    # sphinx-book-theme 1.4 reads an attribute Sphinx 11 will remove: the theme's to fix
    (r".*HandleFootnoteTransform\.app", "RemovedInSphinx11Warning"),
)
"""Python warnings of the site's dependencies, not of this project, kept out of make report's
output (message pattern, category name); nothing else is filtered (tests/app/test_report.py)."""


@contextlib.contextmanager
def _quiet_dependencies() -> Iterator[None]:
    """:data:`THIRD_PARTY_NOISE` ignored for the duration (the project's own warnings shown)."""
    import warnings as _w

    with _w.catch_warnings():
        for message, category in THIRD_PARTY_NOISE:
            cls = _sphinx_warning(category)
            _w.filterwarnings("ignore", message=message, category=cls)
        yield


def _sphinx_warning(name: str) -> type[Warning]:
    import sphinx.deprecation

    return getattr(sphinx.deprecation, name, Warning)


class _WarningCounter(io.TextIOBase):
    """Sphinx's warning stream: passes everything to ``target`` and counts the warning and
    error lines (``<location>: WARNING: <message>``, the format Sphinx's warning handler
    writes), what a reader of the build log sees."""

    _LINE = re.compile(r"(?:^|: )(?:WARNING|ERROR|CRITICAL): ", re.MULTILINE)

    def __init__(self, target) -> None:
        self.target = target
        self.count = 0

    def write(self, text: str) -> int:
        self.count += len(self._LINE.findall(text))
        self.target.write(text)
        return len(text)

    def flush(self) -> None:
        self.target.flush()


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args) -> None:  # no access log on the console
        pass


@contextlib.contextmanager
def serve(folder: Path) -> Iterator[str]:
    """Serve ``folder`` over HTTP on 127.0.0.1 (a free port) for the duration; yield the URL."""
    handler = functools.partial(_QuietHandler, directory=str(folder))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()
        thread.join()


def print_pdf(
    html_dir: Path, pdf: Path, chromium: str = CHROMIUM, timeout: int = 300, page: str = "index"
) -> bool:
    """Print ``html_dir/index.html`` to ``pdf`` with Debian's headless Chromium.

    The page is served on 127.0.0.1 (so that MathJax loads its fonts) and given a virtual
    time budget to typeset the maths before printing. Returns False (and prints why) where
    no Chromium is installed or printing failed; a missing PDF never fails the build.
    """
    if not Path(chromium).exists():
        print(f"[pdf] skipped: no Chromium at {chromium} (apt-get install chromium)", flush=True)
        return False
    with tempfile.TemporaryDirectory() as profile, serve(html_dir) as url:
        cmd = [
            chromium,
            *CHROMIUM_FLAGS,
            f"--user-data-dir={profile}",
            "--no-pdf-header-footer",
            "--virtual-time-budget=60000",
            "--run-all-compositor-stages-before-draw",
            f"--print-to-pdf={pdf}",
            url + f"{page}.html",
        ]
        try:
            run = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            print(f"[pdf] skipped: Chromium did not finish in {timeout} s", flush=True)
            return False
    if run.returncode != 0 or not pdf.exists() or pdf.stat().st_size == 0:
        print(f"[pdf] skipped: Chromium exited {run.returncode}: {run.stderr[-500:]}", flush=True)
        return False
    return True


_MATHJAX_KEEP = (
    "tex-chtml.js",  # TeX in, CommonHTML out, the menu and assistive MathML, in one file
    "output/chtml/fonts/woff-v2/*.woff",  # the fonts CommonHTML loads, each as the maths needs
    "input/tex/extensions/*.js",  # what \color, \boxed, ... autoload (the autoload package)
    "ui/safe.js",  # the menu's "filter unsafe content" option
)
"""The files of MathJax the site serves (globs relative to ``_static/mathjax``): what
``tex-chtml.js`` loads by itself. Not kept: the other combined components (``tex-svg.js``,
``tex-mml-chtml.js``, ...), the separate input and output components that ``tex-chtml.js``
contains, the SVG output, the MathML input, and the accessibility explorer with its
speech-rule engine (``a11y/sre.js``, ``sre/``): the menu entries that would load those are
hidden (``docs/site/mathjax_menu.js``)."""

_THEME_UNUSED = (
    "scripts/fontawesome.js",  # icons are drawn from the web fonts (docs/site/_templates)
    "scripts/fontawesome.js.LICENSE.txt",
    "locales",  # the theme's translations: read by Sphinx at build time, not by a page
    "webpack-macros.html",  # a template of the theme, used at build time
)


def _prune_static(static: Path, site: Path) -> dict[str, int]:
    """Delete what no page of the site loads from ``static`` (the site's ``_static``): the
    MathJax files outside :data:`_MATHJAX_KEEP`, the theme's unused files
    (:data:`_THEME_UNUSED`) and the source maps of minified scripts and styles. Returns the
    bytes removed per kind. Raises ``RuntimeError`` naming the page if a page of ``site``
    still refers to a removed file (so a theme upgrade cannot break a page silently)."""
    removed = {"mathjax": 0, "theme": 0, "source maps": 0}
    gone: list[str] = []

    def drop(f: Path, kind: str) -> None:
        removed[kind] += f.stat().st_size
        gone.append(f.relative_to(static).as_posix())
        f.unlink()

    mj = static / "mathjax"
    if mj.is_dir():
        keep = {f for pattern in _MATHJAX_KEEP for f in mj.glob(pattern)}
        keep.discard(mj / "input/tex/extensions/all-packages.js")  # tex-full.js's, not autoloaded
        for f in sorted(p for p in mj.rglob("*") if p.is_file() and p not in keep):
            drop(f, "mathjax")
    for name in _THEME_UNUSED:
        target = static / name
        for f in [target] if target.is_file() else sorted(target.rglob("*")):
            if f.is_file():
                drop(f, "theme")
    for f in sorted(static.rglob("*.map")):
        drop(f, "source maps")
    for d in sorted((p for p in static.rglob("*") if p.is_dir()), reverse=True):
        if not any(d.iterdir()):
            d.rmdir()
    scripts = [n for n in gone if n.endswith((".js", ".css"))]
    for page in sorted([*site.glob("*.html"), *site.glob("notebooks/*.html")]):
        html = page.read_text(encoding="utf-8", errors="replace")
        for n in scripts:
            if f"_static/{n}" in html:
                raise RuntimeError(f"{page.relative_to(site)} loads _static/{n}, which the "
                                   "site no longer ships (analysis.app.report._prune_static)")
    return removed


def preview_png(path: Path, colours: int = 256) -> tuple[int, int]:
    """Rewrite the figure ``path`` (a PNG saved by :func:`analysis.app.plotting.save_figure`)
    as the site's raster preview: the same pixels reduced to a palette of ``colours`` (median
    cut, or fast octree where the image has transparency; no dithering: a plot has few
    colours, a colour map at most 256 distinct levels on screen), optimised. The SVG stays
    the exact, vector download. Returns the sizes before and after [bytes]; a file that
    would not shrink is left as it was."""
    from PIL import Image

    if not 2 <= colours <= 256:
        raise ValueError(f"colours={colours}: a PNG palette holds 2 to 256 colours")
    before = path.stat().st_size
    with Image.open(path) as im:
        im.load()
        info = {k: v for k, v in im.info.items() if k == "dpi"}
        rgba = im.convert("RGBA")
    if rgba.getextrema()[3][0] == 255:  # opaque (matplotlib's white face): median cut keeps
        # a colour bar's gradient smooth (fast octree bands it into ~30 steps)
        q = rgba.convert("RGB").quantize(
            colours, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE
        )
    else:  # median cut has no alpha
        q = rgba.quantize(colours, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE)
    buf = io.BytesIO()
    q.save(buf, "PNG", optimize=True, **info)
    if buf.tell() >= before:
        return before, before
    path.write_bytes(buf.getvalue())
    return before, buf.tell()


CJK_FONT = "cjk-subset.woff"
"""The site's CJK glyphs (:func:`analysis.app.webfont.subset_cjk`), in ``_static``; the
``@font-face`` that serves it is in ``docs/site/_static/report.css``."""


def _write_cjk_font(src: Path, static: Path) -> str:
    """The CJK font subset for the site's text (every page's source under ``src``: the
    generated pages, the notebooks, the figure captions) written to ``static``; returns the
    characters it holds ('' and nothing written if the text has none)."""
    from analysis.app.webfont import cjk_characters, subset_cjk

    text = "".join(
        f.read_text(encoding="utf-8", errors="replace")
        for f in sorted(src.rglob("*"))
        if f.suffix in (".md", ".ipynb", ".json") and "downloads" not in f.relative_to(src).parts
    )
    chars = cjk_characters(text)
    if chars:
        static.mkdir(parents=True, exist_ok=True)
        (static / CJK_FONT).write_bytes(subset_cjk(chars))
    return chars


def _check_cjk_covered(site: Path, chars: str) -> None:
    """``RuntimeError`` naming the page if a page shows a CJK character the subset lacks."""
    from analysis.app.webfont import cjk_characters

    for page in sorted([*site.glob("*.html"), *site.glob("notebooks/*.html")]):
        extra = set(cjk_characters(page.read_text(encoding="utf-8"))) - set(chars)
        if extra:
            raise RuntimeError(f"{page.relative_to(site)} shows {''.join(sorted(extra))!r}, "
                               f"which {CJK_FONT} lacks")


def _git_commit() -> str | None:
    try:
        run = subprocess.run(
            ["git", "-C", str(PROJECT), "rev-parse", "--short", "HEAD"],
            capture_output=True,
            text=True,
            timeout=10,
        )
    except (OSError, subprocess.TimeoutExpired):
        return None
    return run.stdout.strip() or None if run.returncode == 0 else None


_Say = Callable[[str], None]
"""A progress printer: one line with the seconds since the build started."""


def _stored_notebooks(
    paths: list[Path], dl_nb: Path, fig_dir: Path, figures: str | Path | None, say: _Say
) -> list[tuple[Path, nbformat.NotebookNode, float]]:
    """The notebooks with their stored outputs (``execute=False``), copied to the downloads
    ``dl_nb``, and the figures a run of them saved in ``figures`` copied to ``fig_dir``."""
    executed: list[tuple[Path, nbformat.NotebookNode, float]] = []
    n = len(paths)
    saved = Path(figures) if figures is not None else figure_dir()
    for i, path in enumerate(paths, start=1):
        say(f"notebook {i}/{n}: {path.name}: stored outputs (not executed)")
        nb = nbformat.read(path, as_version=4)
        nbformat.write(nb, dl_nb / path.name)
        executed.append((path, nb, 0.0))
        # the figures this notebook saves (not stale ones of notebooks since removed)
        code = "\n".join(c.source for c in nb.cells if c.cell_type == "code")
        for stem in re.findall(r"save_figure\(\s*\w+,\s*\"([^\"]+)\"", code):
            for f in saved.glob(f"{stem}.*"):
                if f.suffix in (".svg", ".png", ".json"):
                    shutil.copyfile(f, fig_dir / f.name)
    return executed


def _execute_notebooks(
    paths: list[Path],
    dl_nb: Path,
    fig_dir: Path,
    failed: dict[str, str],
    say: _Say,
    *,
    cache=None,
    workers: int = 2,
) -> list[tuple[Path, nbformat.NotebookNode, float]]:
    """Execute every notebook (fresh kernel each, ``workers`` at a time) and copy it to the
    downloads ``dl_nb``; its figures go to ``fig_dir``. A notebook whose code and inputs are
    in ``cache`` (:class:`analysis.app.report_cache.NotebookCache`) is taken from it (its
    figures too) instead of executed; one that raises is recorded in ``failed`` (stem -> first
    line of the error) and not cached. The time of a cached notebook is 0."""
    from concurrent.futures import ThreadPoolExecutor

    n = len(paths)
    results: dict[Path, tuple[nbformat.NotebookNode, float]] = {}
    todo = []
    for i, path in enumerate(paths, start=1):
        nb = nbformat.read(path, as_version=4)
        hit = cache.get(nb, fig_dir) if cache is not None else None
        if hit is not None:
            say(f"notebook {i}/{n}: {path.name}: unchanged, taken from the cache")
            results[path] = (hit, 0.0)
        else:
            todo.append((i, path, nb))

    def run(item) -> None:
        i, path, nb = item
        say(f"notebook {i}/{n}: executing {path.name} ...")
        t = time.perf_counter()
        last = [t]

        def beat(k: int, m: int) -> None:
            now = time.perf_counter()
            if now - last[0] >= 10:
                last[0] = now
                say(f"notebook {i}/{n}: {path.name} cell {k}/{m}, {now - t:.0f} s")

        with tempfile.TemporaryDirectory(prefix="analysis-figures-") as tmp:
            env = os.environ | {"ANALYSIS_FIGURE_DIR": tmp, "MPLBACKEND": NB_BACKEND}
            try:
                execute_notebook(path, on_cell=beat, into=nb, env=env)
            except CellExecutionError as exc:
                failed[path.stem] = _first_line_of_error(exc)
            figures = sorted(Path(tmp).glob("*"))
            for f in figures:
                shutil.copyfile(f, fig_dir / f.name)
            if cache is not None and path.stem not in failed:
                cache.put(nb, str(path), figures, Path(tmp))
        dt = time.perf_counter() - t
        results[path] = (nb, dt)
        if path.stem in failed:
            say(f"notebook {i}/{n}: {path.name} FAILED after {dt:.1f} s: {failed[path.stem]}")
        else:
            say(f"notebook {i}/{n}: {path.name} done in {dt:.1f} s")

    # the biggest notebooks first, so that the two workers finish together
    todo.sort(key=lambda item: -item[1].stat().st_size)
    if todo:
        with ThreadPoolExecutor(max_workers=max(1, workers)) as pool:
            list(pool.map(run, todo))
    executed = []
    for path in paths:
        nb, dt = results[path]
        nbformat.write(nb, dl_nb / path.name)
        executed.append((path, nb, dt))
    return executed


def _intro(
    executed: list[tuple[Path, nbformat.NotebookNode, float]],
    titles: dict[str, str],
    failed: dict[str, str],
    *,
    execute: bool,
) -> str:
    """The front page's opening paragraph: the paper, the commit, how the notebooks ran."""
    n = len(executed)
    commit = _git_commit()
    total = sum(dt for _, _, dt in executed)
    return (
        "The subject: Li Feng, Zhang Xue-song, Yue Yun, Zhang Zhong-mei. *Research on "
        "self-navigation system of material grabbing robot based on the inverse kinematics "
        "analysis.* Food & Machinery, 2016 (seed 000, notebooks 01-07 and 09); and three "
        "companion papers: a 4-axis palletizer (seed 001, notebook 11), a 2P4R fruit picker "
        "in screw theory (seed 002, notebook 12) and the GR-1 5-DOF handling arm (seed 004, "
        "notebook 10). Every printed equation, table, listing and claim re-derived, "
        "recomputed or executed. "
        f"This site was built{f' from commit `{commit}`' if commit else ''}: "
        + (
            f"all {n} notebooks were executed for it ({total:.0f} s"
            + (f"; {sum(k in titles for k in failed)} failed" if failed else "")
            + ")"
            if execute
            else f"from the stored outputs of the {n} notebooks (re-executed and compared "
            "by nbval in the same test run)"
        )
        + ", and the verdicts below recomputed."
    )


def _write_sources(
    src: Path,
    fig_dir: Path,
    nb_dir: Path,
    executed: list[tuple[Path, nbformat.NotebookNode, float]],
    *,
    execute: bool,
    failed: dict[str, str],
    say: _Say,
    front: Callable[[], list] | None = None,
) -> list:
    """The site's sources under ``src``: the notebooks prepared as pages, the downloads, the
    front page with its recomputed verdicts, the register, figures and downloads pages.
    Returns the downloads (:class:`analysis.app.site_content.Download`)."""
    from analysis.app import site_content as site
    from analysis.app.frontpage import front_page_data

    captions = site.figure_captions(fig_dir)
    missing = [s for s, c in captions.items() if not c]
    say(
        f"{len(captions)} figures saved"
        + (f"; no caption for {', '.join(missing)}" if missing else "")
    )
    titles, homes = {}, {}
    for path, nb, dt in executed:
        page, placed = site.prepare_notebook(
            nb, path.name, captions, seconds=dt if execute else None, failure=failed.get(path.stem)
        )
        nbformat.write(page, nb_dir / path.name)
        titles[path.stem] = _title(nb, path.stem)
        homes.update({s: f"notebooks/{path.stem}" for s in placed})
    say("recomputing the front-page verdicts and writing the downloads ...")
    items = site.write_downloads(src)
    items += [
        site.Download(
            f"notebooks/{p.name}",
            "Executed notebooks",
            f"{p.stem}: {titles[p.stem]}",
            f"executed in {dt:.1f} s" if execute else "stored outputs, verified by nbval",
        )
        for p, _, dt in executed
    ]
    try:
        sections = (front or front_page_data)()
    except Exception as exc:  # the site still shows everything else, and says what broke
        failed["front page"] = f"front_page_data() raised {type(exc).__name__}: {exc}"
        say(failed["front page"])
        sections = []
    intro = _intro(executed, titles, failed, execute=execute)
    docs = [f"notebooks/{p.stem}" for p, _, _ in executed]
    toc = {"Notebooks": docs, "Report": ["register", "figures", "downloads"]}
    (src / "index.md").write_text(
        site.front_page_md(sections, captions, homes, titles, intro, toc, problems=failed),
        encoding="utf-8",
    )
    # the printed report (report.pdf): the front page and every figure with its caption, no
    # code and no notebook listings (the notebooks are on the site and as downloads)
    (src / "print.md").write_text(
        "---\norphan: true\n---\n\n"  # MyST front matter (a ':orphan:' line is printed as text)
        + site.front_page_md(sections, captions, homes, titles, intro, {}, problems=failed)
        + "\n\n"
        + site.figures_md(captions, homes, titles).replace("# Figures", "## Figures", 1),
        encoding="utf-8",
    )
    (src / "register.md").write_text(site.register_md(), encoding="utf-8")
    (src / "figures.md").write_text(site.figures_md(captions, homes, titles), encoding="utf-8")
    (src / "downloads.md").write_text(site.downloads_md(src, items), encoding="utf-8")
    return items


def build_report(
    out: str | Path = "build/report",
    notebooks: list[Path] | None = None,
    *,
    pdf: bool = True,
    execute: bool = True,
    figures: str | Path | None = None,
    cache: bool = True,
) -> Path:
    """Execute the notebooks and build the report site under ``out``; return its index.html.

    ``cache`` (default on): unchanged notebooks are not executed again, the front page's data
    is not recomputed (:mod:`analysis.app.report_cache`: keyed by each notebook's code and the
    digest of the package, ``data/`` and the lock), and when nothing at all changed since the
    site in ``out`` was built (the same notebooks, inputs, site configuration and options) the
    build stops at once, saying so.

    ``pdf=False`` skips the printed ``report.pdf`` (it needs Debian's Chromium anyway).
    ``execute=False`` builds from the notebooks' stored outputs and the figures a run of
    them saved in ``figures`` (default ``build/figures``): what ``make test`` does after
    nbval has re-executed every notebook, compared it with its stored outputs and saved its
    figures, so the browser tests need not execute everything a second time.
    A notebook that raises does not stop the build: its page shows the outputs up to the
    failing cell and the error, the front page lists it, and :class:`NotebookFailed` is
    raised once the site is written (so ``make report`` fails, with a site to look at).
    """
    from analysis.app import site_content as site

    t0 = time.perf_counter()

    def say(msg: str) -> None:
        print(f"[{time.perf_counter() - t0:6.1f} s] {msg}", flush=True)

    out = Path(out).resolve()
    work = out.with_name(out.name + "-src")
    _refuse_foreign(out)  # before anything is read or built
    _refuse_foreign(work)
    paths = [Path(p).resolve() for p in notebooks] if notebooks else notebook_paths()
    nb_cache, front, stamp = None, None, None
    if cache:
        from analysis.app import report_cache as rc

        digest, whole = rc.inputs_digest(), rc.site_digest()
        nb_cache = rc.NotebookCache(digest=digest) if execute else None

        def front():
            return rc.cached_front_page(_front_page_data, whole)

        if execute:
            stamp = _build_stamp(whole, paths, pdf)
            index = out / "index.html"
            if index.exists() and (out / _MARKER).read_text(errors="replace").endswith(stamp):
                say(f"nothing changed since {index} was built: the site is current")
                return index
    _fresh_dir(out)
    _fresh_dir(work)
    src = work / "site"
    fig_dir, nb_dir, dl_nb = src / "figures", src / "notebooks", src / "downloads" / "notebooks"
    for d in (fig_dir, nb_dir, dl_nb):
        d.mkdir(parents=True)

    # 1. execute every notebook (fresh kernel each); figures go to the staged figures/
    failed: dict[str, str] = {}  # notebook stem (or "front page") -> what went wrong
    if execute:
        # kernels draw with the inline backend, as under nbval (make test), whatever the caller
        # uses; unchanged notebooks (code and inputs) come from the cache
        executed = _execute_notebooks(paths, dl_nb, fig_dir, failed, say, cache=nb_cache)
    else:
        executed = _stored_notebooks(paths, dl_nb, fig_dir, figures, say)

    # the site's raster previews (build/figures keeps matplotlib's full-colour PNGs)
    sizes = [preview_png(f) for f in sorted(fig_dir.glob("*.png"))]
    say(f"{len(sizes)} PNG previews: {sum(a for a, _ in sizes) / 1e6:.2f} MB -> "
        f"{sum(b for _, b in sizes) / 1e6:.2f} MB (palette of 256 colours)")

    # 2. figures, notebooks prepared for the site, downloads, generated pages
    items = _write_sources(
        src, fig_dir, nb_dir, executed, execute=execute, failed=failed, say=say, front=front
    )

    # 3. the printed form: one page (singlehtml) printed by Chromium, then offered as download
    doctrees = work / "doctrees"
    warnings = 0
    if pdf:
        say("sphinx: single-page version for printing ...")
        warnings += _sphinx(
            src, work / "print", work / "doctrees-print", "singlehtml",
            {"root_doc": "print",  # the site's pages are not in the printed form's contents
             "suppress_warnings": ["mystnb.unknown_mime_type", "toc.not_included"],
             # the front page is print.md's first part: its section labels once, not twice
             "exclude_patterns": [*_SITE_EXCLUDE, "index.md"]},
        )
        _write_cjk_font(src, work / "print" / "_static")
        say("printing report.pdf with headless Chromium ...")
        if print_pdf(work / "print", src / "downloads" / "report.pdf", page="print"):
            items.append(
                site.Download(
                    "report.pdf",
                    "Printable report",
                    "The report as one PDF (A4): the verdicts, the findings and every figure "
                    "with its caption, without code; printed by headless Chromium",
                    "make report",
                    at_root=True,
                )
            )
            (src / "downloads.md").write_text(site.downloads_md(src, items), encoding="utf-8")

    # 4. the site
    say("sphinx: building the site ...")
    warnings += _sphinx(  # the printed form is not a page of the site
        src, out, doctrees, "html",
        {"exclude_patterns": [*_SITE_EXCLUDE, "print.md"]},
    )
    pdf_file = src / "downloads" / "report.pdf"
    if pdf and pdf_file.exists():  # one stable path, linked from downloads.html
        shutil.copyfile(pdf_file, out / "report.pdf")
        say(f"report.pdf: {out / 'report.pdf'} ({_pdf_pages(pdf_file)} pages)")
    removed = _prune_static(out / "_static", out)
    cjk = _write_cjk_font(src, out / "_static")
    _check_cjk_covered(out, cjk)
    say(f"{CJK_FONT}: {len(cjk)} CJK characters, "
        f"{(out / '_static' / CJK_FONT).stat().st_size / 1e3:.0f} kB" if cjk else "no CJK text")
    say("left out of _static (no page loads them): "
        + ", ".join(f"{k} {v / 1e6:.2f} MB" for k, v in removed.items()))
    (out / _MARKER).write_text(
        "written by analysis.app.report; deleted on the next build\n"
        + (f"inputs {stamp}" if stamp and not failed else "")
    )
    index = out / "index.html"
    say(f"done: {index} ({warnings} Sphinx warnings)")
    if failed:
        raise NotebookFailed(
            f"the site was built ({index}), but "
            + "; ".join(f"{k}: {v}" for k, v in failed.items())
        )
    return index


_SITE_EXCLUDE = ("downloads/**", "figures/**", "**.ipynb_checkpoints")
"""What Sphinx never reads as a page (``docs/site/conf.py``'s ``exclude_patterns``)."""


def _pdf_pages(path: Path) -> int:
    """How many pages the PDF at ``path`` has (its page objects, as Chromium writes them)."""
    return len(re.findall(rb"/Type\s*/Page[^s]", path.read_bytes()))


def _front_page_data() -> list:
    from analysis.app.frontpage import front_page_data

    return front_page_data()


def _build_stamp(digest: str, paths: list[Path], pdf: bool) -> str:
    """What a site depends on: the inputs' digest, the notebooks, the site's configuration
    (``docs/site``) and the options; equal stamps build the same site."""
    import hashlib

    h = hashlib.sha256(f"{digest}\0pdf={pdf}\0".encode())
    for f in [*paths, *sorted(p for p in CONF_DIR.rglob("*") if p.is_file())]:
        h.update(str(f.name).encode() + b"\0" + f.read_bytes())
    return h.hexdigest()


def _first_line_of_error(exc: Exception) -> str:
    """'ImportError: cannot import name ...' from nbclient's CellExecutionError."""
    ename, evalue = getattr(exc, "ename", ""), getattr(exc, "evalue", "")
    if ename:
        return f"{ename}: {evalue}".strip()
    return str(exc).strip().splitlines()[-1] if str(exc).strip() else type(exc).__name__
