"""The built site's files and its printed form: the site served on 127.0.0.1 (:func:`serve`),
printed to PDF by Debian's headless Chromium (:func:`print_pdf`), its ``_static`` pruned of
what no page loads (:func:`prune_static`), its raster previews (:func:`preview_png`) and the
CJK font subset of its text (:func:`write_cjk_font`, :func:`check_cjk_covered`).
:mod:`analysis.app.report` calls them once the pages are written."""

from __future__ import annotations

import contextlib
import functools
import http.server
import io
import re
import subprocess
import tempfile
import threading
from collections.abc import Iterator
from pathlib import Path

__all__ = [
    "CHROMIUM",
    "CHROMIUM_FLAGS",
    "CJK_FONT",
    "check_cjk_covered",
    "pdf_pages",
    "preview_png",
    "print_pdf",
    "prune_static",
    "serve",
    "write_cjk_font",
]


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


def prune_static(static: Path, site: Path) -> dict[str, int]:
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
                raise RuntimeError(
                    f"{page.relative_to(site)} loads _static/{n}, which the "
                    "site no longer ships (analysis.app.report_files.prune_static)"
                )
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


def write_cjk_font(src: Path, static: Path) -> str:
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


def check_cjk_covered(site: Path, chars: str) -> None:
    """``RuntimeError`` naming the page if a page shows a CJK character the subset lacks."""
    from analysis.app.webfont import cjk_characters

    for page in sorted([*site.glob("*.html"), *site.glob("notebooks/*.html")]):
        extra = set(cjk_characters(page.read_text(encoding="utf-8"))) - set(chars)
        if extra:
            raise RuntimeError(
                f"{page.relative_to(site)} shows {''.join(sorted(extra))!r}, which {CJK_FONT} lacks"
            )


def pdf_pages(path: Path) -> int:
    """How many pages the PDF at ``path`` has (its page objects, as Chromium writes them)."""
    return len(re.findall(rb"/Type\s*/Page[^s]", path.read_bytes()))
