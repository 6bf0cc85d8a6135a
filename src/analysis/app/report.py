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
import errno
import io
import re
import shutil
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import nbformat

from analysis.app.report_files import (
    CHROMIUM,
    CHROMIUM_FLAGS,
    CJK_FONT,
    check_cjk_covered,
    pdf_pages,
    preview_png,
    print_pdf,
    prune_static,
    serve,
    write_cjk_font,
)
from analysis.app.report_notebooks import (
    NB_BACKEND,
    NotebookFailed,
    Say,
    execute_all,
    execute_notebook,
    notebook_paths,
    notebook_title,
    stored_notebooks,
)

__all__ = [  # the site's builder; the names of its two helpers' modules, importable from here
    "CHROMIUM",
    "CHROMIUM_FLAGS",
    "NB_BACKEND",
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
_MARKER = ".analysis-report"


def _refuse_foreign(path: Path) -> None:
    """FileExistsError if ``path`` is a non-empty folder this module did not write: only its
    marker file says so (an ``index.html`` may be anyone's web site)."""
    if path.exists():
        ours = (path / _MARKER).is_file()
        if any(path.iterdir()) and not ours:
            raise FileExistsError(errno.EEXIST, "is not empty and not a report build: not "
                                  "deleting it", str(path))  # the command: "<path>: is not ..."


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
    say: Say,
    front: Callable[[], list] | None = None,
) -> list:
    """The site's sources under ``src``: the notebooks prepared as pages, the downloads, the
    front page with its recomputed verdicts, the register, figures and downloads pages.
    Returns the downloads (:class:`analysis.app.site_content.Download`)."""
    from analysis.app import site_content as site
    from analysis.app.frontpage import front_page_data

    # numbered in the order the notebooks show them (site_notebooks.figure_numbers)
    captions = site.shown_order(site.figure_captions(fig_dir), (nb for _, nb, _ in executed))
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
        titles[path.stem] = notebook_title(nb, path.stem)
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
        executed = execute_all(paths, dl_nb, fig_dir, failed, say, cache=nb_cache)
    else:
        executed = stored_notebooks(paths, dl_nb, fig_dir, figures, say)

    # the site's raster previews (build/figures keeps matplotlib's full-colour PNGs)
    sizes = [preview_png(f) for f in sorted(fig_dir.glob("*.png"))]
    say(
        f"{len(sizes)} PNG previews: {sum(a for a, _ in sizes) / 1e6:.2f} MB -> "
        f"{sum(b for _, b in sizes) / 1e6:.2f} MB (palette of 256 colours)"
    )

    # 2. figures, notebooks prepared for the site, downloads, generated pages
    items = _write_sources(
        src, fig_dir, nb_dir, executed, execute=execute, failed=failed, say=say, front=front
    )

    # 3. the printed form; 4. the site
    warnings = _print_pdf(src, work, items, say) if pdf else 0
    warnings += _site(src, out, work / "doctrees", pdf=pdf, say=say)
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


def _print_pdf(src: Path, work: Path, items: list, say: Say) -> int:
    """The printed form: one page (singlehtml) printed by Chromium to
    ``src/downloads/report.pdf``, then offered as a download (``items`` and the downloads
    page updated). Returns Sphinx's warnings."""
    from analysis.app import site_content as site

    say("sphinx: single-page version for printing ...")
    warnings = _sphinx(
        src, work / "print", work / "doctrees-print", "singlehtml",
        {"root_doc": "print",  # the site's pages are not in the printed form's contents
         "suppress_warnings": ["mystnb.unknown_mime_type", "toc.not_included"],
         # the front page is print.md's first part: its section labels once, not twice
         "exclude_patterns": [*_SITE_EXCLUDE, "index.md"]},
    )  # fmt: skip
    write_cjk_font(src, work / "print" / "_static")
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
    return warnings


def _site(src: Path, out: Path, doctrees: Path, *, pdf: bool, say: Say) -> int:
    """The site from ``src`` into ``out``: Sphinx's HTML, the PDF at its stable path, the
    ``_static`` pruned, the CJK font subset. Returns Sphinx's warnings."""
    say("sphinx: building the site ...")
    warnings = _sphinx(  # the printed form is not a page of the site
        src, out, doctrees, "html",
        {"exclude_patterns": [*_SITE_EXCLUDE, "print.md"]},
    )  # fmt: skip
    pdf_file = src / "downloads" / "report.pdf"
    if pdf and pdf_file.exists():  # one stable path, linked from downloads.html
        shutil.copyfile(pdf_file, out / "report.pdf")
        say(f"report.pdf: {out / 'report.pdf'} ({pdf_pages(pdf_file)} pages)")
    removed = prune_static(out / "_static", out)
    cjk = write_cjk_font(src, out / "_static")
    check_cjk_covered(out, cjk)
    say(
        f"{CJK_FONT}: {len(cjk)} CJK characters, "
        f"{(out / '_static' / CJK_FONT).stat().st_size / 1e3:.0f} kB"
        if cjk
        else "no CJK text"
    )
    say(
        "left out of _static (no page loads them): "
        + ", ".join(f"{k} {v / 1e6:.2f} MB" for k, v in removed.items())
    )
    return warnings


_SITE_EXCLUDE = ("downloads/**", "figures/**", "**.ipynb_checkpoints")
"""What Sphinx never reads as a page (``docs/site/conf.py``'s ``exclude_patterns``)."""


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
